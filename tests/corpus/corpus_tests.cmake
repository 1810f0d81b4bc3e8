# The real-client corpus (docs/corpus.md): third-party programs (vedo's
# examples from Debian's python3-vedo-examples) run unmodified with
# enable_shadows injected, every technique against raytrace and none.
# corpus.subset runs the `ctest` subset of compare/corpus/corpus.json (5 examples
# x 7 techniques, about 70 s; with the negative controls 120 s of CPU); the
# whole corpus is scripts/corpus.sh (60 examples, about 8 minutes).
set(VTKSHADOW_CORPUS ${PROJECT_SOURCE_DIR}/compare/corpus/corpus.py)
set(VTKSHADOW_CORPUS_OUT ${VTKSHADOW_TEST_OUT}/corpus)
# The subset runs against the installed package, as a user's program would:
# Debian's plain /usr/bin/python3 (no PYTHONPATH, no LD_LIBRARY_PATH) after
# install.package has installed this build's .deb, and vtkshadow must come
# from /usr/lib/python3/dist-packages.
add_test(NAME corpus.subset
  COMMAND ${VTKSHADOW_GL} /usr/bin/env -u PYTHONPATH -u LD_LIBRARY_PATH /usr/bin/python3
          ${VTKSHADOW_CORPUS} run --python /usr/bin/python3 --subset ctest
          --require-module /usr/lib/python3/dist-packages --out ${VTKSHADOW_CORPUS_OUT}/subset)
set_tests_properties(corpus.subset PROPERTIES LABELS "corpus;render" TIMEOUT 600
  FIXTURES_REQUIRED installed_package)

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
# crash: the csm run aborts; error: it issues a VTK error; vanish: it hides
# the largest actor; none-lighting: it darkens the surfaces where nothing
# casts (warp1); bound: none's frame stands in for csm's (--as csm=none) on
# an example whose shadows cover more than csm's 1.5% bound.
vtkshadow_corpus_negative(crash advanced.interpolateScalar3 crash --sabotage crash)
vtkshadow_corpus_negative(error advanced.interpolateScalar3 error --sabotage error)
vtkshadow_corpus_negative(vanish advanced.interpolateScalar3 vanish --sabotage hide)
vtkshadow_corpus_negative(none_lighting advanced.warp1 none-lighting --sabotage light)
vtkshadow_corpus_negative(bound advanced.interpolateScalar3 bound --techniques raytrace,none,volume
                          --as volume=none)
# shadow: none's frame stands in for csm's on an example whose shadow is
# small in the frame (under csm's 1.5% bound): the shadow-relative check
# still sees it lost.
vtkshadow_corpus_negative(shadow basic.legendbox shadow
                          --techniques raytrace,none,csm --as csm=none)

# raytrace's classifier changes no pixel of third-party programs: seven vedo
# examples (curvature-coloured mesh, boolean, extrusion, tubes of varying
# radius; and three that draw points as spheres or lines as tubes among
# meshes: warp1, connVtx, silhouette1) under raytrace and
# raytrace:classify=0, equal in every pixel, the classifier's maps built in
# every one. Budget: 30 s.
add_test(NAME corpus.classify_identical
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/corpus/test_classify_identical.py
          --python ${VTKSHADOW_BIN}/vtkshadow-python --out ${VTKSHADOW_CORPUS_OUT}/classify
          advanced/measure_curvature basic/boolean basic/extrude basic/tube_radii
          advanced/warp1 basic/connVtx basic/silhouette1)
set_tests_properties(corpus.classify_identical PROPERTIES LABELS "corpus;render" TIMEOUT 300)
