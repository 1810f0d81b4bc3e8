# Projected planar shadows (--technique planar) against the exact answer by
# ray casting: shadows on "receiver" planes only, v = 1 on every other surface
# (tests/render/test_planar.py explains the reference and every case).
# Needs VTKSHADOW_GL, VTKSHADOW_PY, VTKSHADOW_BIN, VTKSHADOW_TEST_OUT from
# tests/vtk_tests.cmake, which includes this file.
include(${CMAKE_CURRENT_LIST_DIR}/render_bounds.cmake)
# Rows: case, light, max wrong_pct, max wrong_of_shadow_pct (the margin rule
# is in render_bounds.cmake). Planar is exact: every case and light measured
# wrong_pct 0 and wrong_of_shadow_pct 0, so every bound is the floor.
vtkshadow_exact_cases(planar planar
  "sphere-floor-directional-4x3 0 0.02 1.0"
  "sphere-floor-point-4x3 0 0.02 1.0"
  "sphere-floor-spot-4x3 0 0.02 1.0"
  "sphere-floor-directional-16x9 0 0.02 1.0"
  "box-tilted-plane-directional 0 0.02 1.0"
  "box-tilted-plane-point 0 0.02 1.0"
  "box-tilted-plane-spot 0 0.02 1.0"
  "grazing-85 0 0.02 1.0"
  "grazing-89.9 0 0.02 1.0"
  "light-below-camera-below 0 0.02 1.0"
  "caster-above-point-light 0 0.02 1.0"
  "near-far-1e5 0 0.02 1.0"
  "offset-1e6 0 0.02 1.0"
  "scale-1e-6 0 0.02 1.0"
  # 36 (receiver, light) pairs: more than one 32-bit mask channel; light 2's
  # bits are in the second channel. Every light is checked.
  "many-receivers 0 0.02 1.0"
  "many-receivers 1 0.02 1.0"
  "many-receivers 2 0.02 1.0")

# Two lights: each light's visibility against the exact answer, and in colour
# (float renders) each shadow removes only its own light's contribution.
add_test(NAME render.planar.two-lights
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY}
          ${CMAKE_CURRENT_SOURCE_DIR}/render/test_planar_two_lights.py
          --bin ${VTKSHADOW_BIN} --out ${VTKSHADOW_TEST_OUT}/planar --technique planar)
set_tests_properties(render.planar.two-lights PROPERTIES LABELS "render" TIMEOUT 120)

# The C API with technique "planar" (tests/capi/test_capi_planar.c).
add_executable(test_capi_planar capi/test_capi_planar.c)
target_link_libraries(test_capi_planar PRIVATE vtkshadow::vtkshadow)
vtk_module_autoinit(TARGETS test_capi_planar MODULES VTK::RenderingOpenGL2)
add_test(NAME capi.c.planar
  COMMAND ${VTKSHADOW_GL} $<TARGET_FILE:test_capi_planar>
          ${PROJECT_SOURCE_DIR}/scenes/basic/sphere-plane.json ${VTKSHADOW_TEST_OUT}/capi-planar)
