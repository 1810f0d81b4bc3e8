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

# Both places the csm lookups can run (resolve=0 forward in the mappers,
# resolve=1 the screen-space resolve after a depth pre-pass), forced, against
# the exact answer with the bounds of the default rows in csm_tests.cmake
# (the default, resolve=2, measures with a screen frame first).
foreach(resolve_row "forward 0" "screen 1")
  separate_arguments(rr UNIX_COMMAND "${resolve_row}")
  list(GET rr 0 resolve_name)
  list(GET rr 1 resolve_value)
  foreach(row "two-lights 0" "two-lights 1" "box-tilted-plane-spot 0" "sphere-floor-point-4x3 0"
      "offset-1e6 0")
    separate_arguments(f UNIX_COMMAND "${row}")
    list(GET f 0 case)
    list(GET f 1 light)
    set(name render.csm.${resolve_name}.${case}-light${light})
    add_test(NAME ${name}
      COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_planar.py
              --bin ${VTKSHADOW_BIN} --out ${VTKSHADOW_TEST_OUT}/csm-${resolve_name}
              --case ${case} --light ${light} --technique csm --reference all
              --max-wrong-pct 0.02 --max-wrong-of-shadow-pct 1.0 --set resolve=${resolve_value})
    set_tests_properties(${name} PROPERTIES LABELS "render" TIMEOUT 300)
  endforeach()
endforeach()
