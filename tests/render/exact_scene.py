"""Exact per-light visibility of analytic scenes (spheres over parallelograms),
computed by ray casting one ray through the centre of each pixel, with the same
camera model as VTK, POV-Ray and Cycles (shared/notes/reference-renderers.md).

Used by the render tests: the renderer's triangles approximate the analytic
shapes, so the tests compare outside a one-pixel band along every exact edge.
"""
import numpy as np


def normalize(v):
    v = np.asarray(v, dtype=np.float64)
    return v / np.linalg.norm(v, axis=-1, keepdims=True)


def camera_rays(camera, width, height):
    """Unnormalized ray directions (H, W, 3) through pixel centres, row 0 at the top."""
    eye = np.asarray(camera["position"], float)
    f = normalize(np.asarray(camera["focal_point"], float) - eye)
    r = normalize(np.cross(f, camera["view_up"]))
    u = np.cross(r, f)
    t = np.tan(np.radians(camera["view_angle"]) / 2.0)
    a = width / height
    i = (np.arange(width) + 0.5) / width * 2.0 - 1.0
    j = 1.0 - (np.arange(height) + 0.5) / height * 2.0
    ii, jj = np.meshgrid(i, j)
    return eye, f + ii[..., None] * (t * a) * r + jj[..., None] * t * u


def hit_sphere(origin, dirs, center, radius):
    """Nearest positive ray parameter to the sphere, inf on a miss."""
    oc = origin - np.asarray(center, float)
    a = np.einsum("...k,...k", dirs, dirs)
    b = 2.0 * np.einsum("...k,...k", dirs, oc)
    c = np.einsum("...k,...k", oc, oc) - radius * radius
    disc = b * b - 4 * a * c
    sq = np.sqrt(np.maximum(disc, 0.0))
    t0 = (-b - sq) / (2 * a)
    t1 = (-b + sq) / (2 * a)
    eps = 1e-9 * max(1.0, float(np.max(np.abs(oc))))
    t = np.where(t0 > eps, t0, np.where(t1 > eps, t1, np.inf))
    return np.where(disc >= 0, t, np.inf)


def hit_parallelogram(origin, dirs, o, p1, p2):
    """Ray parameter to the parallelogram o + s(p1-o) + t(p2-o), inf on a miss."""
    o = np.asarray(o, float)
    e1 = np.asarray(p1, float) - o
    e2 = np.asarray(p2, float) - o
    n = np.cross(e1, e2)
    denom = np.einsum("...k,k", dirs, n)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.einsum("...k,k", o - origin, n) / denom
    hit = origin + t[..., None] * dirs
    rel = hit - o
    # Solve rel = s e1 + t e2 in the plane by least squares via the Gram matrix.
    g = np.array([[e1 @ e1, e1 @ e2], [e1 @ e2, e2 @ e2]])
    rhs = np.stack([rel @ e1, rel @ e2], axis=-1)
    st = rhs @ np.linalg.inv(g).T
    inside = (st[..., 0] >= 0) & (st[..., 0] <= 1) & (st[..., 1] >= 0) & (st[..., 1] <= 1)
    ok = np.isfinite(t) & (t > 1e-9) & inside & (np.abs(denom) > 1e-300)
    return np.where(ok, t, np.inf), normalize(n)


def render_exact(scene, light_index, width, height):
    """Returns (visibility, valid, object_id), each (H, W), row 0 at the top.

    The scene holds "sphere" and "plane" objects only (the test scenes)."""
    eye, dirs = camera_rays(scene["camera"], width, height)
    best = np.full((height, width), np.inf)
    obj = np.full((height, width), -1)
    normal = np.zeros((height, width, 3))
    for k, o in enumerate(scene["objects"]):
        if "sphere" in o:
            s = o["sphere"]
            t = hit_sphere(eye, dirs, s["center"], s["radius"])
            closer = t < best
            p = eye + t[..., None] * dirs
            n = normalize(np.where(closer[..., None], p - np.asarray(s["center"], float), 1.0))
        else:
            pl = o["plane"]
            t, n0 = hit_parallelogram(eye, dirs, pl["origin"], pl["point1"], pl["point2"])
            closer = t < best
            n = np.broadcast_to(n0, normal.shape)
        best = np.where(closer, t, best)
        obj = np.where(closer, k, obj)
        normal = np.where(closer[..., None], n, normal)
    hitmask = np.isfinite(best)
    p = eye + np.where(hitmask, best, 0.0)[..., None] * dirs
    # Two-sided lighting: the normal faces the camera, as VTK, POV-Ray, Cycles.
    facing = np.einsum("...k,...k", normal, dirs) > 0
    normal = np.where(facing[..., None], -normal, normal)

    light = scene["lights"][light_index]
    if light["type"] == "directional":
        to_light = np.broadcast_to(-normalize(light["direction"]), p.shape)
        light_dist = np.full(best.shape, np.inf)
    else:
        d = np.asarray(light["position"], float) - p
        light_dist = np.linalg.norm(d, axis=-1)
        to_light = d / light_dist[..., None]
    valid = hitmask & (np.einsum("...k,...k", normal, to_light) > 1e-6)
    if light["type"] == "spot":
        axis = normalize(np.asarray(light["focal_point"], float) - np.asarray(light["position"], float))
        cos_angle = np.einsum("...k,k", -to_light, axis)
        valid &= cos_angle > np.cos(np.radians(light["cone_angle"]))

    # Shadow rays from every hit point towards the light.
    blocked = np.zeros(best.shape, bool)
    offset = 1e-7 * max(1.0, float(np.max(np.abs(p))))
    origin = p + offset * to_light
    for k, o in enumerate(scene["objects"]):
        if "sphere" in o:
            s = o["sphere"]
            t = hit_sphere(origin, to_light, s["center"], s["radius"])
        else:
            pl = o["plane"]
            t, _ = hit_parallelogram(origin, to_light, pl["origin"], pl["point1"], pl["point2"])
        blocked |= (t < light_dist) & (obj != k)
    visibility = np.where(valid & ~blocked, 1.0, 0.0)
    return visibility, valid, obj


def edge_band(labels, radius=1):
    """Pixels within `radius` (Chebyshev) of a change of `labels`."""
    edge = np.zeros(labels.shape, bool)
    edge[:, 1:] |= labels[:, 1:] != labels[:, :-1]
    edge[:, :-1] |= labels[:, 1:] != labels[:, :-1]
    edge[1:, :] |= labels[1:, :] != labels[:-1, :]
    edge[:-1, :] |= labels[1:, :] != labels[:-1, :]
    band = edge.copy()
    for _ in range(radius - 1 if radius > 1 else 0):
        grown = band.copy()
        grown[1:, :] |= band[:-1, :]
        grown[:-1, :] |= band[1:, :]
        grown[:, 1:] |= band[:, :-1]
        grown[:, :-1] |= band[:, 1:]
        band = grown
    return band
