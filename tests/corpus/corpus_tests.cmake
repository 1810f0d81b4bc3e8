# The real-client corpus (docs/corpus.md): third-party programs (vedo's
# examples from Debian's python3-vedo-examples) run unmodified with
# enable_shadows injected, every technique against raytrace and none.
# corpus.subset runs the `ctest` subset of compare/corpus/corpus.json; the
# whole corpus is scripts/corpus.sh (about 10 minutes).
set(VTKSHADOW_CORPUS ${PROJECT_SOURCE_DIR}/compare/corpus/corpus.py)
set(VTKSHADOW_CORPUS_OUT ${VTKSHADOW_TEST_OUT}/corpus)
add_test(NAME corpus.subset
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${VTKSHADOW_CORPUS} run --python ${VTKSHADOW_PY}
          --subset ctest --out ${VTKSHADOW_CORPUS_OUT}/subset)
set_tests_properties(corpus.subset PROPERTIES LABELS "corpus;render" TIMEOUT 600)

# Negative controls: each check must report a deliberately broken run
# (corpus.py --expect-fail CHECK exits 0 only when CHECK failed). One example,
# three techniques each.
function(vtkshadow_corpus_negative name example check)
  add_test(NAME corpus.negative.${name}
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${VTKSHADOW_CORPUS} run --python ${VTKSHADOW_PY}
            --only ${example} --techniques raytrace,none,csm --expect-fail ${check}
            --out ${VTKSHADOW_CORPUS_OUT}/negative-${name} ${ARGN})
  set_tests_properties(corpus.negative.${name} PROPERTIES LABELS "corpus;render" TIMEOUT 300)
endfunction()
