"""Accept/reject of vtkShadowTechnique.SetOption for every technique, a
fixed list of keys (every key some pass took before the settings tables,
plus a few that no pass has) and a fixed list of values (the old ranges'
ends, just inside and outside them, halves, NaN, infinities). Prints one
line per technique, key and value: "technique key value 1|0". Run with
vtkshadow-python before and after a change to the settings and diff the
outputs (issue #30)."""
import math
import vtkshadow

KEYS = """cast_headlight residual_light map_resolution cascades ratio_per_cascade
split lambda split_fraction_0 split_fraction_3 split_fraction_6 split_fraction_7
split_fraction_ stable max_texel_px memory_budget bias_scale filter pcf_size
poisson_radius blend_band max_distance fade debug_cascades resolve tap_texel_px
tile_cull soft soft_samples adaptive pcss_blocker_taps pcss_filter_taps
pcss_max_texels detect_receivers plane_tolerance samples threads light_radius
light_angle depth_bias slope_bias force_zfail facing_test max_error
penumbra_target bogus""".split()
ENDS = [0, 1, 2, 3, 8, 9, 16, 64, 90, 100, 180, 255, 256, 1024, 16384, 0.5, 1.5,
        65536, 1e6, 1e12, 1e300]
VALUES = sorted({v for e in ENDS for v in (e, -e, e + 0.5, e - 0.5, e * (1 + 1e-9),
                                           e * (1 - 1e-9), e + 1e-9, e - 1e-9)})
VALUES += [math.nan, math.inf, -math.inf]

registry = vtkshadow.vtkShadowTechniqueRegistry
for i in range(registry.GetNumberOfTechniques()):
    name = registry.GetName(i)
    for key in KEYS:
        for value in VALUES:
            t = vtkshadow.vtkShadowTechnique()
            t.SetName(name)
            print(name, key, repr(value), int(bool(t.SetOption(key, value))))
