# Style rules checked by tools (label unit: they need no GL and run in seconds).
# No function longer than 120 lines, in any language, in the product (vtkshadow/,
# tools/, paraview/), the harness (compare/), the tests, the benchmarks and the
# scripts: universal-ctags gives each C/C++ function's first and last line,
# Python's ast module each def's (tests/style/check_function_length.py).
find_package(Python3 COMPONENTS Interpreter REQUIRED)
find_program(VTKSHADOW_CTAGS NAMES ctags-universal universal-ctags ctags)
if(NOT VTKSHADOW_CTAGS)
  # The test still runs and fails with the install hint: never a silent skip.
  set(VTKSHADOW_CTAGS ctags)
endif()
add_test(NAME style.function_length
  COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/check_function_length.py
          --ctags ${VTKSHADOW_CTAGS} --max 120 ${PROJECT_SOURCE_DIR}
          vtkshadow tools compare paraview tests bench scripts scenes)
set_tests_properties(style.function_length PROPERTIES LABELS "unit")

# The VTK layer, the product's tools and the harness in VTK's clang-format style
# (every C++ file under vtkshadow/vtk, tools/ and compare/).
find_program(VTKSHADOW_CLANG_FORMAT NAMES clang-format clang-format-14)
if(NOT VTKSHADOW_CLANG_FORMAT)
  set(VTKSHADOW_CLANG_FORMAT clang-format) # the test fails with the install hint
endif()
add_test(NAME style.clang_format
  COMMAND sh ${CMAKE_CURRENT_LIST_DIR}/check_clang_format.sh ${PROJECT_SOURCE_DIR}
          ${VTKSHADOW_CLANG_FORMAT})
set_tests_properties(style.clang_format PROPERTIES LABELS "unit")
