# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "harness.soft=293"
  "sanitize.product=250"
  "harness.references_fresh=137"
  "harness.library.soft=114"
  "render.soak=105"
  "harness.library.hard=70"
  "render.raytrace.soft=64"
  "harness.eevee=55"
  "sanitize.unit=55"
  "harness.reflection_pov-two-mirrors=48"
  "harness.library.mirror=46"
  "harness.library.scivis=45"
  "harness.soft_csm_sampled=44"
  "harness.soft_planar_adaptive=43"
  "cli.bench_soft=42"
  "harness.library.primitives=42"
  "harness.controls=40"
  "corpus.subset=33"
  "harness.reflection_pov-wall-mirror=30"
  "harness.soft_adaptive=27"
  "paraview.ranks=25"
  "harness.library.basic=23"
  "harness.cache=22"
)
foreach(entry IN LISTS _vtkshadow_test_costs)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 cost)
  if(TEST ${name})
    set_tests_properties(${name} PROPERTIES COST ${cost})
  endif()
endforeach()
