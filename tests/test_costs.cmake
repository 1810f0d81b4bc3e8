# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "harness.soft=311"
  "sanitize.product=265"
  "harness.references_fresh=120"
  "harness.library.soft=106"
  "render.soak=104"
  "harness.library.hard=78"
  "sanitize.unit=76"
  "harness.library.scivis=60"
  "harness.controls=55"
  "harness.library.mirror=55"
  "render.raytrace.soft=52"
  "harness.reflection_pov-two-mirrors=52"
  "harness.eevee=49"
  "cli.bench_soft=47"
  "harness.soft_csm_sampled=46"
  "harness.soft_planar_adaptive=33"
  "corpus.subset=33"
  "harness.library.primitives=32"
  "harness.reflection_pov-wall-mirror=29"
  "harness.library.basic=28"
  "paraview.ranks=27"
  "harness.library.translucent=24"
  "harness.cache=22"
  "harness.soft_adaptive=21"
)
foreach(entry IN LISTS _vtkshadow_test_costs)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 cost)
  if(TEST ${name})
    set_tests_properties(${name} PROPERTIES COST ${cost})
  endif()
endforeach()
