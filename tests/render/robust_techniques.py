"""What the robustness suite (test_robust.py) expects of each shadow
technique, as data.

Every technique of the registry (vtkShadowTechnique.GetKnownTechniques()) runs
every case of the suite. The generic checks hold for any technique; what differs
between techniques is written here, one Profile per technique name:

  casts         the technique draws shadows at all (False: "none"; then every
                case checks that no pixel is shadowed instead of >= MIN_SHADOWED)
  exact_model   the shadows it promises on a sphere-plane scene, as an
                exact_scene.trace_scene model: "all" (every caster on every
                surface), "planar" (only on receiver planes), "none"
  exact_bound   (lo, hi): wrong_pct against that exact answer must lie in
                [lo, hi] (vtkshadow-metrics --band 1 with test_planar's exclude
                band). A known-bad technique gets its known range, so that a
                change of its error is seen too.
  agreement     percent of pixels on which a variant set-up (composite mapper,
                viewports, ...) must agree with its plain reference
  stats         pass -> {name: number} after a frame (technique counters)
  same_stats    {kind: stats}: stats that must be equal for a variant and its
                reference of that kind (the same geometry: composite vs plain
                actors, glyph mapper vs filter)
  expect        {kind: {stat: value}}: stats a case's render of that kind must
                show (kinds: composite, composite hidden, glyph, translucent
                box, translucent receiver, lighting-off caster, lighting-off
                receiver, viewport, headlight on)
  work          pass -> cumulative count of rebuilt GPU data (caster geometry,
                shadow maps): the caching case reads it; None: not observable
  caching       {event: "some" | int}: how `work` must change on each event of
                the caching case (first frame, still frames, a caster moved,
                casters' data changed, light moved, camera orbit); an event
                not listed is not checked
  headlight_on  pass -> None: make the headlight cast (None: the technique has
                no such option; then only "the headlight casts nothing" is checked)
  settings      [(label, {SetOption key: value}, probe or None)]: configurations
                run against the exact answer in the "settings" case; probe(c,
                pass, stats, extra) adds the technique's own checks
  special       {label: function(c, ctx)}: technique-only checks of the
                "settings" case (planar's explicit receiver plane)
  translucent_casts  None: translucent actors cast nothing (the translucent
                case wants the floor outside the box unchanged); a number:
                the visibility the opacity-0.4 box's partial shadow must have
                where it falls alone (two crossings: 0.36, docs/translucency.md)
  known         {(case, start of a check's message): why}: known failures of
                the technique. Such a check must still FAIL (printed "xfail");
                when it passes the test fails, so the entry goes once the
                defect is fixed.

A technique added to the registry without a Profile runs with DEFAULT (casts
on every surface, wrong_pct <= 0.5, no counters): so it is checked by being
registered, and a technique that promises less says so by adding its Profile.
"""
from dataclasses import dataclass, field
from typing import Callable, Optional

import vtkshadow


@dataclass
class Profile:
    casts: bool = True
    exact_model: str = "all"
    exact_bound: tuple = (0.0, 0.5)
    agreement: float = 99.9
    stats: Callable = lambda p: {}
    same_stats: dict = field(default_factory=dict)
    expect: dict = field(default_factory=dict)
    work: Optional[Callable] = None
    caching: dict = field(default_factory=dict)
    headlight_on: Optional[Callable] = None
    settings: list = field(default_factory=list)
    special: dict = field(default_factory=dict)
    known: dict = field(default_factory=dict)
    translucent_casts: Optional[float] = None


def new_pass(technique, options=None):
    """The technique's pass pipeline, as vtkShadowTechnique::Install() sets
    it, with SetOption(key, value) applied first."""
    t = vtkshadow.vtkShadowTechnique()
    t.SetName(technique)
    for key, value in (options or {}).items():
        if not t.SetOption(key, value):
            raise ValueError(f"technique {technique}: SetOption({key}, {value}) refused")
    p = t.CreatePass()
    if p is None:
        raise ValueError(f"technique {technique}: CreatePass() gave nothing")
    # CreatePass() hands its reference to the caller and the wrapper took one
    # more: give ours back so the pass dies with its last Python reference.
    if p.GetReferenceCount() > 1:
        p.UnRegister(None)
    return p


