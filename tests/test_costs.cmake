# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "sanitize.product=215"
  "harness.soft=210"
  "sanitize.unit=108"
  "harness.library.hard=104"
  "harness.library.soft=96"
  "render.soak=92"
  "harness.references_fresh=86"
  "harness.controls=83"
  "harness.library.scivis=73"
  "harness.reflection_pov-two-mirrors=66"
  "harness.library.mirror=60"
  "harness.eevee=54"
  "render.raytrace.soft=50"
  "harness.soft_planar_adaptive=45"
  "cli.bench_soft=43"
  "harness.library.basic=41"
  "harness.library.primitives=35"
  "harness.soft_csm_sampled=34"
  "corpus.subset=33"
  "render.raytrace.classify=30"
  "harness.reflection_pov-wall-mirror=29"
  "harness.library.translucent=29"
  "harness.soft_adaptive=27"
  "paraview.ranks=24"
  "harness.cache=21"
)
foreach(entry IN LISTS _vtkshadow_test_costs)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 cost)
  if(TEST ${name})
    set_tests_properties(${name} PROPERTIES COST ${cost})
  endif()
endforeach()
