# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "sanitize.product=217"
  "harness.soft=177"
  "harness.library.soft=174"
  "harness.library.hard=110"
  "harness.references_fresh=93"
  "sanitize.unit=90"
  "render.soak=85"
  "cli.bench_soft=67"
  "harness.soft_planar=54"
  "harness.eevee=52"
  "render.raytrace.soft=50"
  "harness.library.scivis=49"
  "harness.reflection_pov-two-mirrors=45"
  "harness.soft_csm_sampled=43"
  "harness.library.mirror=41"
  "harness.library.basic=33"
  "harness.controls=32"
  "harness.soft_planar_adaptive=31"
  "paraview.ranks=30"
  "harness.reflection_pov-wall-mirror=29"
  "render.display.xvfb_run_loop=28"
  "harness.soft_adaptive=28"
  "harness.cache=20"
)
foreach(entry IN LISTS _vtkshadow_test_costs)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 cost)
  if(TEST ${name})
    set_tests_properties(${name} PROPERTIES COST ${cost})
  endif()
endforeach()
