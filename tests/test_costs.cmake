# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "harness.soft=272"
  "sanitize.product=178"
  "harness.references_fresh=113"
  "harness.library.soft=104"
  "render.soak=82"
  "sanitize.unit=73"
  "harness.library.hard=67"
  "render.raytrace.soft=59"
  "harness.eevee=55"
  "harness.reflection_pov-two-mirrors=45"
  "cli.bench_soft=43"
  "harness.library.scivis=40"
  "harness.library.mirror=39"
  "harness.soft_csm_sampled=37"
  "harness.controls=35"
  "harness.soft_planar_adaptive=34"
  "harness.reflection_pov-wall-mirror=29"
  "paraview.ranks=26"
  "harness.soft_adaptive=23"
  "harness.cache=23"
  "harness.library.basic=21"
  "corpus.subset=70"
)
foreach(entry IN LISTS _vtkshadow_test_costs)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 cost)
  if(TEST ${name})
    set_tests_properties(${name} PROPERTIES COST ${cost})
  endif()
endforeach()
