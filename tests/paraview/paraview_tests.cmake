# The ParaView plugin (VTKSHADOW_PARAVIEW, paraview/): it loads in pvpython
# and its view renders a library scene with every technique, shadows where
# they belong (test_pv_view.py); the GUI starts with it, exits with status 0
# and its screenshot shows the sphere's shadow from ParaView's key light
# (run_gui.sh); csm across 2 pvbatch ranks equals 1 rank (run_ranks.sh).
# ParaView's Debian build is -O0: these take a minute or two each.
if(VTKSHADOW_PARAVIEW)
  set(vtkshadow_pv_out "${VTKSHADOW_TEST_OUT}/paraview")
  add_test(NAME paraview.view
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_BIN}/vtkshadow-pvpython
            ${CMAKE_CURRENT_SOURCE_DIR}/paraview/test_pv_view.py
            ${PROJECT_SOURCE_DIR}/scenes/basic/sphere-directional.json ${vtkshadow_pv_out}/view)
  add_test(NAME paraview.gui
    COMMAND ${VTKSHADOW_GL} ${CMAKE_CURRENT_SOURCE_DIR}/paraview/run_gui.sh ${VTKSHADOW_BIN}
            ${PROJECT_SOURCE_DIR} ${vtkshadow_pv_out}/gui)
  add_test(NAME paraview.ranks
    COMMAND ${VTKSHADOW_GL} ${CMAKE_CURRENT_SOURCE_DIR}/paraview/run_ranks.sh ${VTKSHADOW_BIN}
            ${PROJECT_SOURCE_DIR} ${vtkshadow_pv_out}/ranks)
  set_tests_properties(paraview.view paraview.gui paraview.ranks PROPERTIES
    LABELS "paraview" TIMEOUT 900)
  # Two ranks plus ParaView's -O0 code: keep it from sharing the 2 cores.
  set_tests_properties(paraview.ranks PROPERTIES RUN_SERIAL ON)
endif()
