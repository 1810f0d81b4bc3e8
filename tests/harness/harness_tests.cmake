# The reference harness (docs/harness.md): included by tests/vtk_tests.cmake,
# which defines VTKSHADOW_GL (a prefix giving an X display through the shared
# Xvfb fixture), VTKSHADOW_PY, VTKSHADOW_BIN and VTKSHADOW_TEST_OUT.
#
# harness.library.<group>: the whole scene library at test scale (0.4, i.e.
# 320x240) by scripts/library-run.sh: every VTK technique against the
# shipped references of scenes/references (a reference that is not shipped
# fails and names scripts/update-references.sh), --check against
# scenes/thresholds.json (mirror: wrong_pct and reflection colour; soft:
# against POV-Ray's area lights, with the hard-shadow control).
# harness.thresholds: every committed limit against what those runs measured.
# harness.references_fresh: a sample of the shipped references rendered
# fresh by POV-Ray and Cycles, equal to the shipped ones.
# harness.<unit>: cache invalidation, missing / hanging / crashing renderer,
# hostile scene, unknown renderer name, HTML escaping, faults (renderer
# killed mid-frame, full / read-only output folder, damaged cache entry).
# harness.check: --check fails for every row it cannot bound.
# harness.eevee: Blender EEVEE (both presets) as a peer on one small basic
# scene, wrong_pct against POV-Ray within measured bounds (about 1 min).
find_program(VTKSHADOW_POVRAY povray)
find_program(VTKSHADOW_BLENDER blender)
if(NOT VTKSHADOW_POVRAY OR NOT VTKSHADOW_BLENDER)
  message(FATAL_ERROR "the harness tests need povray and blender: sh scripts/install-deps.sh")
endif()

set(_harness_src ${CMAKE_CURRENT_LIST_DIR})
set(_library_out ${VTKSHADOW_TEST_OUT}/harness/library)
# The scene groups of scripts/library-run.sh.
set(_library_groups basic scivis cad hard mirror soft translucent primitives)
foreach(group ${_library_groups})
  add_test(NAME harness.library.${group}
    COMMAND ${CMAKE_COMMAND} -E env VTKSHADOW_BIN=${VTKSHADOW_BIN}
            VTKSHADOW_DISPLAY_FILE=${CMAKE_BINARY_DIR}/xvfb/display
            sh ${PROJECT_SOURCE_DIR}/scripts/library-run.sh ${_library_out} ${group} --check)
  set_tests_properties(harness.library.${group} PROPERTIES TIMEOUT 900 LABELS "harness"
    FIXTURES_REQUIRED xvfb FIXTURES_SETUP library)
endforeach()

# Every committed limit against the library run just measured: within the
# margin rule, and failed by vtk/none wherever the reference has a shadow and
# by a hard shadow on every soft row (scenes/update_thresholds.py --verify).
set(_library_results)
set(_library_tests)
foreach(group ${_library_groups})
  list(APPEND _library_results ${_library_out}/${group}/results.json)
  list(APPEND _library_tests harness.library.${group})
endforeach()
add_test(NAME harness.thresholds
  COMMAND python3 ${PROJECT_SOURCE_DIR}/scenes/update_thresholds.py --verify
          ${PROJECT_SOURCE_DIR}/scenes/thresholds.json --require-controls ${_library_results})
# FIXTURES_REQUIRED pulls the library tests into a run of this test alone;
# DEPENDS makes it wait for all of them under -j.
set_tests_properties(harness.thresholds PROPERTIES TIMEOUT 60 LABELS "harness"
  FIXTURES_REQUIRED library DEPENDS "${_library_tests}")
# The same through --check itself: vtk/none under each technique's limits of
# hard/thin-plate and basic/sphere-plane, a hard shadow (raytrace:samples=1)
# under those of soft/sphere-disk and soft/sun-angle, every light caught.
add_test(NAME harness.controls
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_controls.py --bin ${VTKSHADOW_BIN}
          --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/harness/controls)
set_tests_properties(harness.controls PROPERTIES TIMEOUT 300 LABELS "harness"
  FIXTURES_REQUIRED xvfb)

