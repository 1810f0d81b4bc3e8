# CPack: `cd build && cpack -G DEB` makes Debian packages of the same install
# rules `cmake --install` runs, installed under /usr:
#   vtkshadow          the library, headers, CMake package, Python package
#                      and tools: every component but the two below;
#   vtkshadow-paraview the ParaView 5.11 plugin (component `paraview`,
#                      cmake/vtkshadowParaView.cmake), a package of its own
#                      so that vtkshadow does not pull in ParaView.
# The component `python-site` (cmake/vtkshadowPythonSite.cmake) is left
# out: under /usr the Python package is on python3's path already.
# Included last in CMakeLists.txt: it packages the components known then.
set(CPACK_PACKAGE_NAME "vtkshadow")
set(CPACK_PACKAGE_VENDOR "vtkshadow")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Correct, fast shadows for VTK's OpenGL renderer")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_GENERATOR "DEB")
set(CPACK_DEB_COMPONENT_INSTALL ON)
# vtkshadow_0.1.0_amd64.deb, vtkshadow-paraview_0.1.0_amd64.deb
set(CPACK_DEBIAN_FILE_NAME "DEB-DEFAULT")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "vtkshadow maintainers <maintainers@users.noreply.h-seed-4105c87b.example>")
set(CPACK_DEBIAN_PACKAGE_SECTION "science")

get_cmake_property(vtkshadow_components COMPONENTS)
list(REMOVE_ITEM vtkshadow_components python-site)
set(CPACK_COMPONENTS_ALL ${vtkshadow_components})
# One package a group: every component but `paraview` in group vtkshadow.
set(CPACK_COMPONENTS_GROUPING ONE_PER_GROUP)
include(CPackComponent)
cpack_add_component_group(vtkshadow)
cpack_add_component_group(paraview)
foreach(component IN LISTS vtkshadow_components)
  if(component STREQUAL "paraview")
    cpack_add_component(${component} GROUP paraview)
  else()
    cpack_add_component(${component} GROUP vtkshadow)
  endif()
endforeach()

# Depends: the Debian 12 packages of the shared libraries the installed
# files link (readelf -d NEEDED, then dpkg -S), named explicitly rather than
# by dpkg-shlibdeps: ParaView's libraries carry no shlibs information.
# python3-vtk9: `import vtkshadow` imports vtkmodules first.
set(CPACK_DEBIAN_VTKSHADOW_PACKAGE_NAME "vtkshadow")
set(CPACK_DEBIAN_VTKSHADOW_PACKAGE_DEPENDS
  "libvtk9.1, python3-vtk9, python3 (>= 3.11), python3 (<< 3.12), libembree3-3, libcjson1, libpng16-16, libglew2.2, libx11-6, libstdc++6, libgcc-s1, libc6")
# find_package(vtkshadow) from a C or C++ project needs VTK's and cJSON's
# CMake files: recommended, not required by Python users.
set(CPACK_DEBIAN_VTKSHADOW_PACKAGE_RECOMMENDS "libvtk9-dev, libcjson-dev")
set(CPACK_DEBIAN_VTKSHADOW_DESCRIPTION
  "Correct, fast shadows for VTK's OpenGL renderer
 A VTK 9.1 module (C11 core, C++ VTK classes, a C API and Python through
 VTK's wrapping): import vtkshadow; vtkshadow.enable_shadows(renderer).")
# The plugin holds its own static copy of vtkshadow built against
# ParaView's VTK 9.2: it needs ParaView 5.11, not the vtkshadow package.
set(CPACK_DEBIAN_PARAVIEW_PACKAGE_NAME "vtkshadow-paraview")
set(CPACK_DEBIAN_PARAVIEW_PACKAGE_DEPENDS
  "paraview (>= 5.11~), paraview (<< 5.12~), libembree3-3, libcjson1, libglew2.2, libx11-6, libstdc++6, libgcc-s1, libc6")
set(CPACK_DEBIAN_PARAVIEW_DESCRIPTION
  "vtkshadow's ParaView 5.11 plugin: Render View (Shadows)
 The VTKShadow plugin, loadable by name (LoadDistributedPlugin('VTKShadow')
 in pvpython/pvbatch, Tools > Manage Plugins in the GUI).")
include(CPack)
