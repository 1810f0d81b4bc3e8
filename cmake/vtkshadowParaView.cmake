# The ParaView 5.11 plugin (paraview/) as its own CMake project: ParaView's
# VTK 9.2 exports the same target names (VTK::CommonCore, ...) as the system
# VTK 9.1 this project builds against, so the two cannot be found in one
# project. ExternalProject configures and builds it into build/paraview on
# every build; the entry points below start ParaView with it loaded.
# ParaView comes from scripts/install-paraview.sh (a private prefix, because
# Debian's python3-paraview conflicts with python3-vtk9).
set(VTKSHADOW_PARAVIEW_PREFIX "/opt/vtkshadow/paraview-5.11" CACHE PATH
  "Prefix holding ParaView 5.11 (scripts/install-paraview.sh)")
set(VTKSHADOW_PARAVIEW_DIR
  "${VTKSHADOW_PARAVIEW_PREFIX}/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11" CACHE PATH
  "ParaView_DIR for the plugin")
if(NOT EXISTS "${VTKSHADOW_PARAVIEW_DIR}/paraview-config.cmake")
  message(FATAL_ERROR "VTKSHADOW_PARAVIEW is on but ${VTKSHADOW_PARAVIEW_DIR}/paraview-config.cmake "
    "does not exist: run scripts/install-paraview.sh (or set VTKSHADOW_PARAVIEW_DIR), "
    "or configure with -DVTKSHADOW_PARAVIEW=OFF")
endif()
set(VTKSHADOW_PVPYTHON "${VTKSHADOW_PARAVIEW_PREFIX}/usr/bin/pvpython")
set(VTKSHADOW_PVBATCH "${VTKSHADOW_PARAVIEW_PREFIX}/usr/bin/pvbatch")
set(VTKSHADOW_PARAVIEW_GUI "${VTKSHADOW_PARAVIEW_PREFIX}/usr/bin/paraview")
foreach(program VTKSHADOW_PVPYTHON VTKSHADOW_PVBATCH VTKSHADOW_PARAVIEW_GUI)
  if(NOT EXISTS "${${program}}")
    message(FATAL_ERROR "${${program}} does not exist: run scripts/install-paraview.sh")
  endif()
endforeach()

include(ExternalProject)
set(VTKSHADOW_PARAVIEW_BINARY_DIR "${CMAKE_BINARY_DIR}/paraview")
set(vtkshadow_paraview_args
  -DParaView_DIR=${VTKSHADOW_PARAVIEW_DIR}
  -DCMAKE_BUILD_TYPE=${CMAKE_BUILD_TYPE}
  -DCMAKE_C_COMPILER=${CMAKE_C_COMPILER}
  -DCMAKE_CXX_COMPILER=${CMAKE_CXX_COMPILER})
foreach(var CMAKE_C_COMPILER_LAUNCHER CMAKE_CXX_COMPILER_LAUNCHER)
  if(${var})
    list(APPEND vtkshadow_paraview_args -D${var}=${${var}})
  endif()
endforeach()
ExternalProject_Add(vtkshadow_paraview
  SOURCE_DIR "${PROJECT_SOURCE_DIR}/paraview"
  BINARY_DIR "${VTKSHADOW_PARAVIEW_BINARY_DIR}"
  CMAKE_ARGS ${vtkshadow_paraview_args}
  INSTALL_COMMAND ""
  BUILD_ALWAYS ON
  USES_TERMINAL_BUILD ON)

# `cmake --install build` (and CPack's component `paraview`, the
# vtkshadow-paraview package) installs the plugin project's `paraview`
# component: the plugin, vtkshadow.plugins.xml and bin/paraview.conf
# (paraview/CMakeLists.txt). Only that component: the rest of that project
# is the static core and module compiled into the plugin.
install(CODE "
set(vtkshadow_component \"\${CMAKE_INSTALL_COMPONENT}\")
set(CMAKE_INSTALL_COMPONENT paraview)
include(\"${VTKSHADOW_PARAVIEW_BINARY_DIR}/cmake_install.cmake\")
set(CMAKE_INSTALL_COMPONENT \"\${vtkshadow_component}\")"
  COMPONENT paraview)

# PV_PLUGIN_PATH: ParaView loads every plugin in these folders at start.
include("${PROJECT_SOURCE_DIR}/cmake/vtkshadowParaViewLibdir.cmake")
vtkshadow_paraview_libdir(VTKSHADOW_PARAVIEW_LIBDIR "${VTKSHADOW_PARAVIEW_DIR}")
set(VTKSHADOW_PV_PLUGIN_DIR
  "${VTKSHADOW_PARAVIEW_BINARY_DIR}/${VTKSHADOW_PARAVIEW_LIBDIR}/paraview-5.11/plugins/VTKShadow")
foreach(tool pvpython pvbatch paraview)
  if(tool STREQUAL "pvpython")
    set(VTKSHADOW_PV_PROGRAM "${VTKSHADOW_PVPYTHON}")
  elseif(tool STREQUAL "pvbatch")
    set(VTKSHADOW_PV_PROGRAM "${VTKSHADOW_PVBATCH}")
  else()
    set(VTKSHADOW_PV_PROGRAM "${VTKSHADOW_PARAVIEW_GUI}")
  endif()
  configure_file("${PROJECT_SOURCE_DIR}/paraview/vtkshadow-pv.in"
    "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_BINDIR}/vtkshadow-${tool}" @ONLY
    FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE
    WORLD_READ WORLD_EXECUTE)
endforeach()