# The shipped references against a fresh render (a sample: a scene with a
# directional, a point and a spot light, one with lights with a size, and one
# with nested translucent shells),
# and their faults.
add_test(NAME harness.references_fresh
  COMMAND ${VTKSHADOW_PY} ${_harness_src}/test_references.py fresh --bin ${VTKSHADOW_BIN}
          --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/harness/references_fresh
          ${PROJECT_SOURCE_DIR}/scenes/basic/sphere-plane.json
          ${PROJECT_SOURCE_DIR}/scenes/soft/sphere-disk.json
          ${PROJECT_SOURCE_DIR}/scenes/translucent/nested-shells.json)
set_tests_properties(harness.references_fresh PROPERTIES TIMEOUT 900 LABELS "harness")
add_test(NAME harness.references_faults
  COMMAND ${VTKSHADOW_PY} ${_harness_src}/test_references.py faults --bin ${VTKSHADOW_BIN}
          --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/harness/references_faults)
set_tests_properties(harness.references_faults PROPERTIES TIMEOUT 300 LABELS "harness")

foreach(unit cache missing timeout crash hostile renderers html killed full readonly corruptcache)
  add_test(NAME harness.${unit}
    COMMAND ${VTKSHADOW_PY} ${_harness_src}/test_harness.py ${unit} --bin ${VTKSHADOW_BIN}
            --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/harness/${unit})
  # full / readonly need a private mount namespace (root or user
  # namespaces); without one they report SKIP (77) rather than pass.
  set_tests_properties(harness.${unit} PROPERTIES TIMEOUT 600 LABELS "harness"
    SKIP_RETURN_CODE 77)
endforeach()

# EEVEE renders through OpenGL: it needs the shared X display.
add_test(NAME harness.eevee
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_harness.py eevee --bin ${VTKSHADOW_BIN}
          --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/harness/eevee)
set_tests_properties(harness.eevee PROPERTIES TIMEOUT 600 LABELS "harness" FIXTURES_REQUIRED xvfb)

# Tinted shadows (a red filter slab, scenes/translucent/coloured-filter.json):
# every renderer writes the green and blue channels' visibility, POV-Ray and
# Cycles agree on colour_mae, vtk/none (no shadow) and a POV-Ray export
# without the filter are caught by it (test_tinted.py, about 20 s).
add_test(NAME harness.tinted
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_tinted.py --bin ${VTKSHADOW_BIN}
          --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/harness/tinted)
set_tests_properties(harness.tinted PROPERTIES TIMEOUT 120 LABELS "harness" FIXTURES_REQUIRED xvfb)

# --check itself (issue 18): renders VTK techniques, so it needs the display.
add_test(NAME harness.check
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_harness.py check --bin ${VTKSHADOW_BIN}
          --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/harness/check)
set_tests_properties(harness.check PROPERTIES TIMEOUT 600 LABELS "harness" FIXTURES_REQUIRED xvfb)

# Soft shadows (issue 15): the exact penumbra of a sphere over a plane under
# a disk light and a sun with an angle, integrated per pixel
# (exact_penumbra.c), against POV-Ray and Cycles with the sizes, within
# their measured noise; radius 0 gives the hard shadow (test_soft.py).
add_executable(exact_penumbra ${_harness_src}/exact_penumbra.c)
target_link_libraries(exact_penumbra PRIVATE vtkshadow_scene vtkshadow_core vtkshadow_metrics)
set_target_properties(exact_penumbra PROPERTIES C_STANDARD 11 C_EXTENSIONS OFF
  RUNTIME_OUTPUT_DIRECTORY ${VTKSHADOW_BIN})
add_test(NAME harness.soft
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_soft.py --bin ${VTKSHADOW_BIN}
          --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/harness/soft)
set_tests_properties(harness.soft PROPERTIES TIMEOUT 1200 LABELS "harness" FIXTURES_REQUIRED xvfb)

