# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py
# from a whole ctest run): ctest starts the longest first, so that the run
# does not end on one long test. Tests of this directory only.
set(_vtkshadow_test_costs
  "harness.soft=209"
  "sanitize.product=202"
  "harness.references_fresh=106"
  "render.soak=103"
  "harness.library.soft=103"
  "harness.library.hard=96"
  "harness.controls=79"
  "sanitize.unit=74"
  "harness.library.scivis=72"
  "harness.reflection_pov-two-mirrors=64"
  "harness.library.mirror=59"
  "harness.eevee=54"
  "cli.bench_soft=43"
  "render.raytrace.soft=42"
  "harness.library.primitives=37"
  "harness.soft_csm_sampled=36"
  "corpus.subset=31"
  "harness.library.basic=29"
  "harness.reflection_pov-wall-mirror=28"
  "harness.soft_planar_adaptive=28"
  "harness.library.translucent=27"
  "render.raytrace.classify=25"
  "paraview.ranks=22"
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
