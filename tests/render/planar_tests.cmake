# Projected planar shadows (--technique planar) against the exact answer by
# ray casting: shadows on "receiver" planes only, v = 1 on every other surface
# (tests/render/test_planar.py explains the reference and every case).
# Needs VTKSHADOW_GL, VTKSHADOW_PY, VTKSHADOW_BIN, VTKSHADOW_TEST_OUT from
# tests/vtk_tests.cmake, which includes this file.
set(_planar_cases
  sphere-floor-directional-4x3
  sphere-floor-point-4x3
  sphere-floor-spot-4x3
  sphere-floor-directional-16x9
  box-tilted-plane-directional
  box-tilted-plane-point
  box-tilted-plane-spot
  grazing-85
  grazing-89.9
  light-below-camera-below
  caster-above-point-light
  near-far-1e5
  offset-1e6
  scale-1e-6)
foreach(_case IN LISTS _planar_cases)
  add_test(NAME render.planar.${_case}
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_planar.py
            --bin ${VTKSHADOW_BIN} --out ${VTKSHADOW_TEST_OUT}/planar --case ${_case}
            --technique planar --max-wrong-pct 0.05 --min-mask-agreement 99.9)
  set_tests_properties(render.planar.${_case} PROPERTIES LABELS "render" TIMEOUT 120)
endforeach()

# Two lights: each light's visibility against the exact answer, and in colour
# (float renders) each shadow removes only its own light's contribution.
add_test(NAME render.planar.two-lights
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY}
          ${CMAKE_CURRENT_SOURCE_DIR}/render/test_planar_two_lights.py
          --bin ${VTKSHADOW_BIN} --out ${VTKSHADOW_TEST_OUT}/planar --technique planar)
set_tests_properties(render.planar.two-lights PROPERTIES LABELS "render" TIMEOUT 120)

# 36 (receiver, light) pairs: more than one 32-bit mask channel; light 2's
# bits are in the second channel.
foreach(_light 0 2)
  add_test(NAME render.planar.many-receivers-light${_light}
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_planar.py
            --bin ${VTKSHADOW_BIN} --out ${VTKSHADOW_TEST_OUT}/planar --case many-receivers
            --light ${_light} --technique planar --max-wrong-pct 0.05 --min-mask-agreement 99.9)
  set_tests_properties(render.planar.many-receivers-light${_light} PROPERTIES LABELS "render" TIMEOUT 120)
endforeach()

# The C API with technique "planar" (tests/capi/test_capi_planar.c).
add_executable(test_capi_planar capi/test_capi_planar.c)
target_link_libraries(test_capi_planar PRIVATE vtkshadow::vtkshadow)
vtk_module_autoinit(TARGETS test_capi_planar MODULES VTK::RenderingOpenGL2)
add_test(NAME capi.c.planar
  COMMAND ${VTKSHADOW_GL} $<TARGET_FILE:test_capi_planar>
          ${PROJECT_SOURCE_DIR}/scenes/basic/sphere-plane.json ${VTKSHADOW_TEST_OUT}/capi-planar)