# planar's sampled area light against the exact penumbra; the hard case
# unchanged (docs/soft-shadows.md).
add_test(NAME harness.soft_planar
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_soft_planar.py --bin ${VTKSHADOW_BIN}
          --out ${VTKSHADOW_TEST_OUT}/harness/soft_planar)
set_tests_properties(harness.soft_planar PROPERTIES TIMEOUT 1200 LABELS "harness" FIXTURES_REQUIRED xvfb)

# planar's adaptive sample counts (adaptive=1) against the exact penumbra:
# N = 16 and 64 per light within 0.001 of the non-adaptive pen_mae, the
# stats say the batch was used, adaptive=0 the draw of before byte for byte,
# and the small-occluder failure mode bounded (docs/soft-shadows.md).
add_test(NAME harness.soft_planar_adaptive
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_soft_planar_adaptive.py --bin ${VTKSHADOW_BIN}
          --out ${VTKSHADOW_TEST_OUT}/harness/soft_planar_adaptive)
set_tests_properties(harness.soft_planar_adaptive PROPERTIES TIMEOUT 1200 LABELS "harness" FIXTURES_REQUIRED xvfb)

# csm's PCSS (soft=1) against the exact penumbra: pen_mae per light within
# what it reaches, at most half the hard shadow's, and size 0 / soft=0 the
# hard path byte for byte (docs/soft-shadows.md).
add_test(NAME harness.soft_csm
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_soft_csm.py --bin ${VTKSHADOW_BIN}
          --out ${VTKSHADOW_TEST_OUT}/harness/soft_csm)
set_tests_properties(harness.soft_csm PROPERTIES TIMEOUT 1200 LABELS "harness" FIXTURES_REQUIRED xvfb)

# raytrace's adaptive ray counts against the exact penumbra: adaptive=1 within
# 0.002 pen_mae of adaptive=0 at samples 64, with at most 40% of its rays per
# pixel (--stats rays_per_pixel_light).
add_test(NAME harness.raytrace_adaptive
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_raytrace_adaptive.py --bin ${VTKSHADOW_BIN}
          --out ${VTKSHADOW_TEST_OUT}/harness/raytrace_adaptive)
set_tests_properties(harness.raytrace_adaptive PROPERTIES TIMEOUT 1200 LABELS "harness" FIXTURES_REQUIRED xvfb)

# auto's choice for lights with a size by penumbra_target (issue 15 item 5):
# a loose target picks a cheap candidate (planar or PCSS), a tight one
# raytrace with the model's N; both measured within the target against the
# exact penumbra; hard lights unchanged; bad targets exit 2.
add_test(NAME harness.auto_soft
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_auto_soft.py --bin ${VTKSHADOW_BIN}
          --out ${VTKSHADOW_TEST_OUT}/harness/auto_soft)
set_tests_properties(harness.auto_soft PROPERTIES TIMEOUT 1200 LABELS "harness" FIXTURES_REQUIRED xvfb)

# raytrace weights each shadow ray by max(0, N.L) (vsh_rt_weight.h: v =
# I_on / I_off, as Cycles renders a light with a size): on the sphere's own
# terminator, where the light straddles the horizon, its visibility must
# match the weighted exact integral (1: only the sphere shadows itself) and
# not the plain fraction above the horizon (exact_terminator.c,
# test_rt_terminator.py; docs/soft-shadows.md, "Against both references").
add_executable(exact_terminator ${_harness_src}/exact_terminator.c)
target_link_libraries(exact_terminator PRIVATE vtkshadow_scene vtkshadow_core vtkshadow_metrics)
set_target_properties(exact_terminator PROPERTIES C_STANDARD 11 C_EXTENSIONS OFF
  RUNTIME_OUTPUT_DIRECTORY ${VTKSHADOW_BIN})
add_test(NAME harness.rt_terminator
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_rt_terminator.py --bin ${VTKSHADOW_BIN}
          --out ${VTKSHADOW_TEST_OUT}/harness/rt_terminator)
set_tests_properties(harness.rt_terminator PROPERTIES TIMEOUT 600 LABELS "harness" FIXTURES_REQUIRED xvfb)

