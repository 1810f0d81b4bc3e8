# One X display per process: 30 runs of vtkshadow-render on a two-light scene
# under plain `xvfb-run -a` (its own server each, no -noreset: the server
# resets when its last client leaves), all must succeed; and without any
# display, exit status 2 with a message naming xvfb-run -a (the tool and the
# Python vtkShadowVisibility path), never an abort.
find_program(VTKSHADOW_XVFB_RUN xvfb-run)
if(NOT VTKSHADOW_XVFB_RUN)
  message(FATAL_ERROR "xvfb-run not found: apt-get install xvfb (the display test needs it)")
endif()
add_test(NAME render.display.xvfb_run_loop
  COMMAND ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/cli/test_display.py
          --bin ${VTKSHADOW_BIN} --source ${PROJECT_SOURCE_DIR}
          --out ${VTKSHADOW_TEST_OUT}/display --runs 30)
set_tests_properties(render.display.xvfb_run_loop PROPERTIES LABELS "render" TIMEOUT 1200)

# Soak: 3000 frames per technique (every one GetKnownTechniques lists) with
# the camera moving, actors added and removed and a light toggled; RSS, GL
# object counts and shadow-map memory must stay flat (bounds in the script).
add_test(NAME render.soak
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_soak.py
          --bin ${VTKSHADOW_BIN} --frames 3000 --json ${VTKSHADOW_TEST_OUT}/soak.json)
set_tests_properties(render.soak PROPERTIES LABELS "soak;render" TIMEOUT 3600)
# The RSS check can fail: `none` keeping 2 KiB more every frame must be
# reported as leaking (the same judge as render.soak; about 8 s).
add_test(NAME render.soak_detects_leak
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_soak.py
          --bin ${VTKSHADOW_BIN} --frames 1200 --techniques none --leak-kib 2 --expect-leak)
set_tests_properties(render.soak_detects_leak PROPERTIES LABELS "soak;render" TIMEOUT 300)
