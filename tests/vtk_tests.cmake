# Tests that need VTK and an X display (Debian's VTK renders through GLX only).
# Each GL test starts its own Xvfb server (gl-run.sh), so the tests also run
# in parallel and from a shell without DISPLAY. A missing Xvfb is an error,
# never a silently skipped test.
find_program(VTKSHADOW_XVFB Xvfb)
if(NOT VTKSHADOW_XVFB)
  message(FATAL_ERROR "Xvfb not found: apt-get install xvfb xauth (the GL tests need it)")
endif()
set(VTKSHADOW_GL ${CMAKE_COMMAND} -E env VTKSHADOW_DISPLAY_FILE=${CMAKE_BINARY_DIR}/xvfb/display
  ${CMAKE_CURRENT_SOURCE_DIR}/gl-run.sh)
# One Xvfb for the whole run, started and stopped as a ctest fixture.
add_test(NAME xvfb.start COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/xvfb-fixture.sh start ${CMAKE_BINARY_DIR}/xvfb)
add_test(NAME xvfb.stop COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/xvfb-fixture.sh stop ${CMAKE_BINARY_DIR}/xvfb)
set_tests_properties(xvfb.start PROPERTIES FIXTURES_SETUP xvfb)
set_tests_properties(xvfb.stop PROPERTIES FIXTURES_CLEANUP xvfb)
set(VTKSHADOW_BIN "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_BINDIR}")
set(VTKSHADOW_PY "${VTKSHADOW_BIN}/vtkshadow-python")
set(VTKSHADOW_TEST_OUT "${CMAKE_BINARY_DIR}/test-output")
# Tests write below it; their own folders they make themselves.
file(MAKE_DIRECTORY "${VTKSHADOW_TEST_OUT}")

# Python: the wrapped classes import and work.
add_test(NAME python.api
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_python_api.py
          ${PROJECT_SOURCE_DIR})

# enable_shadows on a typical VTK pipeline (wavelet contour, glyphs, unlit
# outline, cube axes, scalar bar, text, volume, composite data, floor), with
# every registered technique (tests/python/test_enable_shadows.py).
add_test(NAME python.enable_shadows
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_enable_shadows.py
          ${PROJECT_SOURCE_DIR})
set_tests_properties(python.enable_shadows PROPERTIES LABELS "render" TIMEOUT 900)

# The key and fill light enable_shadows adds follow the camera in every
# technique with LightFollowCamera off (vedo's setting) as with it on; the
# application's own lights stay where VTK leaves them.
add_test(NAME python.enable_follow_camera
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_enable_follow_camera.py)
set_tests_properties(python.enable_follow_camera PROPERTIES LABELS "render" TIMEOUT 120)

# enable_shadows decides about the key light at each frame from the lights
# the application has then: a light added after the call (vedo's show()) or
# after a frame counts, removing them brings the key light back.
add_test(NAME python.enable_light_changes
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_enable_light_changes.py)
set_tests_properties(python.enable_light_changes PROPERTIES LABELS "render" TIMEOUT 120)

# enable_shadows given a plotter, a window, a technique name, None...: a
# TypeError saying what to pass, nothing changed.
add_test(NAME python.enable_wrong_type
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_enable_wrong_type.py)
set_tests_properties(python.enable_wrong_type PROPERTIES TIMEOUT 60)

# enable_shadows on a renderer with passes or post-processing: SSAO kept on
# top, the renderer's FXAA, depth peeling and translucency as without a pass,
# a camera pass over standard steps drawn through, VTK's own shadow passes
# replaced and said, anything else refused naming it.
add_test(NAME python.enable_composes
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_enable_composes.py)
set_tests_properties(python.enable_composes PROPERTIES LABELS "render" TIMEOUT 120)