# ---------------------------------------------------------------------------
# Counters of the passes
def planar_stats(p):
    return {"pairs": p.GetNumberOfShadowPairs(), "triangles": p.GetNumberOfMaskTriangles(),
            "builds": p.GetNumberOfGeometryBuilds()}


def csm_stats(p):
    n = p.GetNumberOfCascades(0)
    return {"cascades": n, "used": p.GetUsedResolution(), "maps": p.GetNumberOfMapsRendered(),
            "reused": p.GetNumberOfMapsReused(), "total": p.GetTotalMapsRendered(),
            "bytes": p.GetMemoryBytes(), "far": [p.GetCascadeFar(0, k) for k in range(n)],
            "texel_px": [p.GetCascadeTexelPixels(0, k) for k in range(n)]}


def auto_stats(p):
    out = {"choice": p.GetChoice()}
    out.update({"planar_" + k: v for k, v in planar_stats(p.GetPlanarPass()).items()})
    out.update({"csm_" + k: v for k, v in csm_stats(p.GetCascadedPass()).items()
                if k in ("cascades", "maps", "reused", "total")})
    return out


def raytrace_stats(p):
    return {"builds": p.GetNumberOfMeshBuilds(), "commits": p.GetNumberOfTopLevelCommits(),
            "rays": p.GetNumberOfRaysTraced(), "triangles": p.GetNumberOfCasterTriangles()}


# ---------------------------------------------------------------------------
# csm's own settings and what each must show (from the former
# test_csm_robust.py: filters, splits, stable, cascade-count, max-texel,
# big-map, debug-cascades)
SPLIT_FRACTIONS = (0.1, 0.3, 0.6)


def probe_cascades(count):
    def probe(c, p, st, extra):
        c.check(st["cascades"] == count, f"GetNumberOfCascades(0) {st['cascades']} (want {count})")
    return probe


def probe_explicit(c, p, st, extra):
    ex = st["far"]
    ok, near = False, None
    if len(ex) == 4:
        far = ex[3]
        # Split i ends at near + fraction_i (far - near); near from split 0.
        near = (ex[0] - SPLIT_FRACTIONS[0] * far) / (1.0 - SPLIT_FRACTIONS[0])
        want = [near + f * (far - near) for f in SPLIT_FRACTIONS]
        ok = all(abs(a - b) <= 1e-6 * far for a, b in zip(ex[1:3], want[1:]))
    c.check(ok, f"EXPLICIT far depths {[round(x, 4) for x in ex]} follow the fractions "
                f"{SPLIT_FRACTIONS} of the visible range (near {near})")
    fars = extra.setdefault("split_fars", {})
    fars["EXPLICIT"] = tuple(round(x, 6) for x in ex)


def probe_split(name):
    def probe(c, p, st, extra):
        fars = extra.setdefault("split_fars", {})
        fars[name] = tuple(round(x, 6) for x in st["far"])
        if len(fars) == 4:
            c.check(len(set(fars.values())) == 4, "the four split schemes give four different "
                                                  "split sets")
    return probe


def probe_max_texel(c, p, st, extra):
    worst = max(st["texel_px"]) if st["texel_px"] else float("inf")
    c.check(worst <= 1.5, f"GetCascadeTexelPixels per cascade {[round(t, 3) for t in st['texel_px']]}"
                          f" (max {worst:.3f}, need <= 1.5): {st['cascades']} cascades at "
                          f"{st['used']}^2, atlas {st['bytes'] / 2**20:.0f} MiB (budget 256 MiB)")


def probe_big_map(c, p, st, extra):
    text = extra.get("messages", "")
    c.check(1024 <= st["used"] < 16384,
            f"GetUsedResolution() {st['used']} (< 16384), atlas {st['bytes'] / 2**20:.0f} MiB, "
            f"{st['cascades']} cascades")
    c.check("GL limit" in text or "exceeds" in text,
            "a warning about the GL limit: " + (text.strip().splitlines()[0][:160]
                                                if text.strip() else "none"))


