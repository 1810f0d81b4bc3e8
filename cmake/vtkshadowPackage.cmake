# CMake package config so downstream projects can find_package(vtkshadow).
include(CMakePackageConfigHelpers)
configure_package_config_file(
  "${PROJECT_SOURCE_DIR}/cmake/vtkshadowConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}/cmake/vtkshadow/vtkshadowConfig.cmake"
  INSTALL_DESTINATION "${CMAKE_INSTALL_LIBDIR}/cmake/vtkshadow")
write_basic_package_version_file(
  "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}/cmake/vtkshadow/vtkshadowConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)
install(FILES
  "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}/cmake/vtkshadow/vtkshadowConfig.cmake"
  "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}/cmake/vtkshadow/vtkshadowConfigVersion.cmake"
  DESTINATION "${CMAKE_INSTALL_LIBDIR}/cmake/vtkshadow")
