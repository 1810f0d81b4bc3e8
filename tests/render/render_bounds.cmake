# vtkshadow_exact_case(TECHNIQUE REFERENCE CASE LIGHT MAX_WRONG_PCT MAX_WRONG_OF_SHADOW_PCT
#                      [KNOWN_FAILURE reason AT_MOST WRONG_PCT WRONG_OF_SHADOW_PCT])
# One test_planar.py case (one light) against the exact ray-cast answer, as
# render.TECHNIQUE.CASE (light 0) or render.TECHNIQUE.CASE-lightN.
#
# The bounds sit near what is measured. The rule for every bound:
#
#     bound = measured + max(floor, measured), rounded up to 2 significant digits
#
# i.e. twice the measured value, and at least the measured value plus a floor:
#   wrong_pct            floor 0.02 (percent of the compared pixels: about 50
#                        pixels at 640x480; another Mesa or CPU moves a few
#                        pixels along the shadow edges);
#   wrong_of_shadow_pct  floor 1.0 (percent of the exact shadow's pixels).
# A shadow that is lost reads about 100 % of the shadow, so even the smallest
# one (thin-plate: the whole shadow is 0.30 % of the compared pixels) fails.
# The measured values (Debian 12, Mesa llvmpipe, when the bounds were set) are
# in the comment of each table row; re-measure before changing a bound.
#
# KNOWN_FAILURE: the case misses its bounds today for the reason given; the
# test passes while it still misses them and fails once the case is fixed,
# so that it moves to the bounded rows (test_planar.py --known-failure). It
# fails too when the case gets worse than AT_MOST (wrong_pct,
# wrong_of_shadow_pct): 1.25 x measured + the floors above.
function(vtkshadow_exact_case technique reference case light max_wrong max_of_shadow)
  cmake_parse_arguments(PARSE_ARGV 6 arg "" "KNOWN_FAILURE" "AT_MOST")
  set(name render.${technique}.${case})
  if(NOT light EQUAL 0)
    set(name ${name}-light${light})
  endif()
  set(extra)
  if(arg_KNOWN_FAILURE)
    list(LENGTH arg_AT_MOST n)
    if(NOT n EQUAL 2)
      message(FATAL_ERROR "${name}: KNOWN_FAILURE needs AT_MOST WRONG_PCT WRONG_OF_SHADOW_PCT")
    endif()
    set(extra --known-failure "${arg_KNOWN_FAILURE}" --known-failure-at-most ${arg_AT_MOST})
  endif()
  add_test(NAME ${name}
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_planar.py
            --bin ${VTKSHADOW_BIN} --out ${VTKSHADOW_TEST_OUT}/${technique} --case ${case}
            --light ${light} --technique ${technique} --reference ${reference}
            --max-wrong-pct ${max_wrong} --max-wrong-of-shadow-pct ${max_of_shadow} ${extra})
  set_tests_properties(${name} PROPERTIES LABELS "render" TIMEOUT 300)
endfunction()

# vtkshadow_exact_cases(TECHNIQUE REFERENCE ROWS...): one test per row
# "CASE LIGHT MAX_WRONG_PCT MAX_WRONG_OF_SHADOW_PCT".
function(vtkshadow_exact_cases technique reference)
  foreach(row IN LISTS ARGN)
    separate_arguments(f UNIX_COMMAND "${row}")
    list(GET f 0 case)
    list(GET f 1 light)
    list(GET f 2 max_wrong)
    list(GET f 3 max_of_shadow)
    vtkshadow_exact_case(${technique} ${reference} ${case} ${light} ${max_wrong} ${max_of_shadow})
  endforeach()
endfunction()
