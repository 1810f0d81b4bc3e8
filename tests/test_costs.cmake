# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "sanitize.product=465"
  "harness.soft=431"
  "harness.library.hard=214"
  "sanitize.unit=206"
  "harness.library.soft=188"
  "render.soak=176"
  "harness.controls=171"
  "harness.references_fresh=170"
  "harness.reflection_pov-two-mirrors=140"
  "harness.library.scivis=140"
  "harness.library.mirror=116"
  "render.raytrace.soft=111"
  "harness.eevee=102"
  "cli.bench_soft=91"
  "harness.soft_csm_sampled=88"
  "harness.soft_planar_adaptive=83"
  "render.raytrace.classify=73"
  "harness.library.primitives=71"
  "harness.library.basic=61"
  "harness.library.translucent=59"
  "harness.soft_adaptive=57"
  "corpus.subset=55"
  "paraview.ranks=47"
  "harness.reflection_pov-wall-mirror=43"
  "harness.cache=38"
  "harness.soft_volume=35"
  "render.csm.flicker=32"
  "python.splat_flat_casters=31"
  "render.exact_trial.isosurface=30"
  "render.display.xvfb_run_loop=29"
  "render.auto_choice.max-error=26"
  "render.csm.flicker-offset-1e6=25"
  "corpus.classify_identical=24"
  "harness.variants=24"
  "python.vedo_placement=24"
  "harness.reflection_pov-below=23"
  "core.rt_classify=22"
  "harness.reflection_pov-wall-point=21"
  "harness.soft_csm=21"
  "python.volume_casters=21"
)
foreach(entry IN LISTS _vtkshadow_test_costs)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 cost)
  if(TEST ${name})
    set_tests_properties(${name} PROPERTIES COST ${cost})
  endif()
endforeach()
