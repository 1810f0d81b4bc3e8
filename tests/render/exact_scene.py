"""Exact per-light visibility of analytic scenes, computed by ray casting one
ray through the centre of each pixel, with the same camera model as VTK, POV-Ray
and Cycles (shared/notes/reference-renderers.md).

Objects: sphere, plane (parallelogram) and box, each with the scene format's
optional row-major affine "transform" (docs/scene-format.md; a transformed
sphere is an ellipsoid), and meshes given as OBJ files ("v" and triangle "f"
lines; an absolute path) with flat faces: a mesh may shadow itself (it need
not be convex), and its face index is its triangle's. Cylinders are not
supported (ValueError).
Any number of lights; render_exact() answers for one of them.

Shadow models (render_exact(..., shadows=...)):
  "all"    every object whose "casts" is not false shadows every other object
           (scenes without "casts" keys: exactly the original behaviour);
  "planar" what projected planar shadows promise: only pixels on "receiver"
           planes are shadowed (by the other casting objects); every other
           surface gets v = 1 wherever it faces the light;
  "none"   no shadows (v = 1 on every valid pixel).

All arithmetic is float64 and camera-relative: the eye is subtracted from every
position (objects, lights) before anything else, so scenes translated far from
the origin or scaled to tiny sizes are computed as exactly as at the origin;
epsilons are relative to the hit distance, never absolute.

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


def _affine(o):
    """(linear 3x3, translation 3) of an object's row-major "transform"."""
    m = o.get("transform")
    if m is None:
        return np.eye(3), np.zeros(3)
    m = np.asarray(m, dtype=np.float64).reshape(4, 4)
    return m[:3, :3].copy(), m[:3, 3].copy()


def _primitive(o, eye):
    """An object in camera-relative coordinates: ("plane", origin, e1, e2),
    ("sphere", A, b, A^-1) for the unit sphere, ("box", A, b, A^-1) for the
    unit cube; world point = A local + b, with the eye subtracted in b."""
    lin, trans = _affine(o)
    shift = trans - eye  # exact enough: both are given numbers, subtracted once
    if "plane" in o:
        pl = o["plane"]
        org = np.asarray(pl["origin"], np.float64)
        e1 = np.asarray(pl["point1"], np.float64) - org
        e2 = np.asarray(pl["point2"], np.float64) - org
        return ("plane", lin @ org + shift, lin @ e1, lin @ e2)
    if "sphere" in o:
        s = o["sphere"]
        c = np.asarray(s["center"], np.float64)
        a = lin * float(s["radius"])
        return ("sphere", a, lin @ c + shift, np.linalg.inv(a))
    if "box" in o:
        b = o["box"]
        lo = np.asarray(b["min"], np.float64)
        hi = np.asarray(b["max"], np.float64)
        a = lin @ np.diag(hi - lo)
        return ("box", a, lin @ lo + shift, np.linalg.inv(a))
    if "mesh" in o:
        v, f = read_obj(o["mesh"])
        return ("mesh", (v @ lin.T + shift)[f])
    raise ValueError("exact_scene: only sphere, plane, box and OBJ mesh objects are supported "
                     f"(got {sorted(k for k in o if k in ('cylinder', 'mesh'))})")


def read_obj(path):
    """Vertices (N, 3) and triangles (T, 3) of a small OBJ file (v and f
    lines; f with 3 vertices, 1-based, optional /vt/vn parts)."""
    verts, faces = [], []
    with open(path) as fh:
        for line in fh:
            parts = line.split()
            if not parts:
                continue
            if parts[0] == "v":
                verts.append([float(x) for x in parts[1:4]])
            elif parts[0] == "f":
                idx = [int(x.split("/")[0]) - 1 for x in parts[1:]]
                for k in range(1, len(idx) - 1):
                    faces.append([idx[0], idx[k], idx[k + 1]])
    return np.asarray(verts, np.float64), np.asarray(faces, int)


