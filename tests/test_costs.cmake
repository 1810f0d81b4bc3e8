# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "harness.soft=266"
  "sanitize.product=187"
  "harness.references_fresh=116"
  "harness.library.soft=101"
  "render.soak=100"
  "harness.library.hard=63"
  "sanitize.unit=60"
  "render.raytrace.soft=54"
  "harness.eevee=50"
  "harness.reflection_pov-two-mirrors=46"
  "harness.library.scivis=40"
  "harness.library.mirror=39"
  "harness.soft_csm_sampled=37"
  "harness.controls=36"
  "cli.bench_soft=34"
  "harness.soft_planar_adaptive=33"
  "corpus.subset=29"
  "harness.reflection_pov-wall-mirror=29"
  "harness.soft_adaptive=25"
  "paraview.ranks=24"
  "harness.cache=23"
  "harness.library.basic=21"
)
foreach(entry IN LISTS _vtkshadow_test_costs)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 cost)
  if(TEST ${name})
    set_tests_properties(${name} PROPERTIES COST ${cost})
  endif()
endforeach()
