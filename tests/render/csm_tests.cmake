# Cascaded shadow maps (--technique csm) and the automatic choice (--technique
# auto: planar where every shadow falls on plane receivers, cascaded maps
# otherwise, nothing when nothing casts) against the exact answer by ray
# casting, with shadows on every surface (--reference all), using the scene
# builders of test_planar.py, outside a one-pixel band along the exact
# boundary. Rows: case, light, max wrong_pct, max wrong_of_shadow_pct, each
# bound by the margin rule of render_bounds.cmake (included by
# planar_tests.cmake); the comment gives what was measured (wrong_pct /
# wrong_of_shadow_pct). Every light of the multi-light scenes is checked.
# A unit sphere over a 200 x 200 floor (big-floor-200) must keep its shadow:
# VTK 9.1's own pass measured 3.8% wrong there.
vtkshadow_exact_cases(csm all
  "sphere-floor-directional-4x3 0 0.02 1.0"   # 0 / 0
  "sphere-floor-point-4x3 0 0.02 1.0"         # 0 / 0
  "sphere-floor-spot-4x3 0 0.02 1.0"          # 0 / 0
  "sphere-floor-directional-16x9 0 0.02 1.0"  # 0 / 0
  "box-tilted-plane-directional 0 0.026 1.2"  # 0.0060 / 0.1307
  "box-tilted-plane-point 0 0.02 1.0"         # 0 / 0
  "box-tilted-plane-spot 0 0.02 1.0"          # 0 / 0
  "light-below-camera-below 0 0.02 1.0"       # 0 / 0 (no shadow at all)
  "caster-above-point-light 0 0.02 1.0"       # 0 / 0
  "near-far-1e5 0 0.027 1.4"                  # 0.0069 / 0.3387
  "offset-1e6 0 0.02 1.0"                     # 0 / 0
  "scale-1e-6 0 0.02 1.0"                     # 0 / 0
  "two-lights 0 0.02 1.0"                     # 0 / 0
  "two-lights 1 0.02 1.0"                     # 0 / 0
  "many-receivers 0 0.02 1.0"                 # 0 / 0
  "many-receivers 1 0.02 1.0"                 # 0 / 0
  "many-receivers 2 0.02 1.0"                 # 0 / 0
  "big-floor-200 0 0.02 1.0"                  # 0 / 0
  "thin-plate 0 0.021 1.1")                   # 0.0004 / 0.0186
# Known failures, bounded on both sides: each passes while csm misses the
# bounded rows' bounds (then move it into the rows above) and fails once it
# is worse than AT_MOST (1.25 x measured + the floors).
# grazing-89.9: with the light 89.9 degrees from the floor normal csm loses
# the whole shadow of the low slabs (shadows 573 times longer than the slabs
# are high): measured wrong_pct 10.7844, wrong_of_shadow_pct 100.
# grazing-85: the shadows fade out towards their far ends with the clipping
# range fitted to the visible geometry: measured 0.9073 / 9.3099, against
# bounds of 0.48 / 5.0 that csm met with a looser clipping range.
vtkshadow_exact_case(csm all grazing-85 0 0.48 5.0
  KNOWN_FAILURE "csm on grazing-85: the far ends of the shadows fade (measured 0.9073 / 9.3099)"
  AT_MOST 1.16 12.7)
vtkshadow_exact_case(csm all grazing-89.9 0 0.02 1.0
  KNOWN_FAILURE "csm loses the grazing-89.9 shadow (measured 10.7844 / 100)"
  AT_MOST 13.5 126)

vtkshadow_exact_cases(auto all
  "sphere-floor-directional-4x3 0 0.02 1.0"   # 0 / 0
  "sphere-floor-point-4x3 0 0.02 1.0"         # 0 / 0
  "sphere-floor-spot-4x3 0 0.02 1.0"          # 0 / 0
  "sphere-floor-directional-16x9 0 0.02 1.0"  # 0 / 0
  "box-tilted-plane-directional 0 0.62 14"    # 0.3067 / 6.7286
  "box-tilted-plane-point 0 0.19 2.8"         # 0.0949 / 1.3673
  "box-tilted-plane-spot 0 0.21 2.5"          # 0.1007 / 1.2339
  "grazing-85 0 0.02 1.0"                     # 0 / 0
  "grazing-89.9 0 0.02 1.0"                   # 0 / 0 (auto chooses planar here)
  "light-below-camera-below 0 0.02 1.0"       # 0 / 0
  "caster-above-point-light 0 0.02 1.0"       # 0 / 0
  "near-far-1e5 0 0.02 1.0"                   # 0 / 0
  "offset-1e6 0 0.02 1.0"                     # 0 / 0
  "scale-1e-6 0 0.02 1.0"                     # 0 / 0
  "two-lights 0 0.02 1.0"                     # 0 / 0
  "two-lights 1 0.02 1.0"                     # 0 / 0
  "many-receivers 0 0.02 1.0"                 # 0 / 0
  "many-receivers 1 0.02 1.0"                 # 0 / 0
  "many-receivers 2 0.02 1.0"                 # 0 / 0
  "big-floor-200 0 0.02 1.0"                  # 0 / 0
  "thin-plate 0 0.027 1.4")                   # 0.0068 / 0.3351

# auto's choice per light (mixed planar + csm in one frame, a light with no
# visible shadow, a receiver out of view, a box (convex, corners repeated
# per face), an L-shaped prism (concave), the --max-error target, points and
# lines drawn as spheres and tubes: the thin-impostor terms send them to an
# exact technique), each light's shadows against the exact answer
# (tests/render/test_auto_choice.py).
foreach(case mixed idle-light out-of-view box concave volume-thin volume-fill max-error
        impostors)
  add_test(NAME render.auto_choice.${case}
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_auto_choice.py
            --bin ${VTKSHADOW_BIN} --out ${VTKSHADOW_TEST_OUT}/auto_choice --case ${case})
  set_tests_properties(render.auto_choice.${case} PROPERTIES LABELS "render" TIMEOUT 300)
endforeach()