# planar on the flat parts of meshes that are not flat as a whole (a slab
# floor, a pedestal's top, a cylinder's cap) against raytrace; RECEIVER() = 0
# opts a mesh out.
add_test(NAME python.planar_flat_parts
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_planar_flat_parts.py)
set_tests_properties(python.planar_flat_parts PROPERTIES LABELS "render" TIMEOUT 120)

# Translucent surfaces under each technique (issue 31, docs/translucency.md):
# partial shadows with the core's transmittance (a sphere of opacity 0.5
# leaves 0.25 under it, opacity 1 gives 0, opacity 0 gives 1, a slab of 0.4
# 0.36, shells of 0.5 around 0.2 0.16, each within 0.03), and a translucent
# plate receiving an opaque sphere's shadow on its own fragments (with
# blending and with depth peeling). `vtk` (VTK's own pass) draws no
# translucent shadow.
# Techniques with one value per light draw a filter's colour grey (--grey:
# they say so per light, GetLightNote).
set(_translucent_raytrace "")
set(_translucent_auto "")
set(_translucent_csm --grey)
set(_translucent_planar --grey)
set(_translucent_volume --grey)
set(_translucent_vtk --expect-none)
foreach(_translucent raytrace csm planar volume auto vtk)
  add_test(NAME python.translucent.${_translucent}
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY}
            ${CMAKE_CURRENT_SOURCE_DIR}/python/test_translucent_casters.py ${_translucent}
            ${_translucent_${_translucent}})
  set_tests_properties(python.translucent.${_translucent} PROPERTIES LABELS "render" TIMEOUT 120)
endforeach()

# csm's partial shadows of translucent actors through its transmittance maps:
# the same scene and expectations as raytrace's, with the default settings,
# the screen resolve, PCF and Poisson.
add_test(NAME python.translucent_csm
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_translucent_csm.py)
set_tests_properties(python.translucent_csm PROPERTIES LABELS "render" TIMEOUT 120)

# raytrace's shadows of points drawn as spheres (size 18) and lines drawn as
# tubes (width 16) (issue 32): Embree spheres and round curves of half the
# pixel width at their depth cast 0.6-1.6x the shadow area of world-sized
# meshes of that radius (1.008, 1.041, parallel 1.009; 0 before); none and
# NO_CAST cast nothing; a zoom after the first frame resizes them.
add_test(NAME python.impostor_casters
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_impostor_casters.py)
set_tests_properties(python.impostor_casters PROPERTIES LABELS "render" TIMEOUT 180)
# A bond's tube ends inside its atom's sphere: raytrace lands each pixel on
# the front-most solid near VTK's impostor depth, so no atom pixel is dark
# under a light straight down the bond (0 of 2366; 154 when landing on the
# tube inside the sphere), and the bond's shadow under a tilted light stays.
add_test(NAME python.impostor_joints
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_impostor_joints.py)
set_tests_properties(python.impostor_joints PROPERTIES LABELS "render" TIMEOUT 60)
# vtkPointGaussianMapper's splats cast spheres of their world radius, plain
# points and lines wider than a pixel the camera-facing squares and bands
# VTK draws (issue 32; docs/enable-shadows.md, "Points, lines and splats"),
# against sphere meshes and quads drawn by the same technique (0.995-1.007);
# 1-pixel points and lines and surface edges cast nothing.
add_test(NAME python.splat_flat_casters
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY}
          ${CMAKE_CURRENT_SOURCE_DIR}/python/test_splat_flat_casters.py)
set_tests_properties(python.splat_flat_casters PROPERTIES LABELS "render" TIMEOUT 180)
# The other techniques cast closed triangle proxies of spheres and tubes at
# that radius (vtkShadowImpostorProxies; docs/enable-shadows.md, "Points as
# spheres, lines as tubes"), against the same controls drawn by the same
# technique: 1.003-1.006 for the points, 1.033-1.038 for the tube (0 px
# before), and the quads and splat spheres above.
foreach(_impostors csm auto volume planar)
  foreach(_script impostor_casters splat_flat_casters)
    add_test(NAME python.${_script}.${_impostors}
      COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY}
              ${CMAKE_CURRENT_SOURCE_DIR}/python/test_${_script}.py ${_impostors})
    set_tests_properties(python.${_script}.${_impostors} PROPERTIES LABELS "render"
      TIMEOUT 180)
  endforeach()