# volume's sampled area light (soft_samples) against the exact penumbra; the
# hard case unchanged (docs/soft-shadows.md).
add_test(NAME harness.soft_volume
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_soft_volume.py --bin ${VTKSHADOW_BIN}
          --out ${VTKSHADOW_TEST_OUT}/harness/soft_volume)
set_tests_properties(harness.soft_volume PROPERTIES TIMEOUT 1200 LABELS "harness" FIXTURES_REQUIRED xvfb)

# Technique variants in --techniques (NAME:KEY=VALUE, docs/harness.md):
# bad entries exit 2 naming the entry before anything is written; a variant's
# settings reach vtkshadow-render (volume soft_samples 1 vs 16 against
# POV-Ray's penumbra) and its rows round trip through update_thresholds.py,
# --check and known-failures.json (test_variants.py).
add_test(NAME harness.variants_usage
  COMMAND ${VTKSHADOW_PY} ${_harness_src}/test_variants.py usage --bin ${VTKSHADOW_BIN}
          --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/harness/variants_usage)
set_tests_properties(harness.variants_usage PROPERTIES TIMEOUT 300 LABELS "harness")
add_test(NAME harness.variants
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_variants.py render --bin ${VTKSHADOW_BIN}
          --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/harness/variants)
set_tests_properties(harness.variants PROPERTIES TIMEOUT 1200 LABELS "harness" FIXTURES_REQUIRED xvfb)

add_test(NAME harness.soft_csm_sampled
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_soft_csm_sampled.py --bin ${VTKSHADOW_BIN}
          --out ${VTKSHADOW_TEST_OUT}/harness/soft_csm_sampled)
set_tests_properties(harness.soft_csm_sampled PROPERTIES TIMEOUT 1200 LABELS "harness" FIXTURES_REQUIRED xvfb)

# volume's adaptive sample counts against the exact penumbra, and the
# small-occluder failure mode (docs/soft-shadows.md).
add_test(NAME harness.soft_adaptive
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_soft_adaptive.py --bin ${VTKSHADOW_BIN}
          --out ${VTKSHADOW_TEST_OUT}/harness/soft_adaptive)
set_tests_properties(harness.soft_adaptive PROPERTIES TIMEOUT 1200 LABELS "harness" FIXTURES_REQUIRED xvfb)

# exact_cache.py: exact_penumbra's and exact_terminator's exact images, kept
# by content for every test of the run, give the bytes of a fresh run from a
# miss and from a hit, and a damaged entry is computed again
# (test_exact_cache.py; a cache folder of its own, no display).
add_test(NAME harness.exact_cache
  COMMAND ${VTKSHADOW_PY} ${_harness_src}/test_exact_cache.py --bin ${VTKSHADOW_BIN}
          --out ${VTKSHADOW_TEST_OUT}/harness/exact_cache)
set_tests_properties(harness.exact_cache PROPERTIES TIMEOUT 300 LABELS "harness")

# volume on casters that are not closed: an open bowl seen from its side
# turned away from the light, against the shipped POV-Ray reference (z-pass
# with the unlit side's caps, the default, 0.002 wrong_pct; z-fail,
# unlit_caps=0, the same; z-pass without caps, unlit_caps=0:open_zfail=0,
# 0.059: that --spec fails).
add_test(NAME harness.open_casters
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_open_casters.py --bin ${VTKSHADOW_BIN}
          --out ${VTKSHADOW_TEST_OUT}/harness/open_casters)
set_tests_properties(harness.open_casters PROPERTIES TIMEOUT 300 LABELS "harness" FIXTURES_REQUIRED xvfb)
add_test(NAME harness.open_casters.zfail
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${_harness_src}/test_open_casters.py --bin ${VTKSHADOW_BIN}
          --out ${VTKSHADOW_TEST_OUT}/harness/open_casters_zfail --spec volume:unlit_caps=0)
set_tests_properties(harness.open_casters.zfail PROPERTIES TIMEOUT 300 LABELS "harness" FIXTURES_REQUIRED xvfb)
