# Wide depth ranges (scenes/hard/near-far-1e5 and -1e6): the near plane comes
# from the visible geometry (vtkShadowScene::ResetCameraClippingRange), so the
# sphere 0.15 from the camera is drawn (--near-object 0) and every technique
# is measured against the exact ray-cast answer of exact_scene.py.
# csm runs with logarithmic splits (lambda=1): with the default practical
# splits (lambda 0.75) its first cascade spans 0.4..834 at a depth ratio of
# 5e4, texels of 3000 pixels, and the shadows near the camera are lost
# (2.7% wrong); the split policy belongs to the cascaded pass.
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
  vtkshadow_depth_range_test(depth.${range}.csm --scene ${scene} --technique csm --set lambda=1
    --reference all --max-wrong-pct 0.5 --near-object 0)
  vtkshadow_depth_range_test(depth.${range}.auto --scene ${scene} --technique auto
    --reference all --max-wrong-pct 0.5 --near-object 0)
endforeach()
