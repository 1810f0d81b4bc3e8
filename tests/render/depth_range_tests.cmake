# Wide depth ranges (scenes/hard/near-far-1e5 and -1e6): the near plane comes
# from the visible geometry (vtkShadowScene::ResetCameraClippingRange), so the
# sphere 0.15 from the camera is drawn (--near-object 0) and every technique
# is measured against the exact ray-cast answer of exact_scene.py.
# csm with its default settings: the practical splits keep every cascade
# within RatioPerCascade (vsh_csm_splits max_ratio). Before that cap the first
# cascade spanned 0.4..834 (texels of 3000 pixels) and csm was 2.73% wrong.
function(vtkshadow_depth_range_test name)
  add_test(NAME render.${name}
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_depth_range.py
            --bin ${VTKSHADOW_BIN} --out ${VTKSHADOW_TEST_OUT}/depth-range ${ARGN})
  set_tests_properties(render.${name} PROPERTIES LABELS "render")
endfunction()
foreach(range 1e5 1e6)
  set(scene ${PROJECT_SOURCE_DIR}/scenes/hard/near-far-${range}.json)
  vtkshadow_depth_range_test(depth.${range}.none --scene ${scene} --technique none
    --reference none --max-wrong-pct 0.0 --near-object 0)
  vtkshadow_depth_range_test(depth.${range}.planar --scene ${scene} --technique planar
    --reference planar --max-wrong-pct 0.0 --near-object 0)
  vtkshadow_depth_range_test(depth.${range}.csm --scene ${scene} --technique csm
    --reference all --max-wrong-pct 0.5 --near-object 0)
  vtkshadow_depth_range_test(depth.${range}.auto --scene ${scene} --technique auto
    --reference all --max-wrong-pct 0.5 --near-object 0)
endforeach()