endforeach()

# planar's four transmittance channels go to the pairs a translucent caster
# can shadow: the floor keeps its partial shadow behind five other receivers.
add_test(NAME python.translucent_planar
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_translucent_planar.py)
set_tests_properties(python.translucent_planar PROPERTIES LABELS "render" TIMEOUT 120)

# raytrace's shadows of vtkVolumes (issue 32): the light through a volume is
# its scalar opacity's transmittance with VTK's opacity correction,
# (1 - a)^(ds / u) per step: a constant 20^3 box reads 0.94^19 = 0.309 and
# 0.94^9.5 = 0.556 under it (within 0.03), also placed by its matrix; a box
# opaque in its top 6 layers reads the integral's 0.294, one under a
# translucent slab 0.25 x 0.556; opacity 0,
# VisibilityOff and none read 1; cell scalars are skipped with the reason in
# the stats; a still frame does not trace and a changed opacity function does.
add_test(NAME python.volume_casters
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_volume_casters.py)
set_tests_properties(python.volume_casters PROPERTIES LABELS "render" TIMEOUT 180)

# A shaded vtkVolume receives opaque surfaces' shadows (vtkShadowVolumeReceiver)
# under raytrace, csm, volume and auto: the half under an opaque slab keeps
# 0.9 / 1.95 = 0.4615 of its summed RGB (only ambient left), directional and
# point light; the other half, a volume with nothing above it and an unshaded
# volume equal `none`; a camera orbit computes no new map, moving the slab one.
add_test(NAME python.volume_receivers
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_volume_receivers.py)
set_tests_properties(python.volume_receivers PROPERTIES LABELS "render" TIMEOUT 180)

# vedo: enable_shadows before show(), after it, or after another technique
# gives the same frame, with the shadow, for every technique (needs
# python3-vedo, which scripts/install-deps.sh installs).
add_test(NAME python.vedo_placement
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_vedo_placement.py)
set_tests_properties(python.vedo_placement PROPERTIES LABELS "render" TIMEOUT 300)

# planar with a vtkLODActor floor: the mapper draws its inner Device actor,
# which shares the floor's property keys (ParaView's actors do the same).
add_test(NAME python.lod_receiver
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_lod_receiver.py)
set_tests_properties(python.lod_receiver PROPERTIES LABELS "render" TIMEOUT 120)

# Parts of vtkAssembly / vtkPropAssembly (nested, moved, NO_CAST on the
# assembly, a floor inside one) cast and receive as the same plain actors at
# the composed matrices, with every registered technique.
add_test(NAME python.assembly_casters
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_assembly_casters.py)
set_tests_properties(python.assembly_casters PROPERTIES LABELS "render" TIMEOUT 120)

# Meshes from live pipelines whose mappers bind buffer textures (cell
# normals, flat shading, cell colours): volume and auto against raytrace, csm
# screen against forward; a wireframe caster is one auto keeps volume from.
add_test(NAME python.volume_live_pipeline
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_volume_live_pipeline.py)
set_tests_properties(python.volume_live_pipeline PROPERTIES LABELS "render" TIMEOUT 120)

# auto's timed exact choice in a live pipeline through enable_shadows: it
# settles while the camera orbits, times again SETTLE still frames after an
# edit of the surface, and not while the surface changes every frame.
add_test(NAME python.auto_trial_edit
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_auto_trial_edit.py)
set_tests_properties(python.auto_trial_edit PROPERTIES LABELS "render" TIMEOUT 200)

