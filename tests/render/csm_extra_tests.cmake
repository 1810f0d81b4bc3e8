# vtkCascadedShadowMapPass in real-application set-ups and every setting
# (tests/render/test_csm_robust.py explains each case), and its temporal
# stability along a camera path (tests/render/test_csm_flicker.py).
# Needs VTKSHADOW_GL, VTKSHADOW_PY, VTKSHADOW_BIN, VTKSHADOW_TEST_OUT from
# tests/vtk_tests.cmake, which includes this file (before the loop that gives
# every test the xvfb fixture).
set(_csm_robust_cases
  viewports
  translucent
  lighting-off
  pbr
  composite
  glyph
  resize
  big-map
  caching
  filters
  splits
  stable
  cascade-count
  debug-cascades
  max-texel)
foreach(_case IN LISTS _csm_robust_cases)
  add_test(NAME render.csm_robust.${_case}
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY}
            ${CMAKE_CURRENT_SOURCE_DIR}/render/test_csm_robust.py
            --case ${_case} --bin ${VTKSHADOW_BIN} --out ${VTKSHADOW_TEST_OUT}/csm_robust)
  set_tests_properties(render.csm_robust.${_case} PROPERTIES LABELS "render" TIMEOUT 300)
endforeach()

# flicker_pct along a 16-frame camera path that makes unstable maps crawl
# (sub-texel dolly, roll), against the exact answer per frame: Stable csm
# below Stable off by a factor, its flicker and wrong_pct bounded, and the
# same path 1e6 from the origin (tests/render/test_csm_flicker.py).
add_test(NAME render.csm.flicker
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_csm_flicker.py
          --out ${VTKSHADOW_TEST_OUT}/csm_flicker --only stable)
add_test(NAME render.csm.flicker-offset-1e6
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_csm_flicker.py
          --out ${VTKSHADOW_TEST_OUT}/csm_flicker_offset --only offset)
set_tests_properties(render.csm.flicker render.csm.flicker-offset-1e6
  PROPERTIES LABELS "render" TIMEOUT 300)
