# Square window: `none` against the unshadowed exact answer (the measurement
# itself is exact), and against the shadowed answer (the comparison sees the
# missing shadow: about 2.7% of the valid pixels); `vtk` (VTK 9.1's shadow
# maps) against the shadowed answer.
vtkshadow_visibility_test(none.square --technique none --size 512x512 --reference unshadowed
  --max-wrong-pct 0.0)
vtkshadow_visibility_test(none.shadowed.square --technique none --size 512x512
  --expect-wrong-pct 2.0 3.5)
vtkshadow_visibility_test(vtk.square --technique vtk --size 512x512 --max-wrong-pct 0.05)
# 4:3 window: VTK 9.1 bakes with the window aspect and looks up with aspect 1,
# so its shadow is misplaced (9.14% of the valid pixels wrong). That is VTK's
# bug, not ours to test; what we claim is that csm does not have it: csm's
# wrong_pct must be at least 10 times below vtk's on this scene (and vtk's
# above 0, so the comparison means something).
vtkshadow_visibility_test(csm.beats-vtk.4x3 --technique csm --size 640x480 --beats vtk --by 10)
