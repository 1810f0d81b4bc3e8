# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "harness.soft=254"
  "sanitize.product=216"
  "harness.references_fresh=118"
  "render.soak=114"
  "harness.library.soft=106"
  "harness.library.hard=100"
  "harness.library.scivis=77"
  "harness.controls=71"
  "sanitize.unit=68"
  "harness.reflection_pov-two-mirrors=67"
  "harness.library.mirror=62"
  "render.raytrace.soft=54"
  "harness.eevee=45"
  "cli.bench_soft=45"
  "harness.soft_csm_sampled=43"
  "harness.library.basic=33"
  "corpus.subset=31"
  "harness.soft_planar_adaptive=30"
  "harness.library.translucent=29"
  "harness.reflection_pov-wall-mirror=29"
  "harness.library.primitives=29"
  "paraview.ranks=25"
  "render.raytrace.classify=21"
  "harness.cache=21"
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
