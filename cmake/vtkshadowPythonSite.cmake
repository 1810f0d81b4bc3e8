# Debian's /usr/bin/python3 imports from /usr/lib/python3/dist-packages (where
# vtk_module_python_default_destination puts the package for every prefix)
# and, for /usr/local, from /usr/local/lib/python3.X/dist-packages only. For
# a prefix other than /usr, install vtkshadow.pth there: site.py adds the
# folder it names, ../../python3/dist-packages (relative to the .pth, so any
# prefix), to sys.path, and `import vtkshadow` works with no PYTHONPATH.
# Decided at install time (the prefix of `cmake --install --prefix` is known
# only then), and in a component of its own, `python-site`, that CPack
# leaves out: the .deb installs to /usr, where the .pth is not needed.
set(VTKSHADOW_PYTHON_SITE "lib/python${VTKSHADOW_PYTHON_MAJOR_MINOR}/dist-packages")
file(RELATIVE_PATH vtkshadow_pth_entry "/prefix/${VTKSHADOW_PYTHON_SITE}"
  "/prefix/${VTKSHADOW_PYTHON_DESTINATION}")
set(VTKSHADOW_PTH "${CMAKE_BINARY_DIR}/CMakeFiles/vtkshadow.pth")
file(WRITE "${VTKSHADOW_PTH}" "${vtkshadow_pth_entry}\n")
install(CODE "
if(NOT CMAKE_INSTALL_PREFIX MATCHES \"^/usr/?$\")
  file(INSTALL DESTINATION \"\${CMAKE_INSTALL_PREFIX}/${VTKSHADOW_PYTHON_SITE}\"
    TYPE FILE FILES \"${VTKSHADOW_PTH}\")
endif()"
  COMPONENT python-site)
