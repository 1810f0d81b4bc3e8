# Square window: `none` against the unshadowed exact answer (the measurement
# itself is exact), `vtk` (VTK 9.1's shadow maps) against the shadowed answer.
vtkshadow_visibility_test(none.square --technique none --size 512x512 --reference unshadowed
  --max-wrong-pct 0.0)
vtkshadow_visibility_test(none.shadowed.square --technique none --size 512x512
  --expect-wrong-pct 3 100)
vtkshadow_visibility_test(vtk.square --technique vtk --size 512x512 --max-wrong-pct VTK_SQUARE_MAX)
# 4:3 window: VTK 9.1 bakes with the window aspect and looks up with aspect 1,
# so its shadow is misplaced. We record the measured error as it is.
vtkshadow_visibility_test(vtk.4x3 --technique vtk --size 640x480 --expect-wrong-pct VTK_43_LO VTK_43_HI)