def csm_settings():
    split = {"cascades": 4, "split_fraction_0": SPLIT_FRACTIONS[0],
             "split_fraction_1": SPLIT_FRACTIONS[1], "split_fraction_2": SPLIT_FRACTIONS[2]}
    out = [("filter HARDWARE_2X2", {"filter": 0}, None),
           ("filter PCF 3", {"filter": 1, "pcf_size": 3}, None),
           ("filter PCF 5", {"filter": 1, "pcf_size": 5}, None),
           ("filter POISSON", {"filter": 2}, None)]
    for k, name in enumerate(("UNIFORM", "LOGARITHMIC", "PRACTICAL", "EXPLICIT")):
        out.append((f"split {name}", dict(split, split=k),
                    probe_explicit if name == "EXPLICIT" else probe_split(name)))
    out += [("Stable on", {"stable": 1}, None), ("Stable off", {"stable": 0}, None)]
    out += [(f"CascadeCount {k}", {"cascades": k}, probe_cascades(k)) for k in (1, 2, 3, 4)]
    out += [("MaxTexelPixels 1.5", {"max_texel_px": 1.5}, probe_max_texel),
            ("MapResolution 16384, 4 cascades", {"map_resolution": 16384, "cascades": 4},
             probe_big_map)]
    return out


def csm_work(p):
    return p.GetTotalMapsRendered()


def auto_work(p):
    """The work of every pass auto may pick: planar's geometry, csm's maps,
    volume's volumes and raytrace's meshes."""
    return (p.GetPlanarPass().GetNumberOfGeometryBuilds() +
            p.GetCascadedPass().GetTotalMapsRendered() +
            p.GetVolumePass().GetNumberOfVolumeBuilds() +
            p.GetRayTracedPass().GetNumberOfMeshBuilds())


# ---------------------------------------------------------------------------
# The special checks (need the suite's render helpers: passed in as ctx)
def planar_explicit_plane(c, ctx):
    """The floor given with AddReceiverPlane (not marked) vs the RECEIVER key."""
    ctx.explicit_plane(c)


def csm_debug_cascades(c, ctx):
    ctx.debug_cascades(c)


