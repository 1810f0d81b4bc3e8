# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "harness.soft=259"
  "sanitize.product=198"
  "harness.references_fresh=116"
  "harness.library.soft=100"
  "render.soak=93"
  "harness.library.hard=59"
  "render.raytrace.soft=50"
  "harness.eevee=45"
  "harness.reflection_pov-two-mirrors=43"
  "sanitize.unit=43"
  "harness.library.mirror=41"
  "harness.library.scivis=40"
  "cli.bench_soft=38"
  "harness.controls=37"
  "harness.soft_csm_sampled=34"
  "harness.soft_planar_adaptive=34"
  "corpus.subset=31"
  "harness.reflection_pov-wall-mirror=28"
  "paraview.ranks=24"
  "harness.library.basic=23"
  "harness.cache=22"
  "harness.soft_adaptive=22"
  "harness.library.translucent=21"
)
foreach(entry IN LISTS _vtkshadow_test_costs)
  string(REPLACE "=" ";" pair "${entry}")
  list(GET pair 0 name)
  list(GET pair 1 cost)
  if(TEST ${name})
    set_tests_properties(${name} PROPERTIES COST ${cost})
  endif()
endforeach()
