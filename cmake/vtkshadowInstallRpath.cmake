# vtkshadow_install_rpath(<dir> <target>...): installed, <target>s (in
# <dir>, relative to the prefix) find libvtkshadow.so in
# CMAKE_INSTALL_LIBDIR through an $ORIGIN-relative RUNPATH. Without it the
# tools of a /usr/local install would need ldconfig or LD_LIBRARY_PATH (the
# loader's default path is /lib and /usr/lib only). VTK's
# vtk_module_wrap_python gives the Python module such a RUNPATH already.
# Relative, so it holds for every prefix: the .deb (/usr), /usr/local, the
# install.downstream test's prefix. In the build tree CMake's build RPATH
# applies instead.
function(vtkshadow_install_rpath dir)
  file(RELATIVE_PATH rel "/prefix/${dir}" "/prefix/${CMAKE_INSTALL_LIBDIR}")
  set_target_properties(${ARGN} PROPERTIES INSTALL_RPATH "$ORIGIN/${rel}")
endfunction()