PROFILES = {
    # VTK's standard passes: no shadow anywhere.
    "none": Profile(casts=False, exact_model="none", exact_bound=(0.0, 0.0), agreement=99.95,
                    settings=[("map_resolution 1024 (ignored)", {"map_resolution": 1024}, None)]),
    # VTK 9.1's own shadow maps: fitted to all props, wrong on non-square
    # windows (render.vtk.4x3 expects 7..12 % on its scene); the range is
    # its known error here, so that a change shows.
    # Its map is fitted to all props' bounds, so a set-up whose bounds differ
    # (a glyph mapper's bounds vs the filter output's) moves the texel grid:
    # shadow edges agree to 99.5 %.
    "vtk": Profile(exact_bound=(1.0, 15.0), agreement=99.5, settings=[
        ("map_resolution 1024", {"map_resolution": 1024}, None),
        ("map_resolution 4096", {"map_resolution": 4096}, None)],
        known={
            ("translucent", "the translucent box renders"):
                "the 'vtk' pipeline (VTK's TestShadowMapPass assembly) draws opaque "
                "geometry only: translucent actors are not drawn",
            ("translucent", "translucent receiver renders"): "as above: not drawn",
            ("resize", "resized 640x480 -> 800x450 vs a fresh 800x450 render: visibility agrees"):
                "VTK 9.1's shadow map after a window resize differs from a fresh window's "
                "(92.5 % agreement)",
            ("caching", "frame after changing 2 casters' data vs a fresh render: visibility agrees"):
                "VTK 9.1's pass after casters' data change differs from a fresh render "
                "(98.7 % agreement)"}),
    # Exact shadows on receiver planes only.
    "planar": Profile(
        exact_model="planar", exact_bound=(0.0, 0.05), agreement=99.95, stats=planar_stats,
        same_stats={"composite": ("triangles",), "composite hidden": ("triangles",),
                    "glyph": ("triangles",), "lighting-off caster": ("triangles",)},
        expect={"composite": {"pairs": 1}, "translucent box": {"pairs": 1},
                # The translucent glass marked receiver receives: a pair of its own.
                "translucent receiver": {"pairs": 2}, "lighting-off caster": {"pairs": 1},
                "lighting-off receiver": {"pairs": 2}, "viewport": {"pairs": 1},
                "headlight on": {"pairs": 1}},
        work=lambda p: p.GetNumberOfGeometryBuilds(),
        caching={"first": 3, "still": 0, "data": 2, "light": 0, "orbit": 0},
        headlight_on=lambda p: p.SetCastHeadlightShadows(True),
        special={"explicit-plane": planar_explicit_plane},
        translucent_casts=0.36),
    "csm": Profile(
        stats=csm_stats, expect={"viewport": {"cascades": ">=1"}},
        work=csm_work, caching={"first": "some", "still": 0, "moved": "some", "data": "some", "light": "some",
                                "orbit": "some", "small orbit reuses": True},
        headlight_on=lambda p: p.SetCastHeadlightShadows(True),
        settings=csm_settings(), special={"debug-cascades": csm_debug_cascades},
        translucent_casts=0.36),
    # Per light planar, csm, volume, raytrace or nothing, by an error
    # target. Its choice may
    # differ between a set-up and its equivalent plain scene (it depends on how
    # the actors are split): planar and csm then differ on shadow-edge pixels.
    "auto": Profile(
        stats=auto_stats, work=auto_work, agreement=99.5,
        caching={"first": "some", "still": 0, "data": "some"},
        settings=[("max_error 0.2", {"max_error": 0.2}, None),
                  ("max_texel_px 1.5", {"max_texel_px": 1.5}, None)],
        # This scene's light goes to planar, which casts translucent actors.
        translucent_casts=0.36),
    # Stencil shadow volumes: exact on every surface; a volume is rebuilt only
    # when the light moves relative to its caster or the mesh changes, never
    # for the camera. The caching case translates a caster under a
    # directional light: the light in the caster's coordinates is unchanged,
    # so its volume is kept ("moved": 0).
    "volume": Profile(
        exact_bound=(0.0, 0.05), agreement=99.95,
        stats=lambda p: {"builds": p.GetNumberOfVolumeBuilds()},
        work=lambda p: p.GetNumberOfVolumeBuilds(),
        caching={"first": "some", "still": 0, "moved": 0, "data": "some",
                 "light": "some", "orbit": 0},
        headlight_on=lambda p: p.SetCastHeadlightShadows(True),
        settings=[("force_zfail 1", {"force_zfail": 1}, None),
                  ("depth_bias 16, slope_bias 0.01", {"depth_bias": 16, "slope_bias": 0.01},
                   None),
                  ("soft_samples 64 with point-sized lights (hard)", {"soft_samples": 64}, None)],
        translucent_casts=0.36),
    # Exact shadows of every caster on every surface, by Embree rays. work =
    # meshes (re)built: moving a caster, the light or the camera rebuilds
    # none (the top level is re-committed), changing 2 casters' data rebuilds
    # exactly their 2 meshes.
    "raytrace": Profile(
        exact_bound=(0.0, 0.05), stats=raytrace_stats,
        same_stats={"composite": ("triangles",), "composite hidden": ("triangles",),
                    "glyph": ("triangles",)},
        work=lambda p: p.GetNumberOfMeshBuilds(),
        caching={"first": "some", "still": 0, "moved": 0, "data": 2, "light": 0, "orbit": 0},
        headlight_on=lambda p: p.SetCastHeadlightShadows(True),
        settings=[("samples 4 with a point-sized light (hard)", {"samples": 4}, None),
                  ("threads 1", {"threads": 1}, None)],
        translucent_casts=0.36),
}
DEFAULT = Profile()


def profile(technique):
    return PROFILES.get(technique, DEFAULT)


def expect_value(want, got):
    """want: a number (equal), '>=N', or 'some' (> 0)."""
    if isinstance(want, str) and want.startswith(">="):
        return got >= float(want[2:])
    if want == "some":
        return got > 0
    return got == want