# The caps of an open caster counted z-fail take its mapper's
# coincident-topology offset (vedo's): red without it, 100 % of the pixels.
add_test(NAME python.volume_coincident_offset
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_volume_coincident_offset.py)
set_tests_properties(python.volume_coincident_offset PROPERTIES LABELS "render" TIMEOUT 120)
add_test(NAME python.volume_edges_offset
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_volume_coincident_offset.py --edges)
set_tests_properties(python.volume_edges_offset PROPERTIES LABELS "render" TIMEOUT 120)
add_test(NAME python.volume_edges_tilt
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/python/test_volume_coincident_offset.py --edges --tetra)
set_tests_properties(python.volume_edges_tilt PROPERTIES LABELS "render" TIMEOUT 120)

# C API from a .c file.
add_executable(test_capi capi/test_capi.c)
target_link_libraries(test_capi PRIVATE vtkshadow::vtkshadow)
vtk_module_autoinit(TARGETS test_capi MODULES VTK::RenderingOpenGL2)
add_test(NAME capi.c
  COMMAND ${VTKSHADOW_GL} $<TARGET_FILE:test_capi> ${PROJECT_SOURCE_DIR}/scenes/basic/sphere-plane.json
          ${VTKSHADOW_TEST_OUT}/capi)

# Install tree + find_package(vtkshadow) from a downstream C project.
add_test(NAME install.downstream
  COMMAND ${VTKSHADOW_GL} ${CMAKE_CURRENT_SOURCE_DIR}/downstream/run.sh ${CMAKE_BINARY_DIR}
          ${CMAKE_CURRENT_SOURCE_DIR}/downstream ${PROJECT_SOURCE_DIR}/scenes/basic/sphere-plane.json)

# The .debs of `cpack -G DEB` (cmake/vtkshadowCPack.cmake): contents, dpkg -i,
# then Debian's /usr/bin/python3 with no wrapper renders a shadow with csm
# and none with "none", and pvpython/pvbatch load the plugin by name. Needs
# root; leaves the packages installed. The build tree's tests still use the
# build tree: vtkshadow-python puts it first on PYTHONPATH, ahead of
# /usr/lib/python3/dist-packages, and the plugin wrappers' PV_PLUGIN_PATH
# loads the build's VTKShadow.so (the installed one is only registered).
set(vtkshadow_install_pv "")
if(VTKSHADOW_PARAVIEW)
  set(vtkshadow_install_pv ${VTKSHADOW_PVPYTHON} ${VTKSHADOW_PVBATCH})
endif()
add_test(NAME install.package
  COMMAND ${VTKSHADOW_GL} ${CMAKE_CURRENT_SOURCE_DIR}/install/run.sh ${CMAKE_BINARY_DIR}
          ${PROJECT_SOURCE_DIR} ${vtkshadow_install_pv})
# Not at the same time as install.downstream: both run `cmake --install`-
# style rules of the same build tree.
set_tests_properties(install.package PROPERTIES LABELS "install" TIMEOUT 180
  RUN_SERIAL ON FIXTURES_SETUP installed_package)

# vtkshadow-render: every bad input gives exit status 2, a message naming the
# file, field and value, and no output file.
add_test(NAME cli.bad_input
  COMMAND ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/cli/test_bad_input.py
          --bin ${VTKSHADOW_BIN} --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/cli)
# --list-techniques prints the registry, name and description per line.
add_test(NAME cli.list_techniques
  COMMAND ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/cli/test_list_techniques.py
          --bin ${VTKSHADOW_BIN})
# ... and a good scene writes image, visibility, mask and stats.
add_test(NAME cli.outputs
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/cli/test_outputs.py
          --bin ${VTKSHADOW_BIN} --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/outputs)
# --stats and vtkshadow-bench time techniques interleaved in one window: the
# structure of their output, none against itself, no state leaked (never a speed).
add_test(NAME cli.timing
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/cli/test_timing.py
          --bin ${VTKSHADOW_BIN} --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/timing)
