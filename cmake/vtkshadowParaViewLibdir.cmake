# vtkshadow_paraview_libdir(<out> <ParaView_DIR>): ParaView's own library
# folder relative to its install prefix (lib/x86_64-linux-gnu for Debian's
# ParaView). The plugin is installed under it, in
# <libdir>/paraview-5.11/plugins/VTKShadow like ParaView's own plugins, and
# not under vtkshadow's CMAKE_INSTALL_LIBDIR (GNUInstallDirs gives plain
# `lib` unless the prefix is /usr), so the .deb puts it where Debian's
# ParaView keeps plugins whatever prefix the build was configured with.
# Used by the top level (the build-tree path of the plugin) and by
# paraview/CMakeLists.txt (where it builds and installs it).
function(vtkshadow_paraview_libdir out paraview_dir)
  # paraview-prefix.cmake (ParaView's) computes its prefix from its own path.
  include("${paraview_dir}/paraview-prefix.cmake")
  get_filename_component(libdir "${paraview_dir}/../.." ABSOLUTE)
  file(RELATIVE_PATH libdir "${_vtk_module_import_prefix}" "${libdir}")
  set(${out} "${libdir}" PARENT_SCOPE)
endfunction()
