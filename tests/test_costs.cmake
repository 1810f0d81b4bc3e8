# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "harness.soft=200"
  "sanitize.product=195"
  "harness.references_fresh=102"
  "render.soak=101"
  "harness.library.soft=100"
  "harness.library.hard=95"
  "sanitize.unit=79"
  "harness.controls=75"
  "harness.library.scivis=72"
  "harness.reflection_pov-two-mirrors=67"
  "harness.library.mirror=58"
  "harness.eevee=46"
  "render.raytrace.soft=46"
  "cli.bench_soft=40"
  "harness.soft_csm_sampled=35"
  "harness.library.primitives=34"
  "corpus.subset=32"
  "harness.soft_planar_adaptive=31"
  "harness.library.basic=30"
  "harness.library.translucent=29"
  "harness.reflection_pov-wall-mirror=28"
  "render.raytrace.classify=28"
  "harness.soft_adaptive=24"
  "paraview.ranks=23"
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