set_tests_properties(cli.timing PROPERTIES LABELS "render" TIMEOUT 1800)
# bench/bench_growth.py on a tiny configuration: rows, the noise-floor
# column, finite numbers, bad options (never a speed).
add_test(NAME cli.bench_growth
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/cli/test_bench_growth.py
          --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/bench_growth)
set_tests_properties(cli.bench_growth PROPERTIES LABELS "render" TIMEOUT 1800)
# bench/bench_soft.py on one soft scene at a tiny size against POV-Ray:
# rows, penumbra figures that fall with samples, the front, bad options.
add_test(NAME cli.bench_soft
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/cli/test_bench_soft.py
          --source ${PROJECT_SOURCE_DIR} --out ${VTKSHADOW_TEST_OUT}/bench_soft)
set_tests_properties(cli.bench_soft PROPERTIES LABELS "render" TIMEOUT 1800)
# bench/rotation_study.py (no GL) on a small grid: its table, the
# finding that a per-pixel turn leaves pen_mae where it was, bad options.
add_test(NAME cli.rotation_study
  COMMAND ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/cli/test_rotation_study.py
          --source ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.rotation_study PROPERTIES TIMEOUT 600)

# Visibility against the exact answer by ray casting (tests/render/).
function(vtkshadow_visibility_test name)
  add_test(NAME render.${name}
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_visibility.py
            --bin ${VTKSHADOW_BIN} --out ${VTKSHADOW_TEST_OUT}/render ${ARGN})
  set_tests_properties(render.${name} PROPERTIES LABELS "render")
endfunction()
include(${CMAKE_CURRENT_SOURCE_DIR}/render/visibility_tests.cmake)

# The C libraries once more with AddressSanitizer and UBSan, unit tests run there.
add_test(NAME sanitize.unit
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sanitize/run.sh ${PROJECT_SOURCE_DIR}
          ${CMAKE_BINARY_DIR}/sanitize)
set_tests_properties(sanitize.unit PROPERTIES TIMEOUT 1200 LABELS "sanitize")
# ... and what the C API, CLI and a few render and harness tests run (VTK
# module, C API, tools) with ASan and UBSan in build-asan, those tests there
# (tests/sanitize/run.sh lists both; Mesa's and VTK's exit-time leaks are
# suppressed in tests/sanitize/lsan.supp).
add_test(NAME sanitize.product
  COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/sanitize/run.sh ${PROJECT_SOURCE_DIR}
          ${CMAKE_BINARY_DIR}/build-asan product)
set_tests_properties(sanitize.product PROPERTIES TIMEOUT 3600 LABELS "sanitize")
include(${CMAKE_CURRENT_SOURCE_DIR}/render/planar_tests.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/render/volume_tests.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/render/robust_tests.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/render/csm_tests.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/render/csm_extra_tests.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/render/raytrace_tests.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/harness/harness_tests.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/render/depth_range_tests.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/render/display_soak_tests.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/corpus/corpus_tests.cmake)
include(${CMAKE_CURRENT_SOURCE_DIR}/paraview/paraview_tests.cmake)

# Planar mirrors (vtkPlanarReflectionPass): mirrored silhouettes against ray
# casting in the test, and colour against POV-Ray per light type
# (tests/render/test_reflection.py).
foreach(case basic grazing wide offset-1e6 below two-mirrors below-lit self-directional self-point
             self-spot)
  add_test(NAME render.reflection_${case}
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_reflection.py
            --bin ${VTKSHADOW_BIN} --out ${VTKSHADOW_TEST_OUT}/reflection --case ${case})
  set_tests_properties(render.reflection_${case} PROPERTIES LABELS "render")
endforeach()
foreach(case pov-directional pov-point pov-spot pov-wall-directional pov-wall-point pov-below pov-wall-mirror pov-two-mirrors)
  add_test(NAME harness.reflection_${case}
    COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_reflection.py
            --bin ${VTKSHADOW_BIN} --out ${VTKSHADOW_TEST_OUT}/reflection --case ${case})
  set_tests_properties(harness.reflection_${case} PROPERTIES LABELS "harness")
