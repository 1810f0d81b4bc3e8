# vtkCascadedShadowMapPass's temporal stability along a camera path
# (tests/render/test_csm_flicker.py). Its real-application set-ups and
# settings are cases of the robustness suite (robust_tests.cmake).
# Needs VTKSHADOW_GL, VTKSHADOW_PY, VTKSHADOW_BIN, VTKSHADOW_TEST_OUT from
# tests/vtk_tests.cmake, which includes this file (before the loop that gives
# every test the xvfb fixture).
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
