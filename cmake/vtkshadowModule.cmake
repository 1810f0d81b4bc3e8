# Build vtkshadow/vtk as an external VTK module with VTK's module system and
# wrap it with VTK's own Python wrapping (as VTK's Examples/Modules/Wrapping).
set(VTKSHADOW_VTK_COMPONENTS
  CommonCore CommonDataModel CommonMath CommonSystem CommonTransforms
  FiltersCore IOGeometry IOImage IOPLY IOXML ParallelCore
  RenderingCore RenderingOpenGL2 RenderingUI RenderingVolume
  InteractionStyle RenderingFreeType)
find_package(VTK 9.1 REQUIRED COMPONENTS ${VTKSHADOW_VTK_COMPONENTS} WrappingPythonCore Python)
string(REPLACE ";" " " VTKSHADOW_VTK_COMPONENTS "${VTKSHADOW_VTK_COMPONENTS}")

set(BUILD_SHARED_LIBS ON)
vtk_module_scan(
  MODULE_FILES     "${PROJECT_SOURCE_DIR}/vtkshadow/vtk/vtk.module"
  REQUEST_MODULES  vtkshadow::vtkshadow
  PROVIDES_MODULES vtkshadow_modules)

vtk_module_build(
  MODULES             ${vtkshadow_modules}
  INSTALL_EXPORT      vtkshadowTargets
  ARCHIVE_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  RUNTIME_DESTINATION "${CMAKE_INSTALL_BINDIR}"
  HEADERS_DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/vtkshadow"
  CMAKE_DESTINATION   "${CMAKE_INSTALL_LIBDIR}/cmake/vtkshadow"
  LICENSE_DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/licenses/vtkshadow"
  VERSION             "${PROJECT_VERSION}")

vtk_module_python_default_destination(VTKSHADOW_PYTHON_DESTINATION)
vtk_module_wrap_python(
  MODULES             ${vtkshadow_modules}
  INSTALL_EXPORT      vtkshadowPython
  PYTHON_PACKAGE      "vtkshadow"
  MODULE_DESTINATION  "${VTKSHADOW_PYTHON_DESTINATION}"
  CMAKE_DESTINATION   "${CMAKE_INSTALL_LIBDIR}/cmake/vtkshadow"
  LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  BUILD_STATIC        OFF
  INSTALL_HEADERS     OFF)

# The package's __init__.py imports the VTK modules our classes derive from
# first, then the wrapped classes.
set(VTKSHADOW_PYTHON_PACKAGE_DIR "${CMAKE_BINARY_DIR}/${VTKSHADOW_PYTHON_DESTINATION}/vtkshadow")
configure_file("${PROJECT_SOURCE_DIR}/vtkshadow/python/__init__.py.in"
  "${VTKSHADOW_PYTHON_PACKAGE_DIR}/__init__.py" @ONLY)
configure_file("${PROJECT_SOURCE_DIR}/vtkshadow/python/enable.py"
  "${VTKSHADOW_PYTHON_PACKAGE_DIR}/enable.py" COPYONLY)
install(FILES "${VTKSHADOW_PYTHON_PACKAGE_DIR}/__init__.py"
  "${VTKSHADOW_PYTHON_PACKAGE_DIR}/enable.py"
  DESTINATION "${VTKSHADOW_PYTHON_DESTINATION}/vtkshadow")

# A /usr/local (or any non-/usr) install: vtkshadow.pth in the site folder
# Debian's python3 searches there. VTK's find_package found Python3.
set(VTKSHADOW_PYTHON_MAJOR_MINOR "${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}")
include("${PROJECT_SOURCE_DIR}/cmake/vtkshadowPythonSite.cmake")

# build/bin/vtkshadow-python: Debian's /usr/bin/python3 with the build tree on
# its paths, like VTK's vtkpython or ParaView's pvpython.
set(VTKSHADOW_PYTHON_EXECUTABLE "/usr/bin/python3" CACHE FILEPATH
  "The Python that can import Debian's VTK")
set(VTKSHADOW_PYTHONPATH "${CMAKE_BINARY_DIR}/${VTKSHADOW_PYTHON_DESTINATION}")
set(VTKSHADOW_LIBRARY_PATH "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
configure_file("${PROJECT_SOURCE_DIR}/vtkshadow/python/vtkshadow-python.in"
  "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_BINDIR}/vtkshadow-python" @ONLY
  FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE
  WORLD_READ WORLD_EXECUTE)