endforeach()

# csm's maps under a mirror on still frames (tests/render/test_reflection_bakes.py).
add_test(NAME render.reflection_csm_bakes
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_reflection_bakes.py
          ${CMAKE_SOURCE_DIR})
set_tests_properties(render.reflection_csm_bakes PROPERTIES LABELS "render")
# raytrace's still frames under a mirror: nothing traced in either world.
add_test(NAME render.reflection_raytrace_traces
  COMMAND ${VTKSHADOW_GL} ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/render/test_reflection_bakes.py
          ${CMAKE_SOURCE_DIR} raytrace)
set_tests_properties(render.reflection_raytrace_traces PROPERTIES LABELS "render")

# Every test of this directory may use the shared X server: added to the
# fixtures a test requires already (harness.thresholds requires the library
# runs too), not in their place.
get_property(vtkshadow_vtk_tests DIRECTORY PROPERTY TESTS)
foreach(test IN LISTS vtkshadow_vtk_tests)
  if(NOT test MATCHES "^xvfb\\.")
    get_property(fixtures TEST ${test} PROPERTY FIXTURES_REQUIRED)
    list(APPEND fixtures xvfb)
    list(REMOVE_DUPLICATES fixtures)
    set_tests_properties(${test} PROPERTIES FIXTURES_REQUIRED "${fixtures}")
  endif()
endforeach()

# Mesh loading under mutation: checker + VTK reader + decoded-cells check, never
# a crash (tests/mesh; the seeds are VSH_MESH_SEEDS from tests/mesh/CMakeLists.txt).
add_executable(test_mesh_read_fuzz mesh/test_mesh_read_fuzz.cxx)
target_link_libraries(test_mesh_read_fuzz PRIVATE vtkshadow::vtkshadow)
target_include_directories(test_mesh_read_fuzz PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/mesh
  ${CMAKE_CURRENT_SOURCE_DIR})
file(MAKE_DIRECTORY "${VTKSHADOW_TEST_OUT}/mesh-read-fuzz")
add_test(NAME mesh.read_fuzz
  COMMAND test_mesh_read_fuzz ${VTKSHADOW_TEST_OUT}/mesh-read-fuzz ${VSH_MESH_SEEDS})
# 1000 mutations per seed: about 90 s on a busy 2-core machine;
# VSH_FUZZ_ITERATIONS=5000 by hand for a longer run.
set_tests_properties(mesh.read_fuzz PROPERTIES LABELS "unit" TIMEOUT 900
  ENVIRONMENT VSH_FUZZ_ITERATIONS=1000)


# The settings tables (vtkShadowSettings.h): what --list-settings prints is
# what SetOption takes (ends, just outside, NaN, integers; no unlisted key
# taken), the docs' tables are the listing (scripts/settings-table.py), and
# the ParaView view's properties use their settings' ranges and defaults.
add_test(NAME cli.settings
  COMMAND ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/cli/test_settings.py --bin ${VTKSHADOW_BIN})
add_test(NAME docs.settings_table
  COMMAND ${VTKSHADOW_PY} ${PROJECT_SOURCE_DIR}/scripts/settings-table.py --check
          ${VTKSHADOW_BIN}/vtkshadow-render ${PROJECT_SOURCE_DIR}/docs/techniques.md)
add_test(NAME paraview.settings
  COMMAND ${VTKSHADOW_PY} ${CMAKE_CURRENT_SOURCE_DIR}/paraview/test_pv_settings.py
          --bin ${VTKSHADOW_BIN} --xml ${PROJECT_SOURCE_DIR}/paraview/Views/RenderViewWithShadows.xml)
set_tests_properties(cli.settings docs.settings_table paraview.settings PROPERTIES LABELS "unit")
