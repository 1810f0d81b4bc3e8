# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "sanitize.product=218"
  "harness.soft=211"
  "harness.library.hard=111"
  "harness.library.soft=108"
  "render.soak=102"
  "sanitize.unit=90"
  "harness.references_fresh=89"
  "harness.controls=76"
  "harness.library.scivis=73"
  "harness.reflection_pov-two-mirrors=72"
  "harness.library.mirror=60"
  "harness.eevee=48"
  "render.raytrace.soft=46"
  "cli.bench_soft=44"
  "harness.soft_planar_adaptive=42"
  "harness.library.primitives=35"
  "harness.soft_csm_sampled=33"
  "harness.library.translucent=33"
  "harness.library.basic=32"
  "harness.reflection_pov-wall-mirror=30"
  "corpus.subset=29"
  "render.raytrace.classify=29"
  "harness.soft_adaptive=27"
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