def _intersect_mesh(tris, origin, dirs, shape):
    """Nearest t > 0 over the triangles (Moller-Trumbore), the flat normal
    and the triangle index."""
    best = np.full(shape[:-1], np.inf)
    normal = np.zeros(shape)
    face = np.zeros(shape[:-1], int)
    for k, (a, b, c) in enumerate(tris):
        e1, e2 = b - a, c - a
        h = np.cross(dirs, e2)
        det = np.einsum("...k,k", h, e1)
        with np.errstate(divide="ignore", invalid="ignore"):
            inv = 1.0 / det
            s = origin - a
            u = np.einsum("...k,...k", s, h) * inv
            q = np.cross(s, e1)
            v = np.einsum("...k,...k", dirs, q) * inv
            t = np.einsum("k,...k", e2, q) * inv
        ok = (det != 0) & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0) & (t < best)
        best = np.where(ok, t, best)
        n = normalize(np.cross(e1, e2))
        normal = np.where(ok[..., None], n, normal)
        face = np.where(ok, k, face)
    return best, normal, face


def _intersect(prim, origin, dirs):
    """Nearest t > 0 along origin + t dirs (inf on a miss), the world normal
    (unit, outward), and a face index (boxes: 0..5 as -x,+x,-y,+y,-z,+z)."""
    shape = np.broadcast_shapes(np.shape(origin), np.shape(dirs))
    origin = np.broadcast_to(origin, shape)
    dirs = np.broadcast_to(dirs, shape)
    kind = prim[0]
    face = np.zeros(shape[:-1], int)
    if kind == "mesh":
        return _intersect_mesh(prim[1], origin, dirs, shape)
    if kind == "plane":
        _, o, e1, e2 = prim
        n = np.cross(e1, e2)
        denom = np.einsum("...k,k", dirs, n)
        with np.errstate(divide="ignore", invalid="ignore"):
            t = np.einsum("...k,k", o - origin, n) / denom
            rel = origin + t[..., None] * dirs - o
            g = np.array([[e1 @ e1, e1 @ e2], [e1 @ e2, e2 @ e2]])
            st = np.stack([rel @ e1, rel @ e2], axis=-1) @ np.linalg.inv(g).T
            inside = np.all((st >= 0) & (st <= 1), axis=-1)
        ok = np.isfinite(t) & (t > 0) & inside & (denom != 0)
        t = np.where(ok, t, np.inf)
        return t, np.broadcast_to(normalize(n), shape), face
    _, a, b, ainv = prim
    ol = (origin - b) @ ainv.T
    dl = dirs @ ainv.T
    if kind == "sphere":
        qa = np.einsum("...k,...k", dl, dl)
        qb = np.einsum("...k,...k", ol, dl)
        qc = np.einsum("...k,...k", ol, ol) - 1.0
        disc = qb * qb - qa * qc
        sq = np.sqrt(np.maximum(disc, 0.0))
        # Stable roots: q = -(b + sign(b) sqrt(disc)), t = q / a and c / q.
        q = -(qb + np.where(qb >= 0, sq, -sq))
        with np.errstate(divide="ignore", invalid="ignore"):
            r1 = q / qa
            r2 = np.where(q != 0, qc / q, -r1)
        t0 = np.minimum(r1, r2)
        t1 = np.maximum(r1, r2)
        t = np.where(t0 > 0, t0, np.where(t1 > 0, t1, np.inf))
        t = np.where(disc >= 0, t, np.inf)
        nl = ol + np.where(np.isfinite(t), t, 0.0)[..., None] * dl
    else:  # box: slabs of the unit cube
        tiny = np.where(dl >= 0, 1e-300, -1e-300)
        dsafe = np.where(np.abs(dl) < 1e-300, tiny, dl)
        ta = (0.0 - ol) / dsafe
        tb = (1.0 - ol) / dsafe
        tmin = np.minimum(ta, tb)
        tmax = np.maximum(ta, tb)
        tnear = np.max(tmin, axis=-1)
        tfar = np.min(tmax, axis=-1)
        hit = (tnear <= tfar) & (tfar > 0)
        entering = tnear > 0
        t = np.where(hit, np.where(entering, tnear, tfar), np.inf)
        axis = np.where(entering, np.argmax(tmin, axis=-1), np.argmin(tmax, axis=-1))
        # Outward normal: -dir sign when entering, +dir sign when leaving.
        dsel = np.take_along_axis(dl, axis[..., None], axis=-1)[..., 0]
        sign = np.where(entering, -np.sign(dsel), np.sign(dsel))
        sign = np.where(sign == 0, 1.0, sign)
        nl = np.zeros(shape)
        np.put_along_axis(nl, axis[..., None], sign[..., None], axis=-1)
        face = 2 * axis + (sign > 0)
    # Normals transform by the inverse transpose (outward stays outward, also
    # for mirroring transforms).
    n = normalize(np.where(np.isfinite(t)[..., None], nl @ ainv, 1.0))
    return t, n, face


