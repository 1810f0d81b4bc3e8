# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "harness.soft=193"
  "sanitize.product=189"
  "render.soak=103"
  "harness.library.soft=102"
  "harness.library.hard=99"
  "harness.references_fresh=99"
  "sanitize.unit=79"
  "harness.controls=72"
  "harness.library.scivis=68"
  "harness.reflection_pov-two-mirrors=63"
  "harness.library.mirror=56"
  "harness.eevee=50"
  "cli.bench_soft=45"
  "render.raytrace.soft=40"
  "harness.soft_planar_adaptive=40"
  "harness.soft_csm_sampled=35"
  "harness.library.primitives=33"
  "harness.library.basic=30"
  "corpus.subset=30"
  "harness.reflection_pov-wall-mirror=28"
  "harness.library.translucent=28"
  "render.raytrace.classify=26"
  "harness.soft_adaptive=22"
  "paraview.ranks=21"
)
foreach(entry IN LISTS _vtkshadow_test_costs)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 cost)
  if(TEST ${name})
    set_tests_properties(${name} PROPERTIES COST ${cost})
  endif()
endforeach()
