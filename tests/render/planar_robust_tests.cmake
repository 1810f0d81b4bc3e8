# vtkPlanarShadowPass in real-application set-ups (composite and glyph
# mappers, actor transforms, viewports and layers, translucent and unlit
# actors, explicit planes, caching, the headlight), each case against an
# equivalent scene of plain vtkPolyDataMapper actors
# (tests/render/test_planar_robust.py explains every case).
# Needs VTKSHADOW_GL, VTKSHADOW_PY, VTKSHADOW_TEST_OUT from tests/vtk_tests.cmake,
# which includes this file.
set(_planar_robust_cases
  composite
  glyph
  transforms
  viewports
  translucent
  lighting-off
  explicit-plane
  caching
  headlight)
foreach(_case IN LISTS _planar_robust_cases)
  add_test(NAME render.planar_robust.${_case}
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY}
            ${CMAKE_CURRENT_SOURCE_DIR}/render/test_planar_robust.py
            --case ${_case} --out ${VTKSHADOW_TEST_OUT}/planar_robust)
  set_tests_properties(render.planar_robust.${_case} PROPERTIES LABELS "render" TIMEOUT 300)
endforeach()

# The C API with technique "planar" (tests/capi/test_capi_planar.c).
add_executable(test_capi_planar capi/test_capi_planar.c)
target_link_libraries(test_capi_planar PRIVATE vtkshadow::vtkshadow)
vtk_module_autoinit(TARGETS test_capi_planar MODULES VTK::RenderingOpenGL2)
add_test(NAME capi.c.planar
  COMMAND ${VTKSHADOW_GL} $<TARGET_FILE:test_capi_planar>
          ${PROJECT_SOURCE_DIR}/scenes/basic/sphere-plane.json ${VTKSHADOW_TEST_OUT}/capi-planar)