def trace_scene(scene, light_index, width, height, shadows="all"):
    """Everything the exact renderer knows, as a dict of (H, W) arrays, row 0
    at the top: "visibility", "valid", "object" (index, -1 background),
    "face" (box face 0..5, 0 otherwise), "distance" (eye to hit along the
    ray), "depth" (along the view direction), "receiver" (pixel on a receiver),
    "blocked" (the shadow ray hits a caster, under the chosen model) and
    "light_cos" (the exact surface's normal, turned to the camera, dotted with
    the direction to the light; 0 off the objects)."""
    if shadows not in ("all", "planar", "none"):
        raise ValueError(f"shadows must be all, planar or none (got {shadows!r})")
    cam = scene["camera"]
    eye_world = np.asarray(cam["position"], np.float64)
    rel_cam = dict(cam, position=[0.0, 0.0, 0.0],
                   focal_point=list(np.asarray(cam["focal_point"], np.float64) - eye_world))
    eye, dirs = camera_rays(rel_cam, width, height)
    view = normalize(np.asarray(rel_cam["focal_point"], np.float64))
    prims = [_primitive(o, eye_world) for o in scene["objects"]]

    best = np.full((height, width), np.inf)
    obj = np.full((height, width), -1)
    face = np.zeros((height, width), int)
    normal = np.zeros((height, width, 3))
    for k, prim in enumerate(prims):
        t, n, f = _intersect(prim, eye, dirs)
        closer = t < best
        best = np.where(closer, t, best)
        obj = np.where(closer, k, obj)
        face = np.where(closer, f, face)
        normal = np.where(closer[..., None], n, normal)
    hitmask = np.isfinite(best)
    tb = np.where(hitmask, best, 0.0)
    p = tb[..., None] * dirs  # camera-relative hit points
    facing = np.einsum("...k,...k", normal, dirs) > 0
    normal = np.where(facing[..., None], -normal, normal)

    light = scene["lights"][light_index]
    if light["type"] == "directional":
        to_light = np.broadcast_to(-normalize(light["direction"]), p.shape)
        light_dist = np.full(best.shape, np.inf)
    else:
        d = (np.asarray(light["position"], np.float64) - eye_world) - p
        light_dist = np.linalg.norm(d, axis=-1)
        with np.errstate(divide="ignore", invalid="ignore"):
            to_light = d / light_dist[..., None]
    light_cos = np.where(hitmask, np.einsum("...k,...k", normal, to_light), 0.0)
    valid = hitmask & (light_cos > 1e-6)
    if light["type"] == "spot":
        axis = normalize(np.asarray(light["focal_point"], np.float64)
                         - np.asarray(light["position"], np.float64))
        valid &= np.einsum("...k,k", -to_light, axis) > np.cos(np.radians(light["cone_angle"]))

    receiver = np.zeros(best.shape, bool)
    for k, o in enumerate(scene["objects"]):
        if o.get("receiver", False):
            receiver |= obj == k
    blocked = np.zeros(best.shape, bool)
    if shadows != "none":
        dist = tb * np.linalg.norm(dirs, axis=-1)
        origin = p + (1e-9 * dist)[..., None] * to_light
        for k, (o, prim) in enumerate(zip(scene["objects"], prims)):
            if not o.get("casts", True):
                continue
            t, _, _ = _intersect(prim, origin, to_light)
            # Every primitive is convex: it never shadows its own lit side.
            # A mesh may: the ray starts just off the surface towards the
            # light, so the face it starts on is never hit.
            blocked |= (t < light_dist) & ((obj != k) | (prim[0] == "mesh"))
        if shadows == "planar":
            blocked &= receiver
    visibility = np.where(valid & ~blocked, 1.0, 0.0)
    return {
        "visibility": visibility, "valid": valid, "object": obj, "face": face,
        "distance": np.where(hitmask, tb * np.linalg.norm(dirs, axis=-1), np.inf),
        "depth": np.where(hitmask, np.einsum("...k,k", p, view), np.inf),
        "receiver": receiver, "blocked": blocked & valid, "light_cos": light_cos,
    }


def render_exact(scene, light_index, width, height, shadows="all"):
    """Returns (visibility, valid, object_id), each (H, W), row 0 at the top,
    for light `light_index`; `shadows` as in trace_scene ("all" by default)."""
    r = trace_scene(scene, light_index, width, height, shadows)
    return r["visibility"], r["valid"], r["object"]


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
