# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "render.soak=291"
  "harness.soft=264"
  "sanitize.product=249"
  "harness.references_fresh=132"
  "harness.library.soft=109"
  "harness.library.hard=76"
  "harness.library.mirror=71"
  "harness.library.scivis=63"
  "harness.reflection_pov-two-mirrors=62"
  "sanitize.unit=62"
  "render.raytrace.soft=52"
  "harness.controls=52"
  "harness.eevee=48"
  "cli.bench_soft=40"
  "corpus.subset=38"
  "harness.soft_csm_sampled=36"
  "harness.soft_planar_adaptive=33"
  "harness.library.primitives=31"
  "paraview.ranks=30"
  "harness.reflection_pov-wall-mirror=29"
  "harness.library.basic=26"
  "harness.cache=23"
  "harness.soft_adaptive=23"
  "harness.library.translucent=22"
)
foreach(entry IN LISTS _vtkshadow_test_costs)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 cost)
  if(TEST ${name})
    set_tests_properties(${name} PROPERTIES COST ${cost})
  endif()
endforeach()
