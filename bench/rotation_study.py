"""Does turning the light's sample pattern per pixel lower the penumbra error?

    rotation_study.py [--size G] [--samples 4,8,16,32,64]

Issue 15 asks for N stratified points on the light "rotated per pixel".
planar, volume and csm soft=2 draw one light point per pass or per map for
the whole screen, so a pattern per pixel would cost passes or maps. Before
paying that, this measures what rotation buys, numerically and exactly: a
disk light (radius 0.5, 4 above the plane z = 0, facing down) over a sphere
(radius 0.5, centre 1.5 above the plane), visibility per plane point over a
G x G grid of [-1.2, 1.2]^2, the reference from 8192 Vogel points. Per N:

- fixed: the N Vogel points of the rasterized passes today (banding);
- turned per pixel: the same N points turned by a random angle per pixel
  (what raytrace does; a rasterizer would need a pass per distinct turn);
- interleaved: N passes in all, spiral point i drawn only on the pixels of
  class i mod 4 (2x2 blocks), then a 2x2 box average (Keller and
  Heidrich's interleaved sampling: the same passes, a quarter of the
  lookups per pixel).

pen_mae is the mean |v - v_ref| over the reference's penumbra (0.02 < v <
0.98), the metric of docs/metrics.md. Needs python3-numpy.
"""
import argparse

import numpy as np

LIGHT_RADIUS, LIGHT_HEIGHT = 0.5, 4.0
CENTRE, SPHERE_RADIUS = np.array([0.0, 0.0, 1.5]), 0.5
GOLDEN_ANGLE = np.pi * (3.0 - np.sqrt(5.0))


def vogel(n, turn=0.0):
    """The unit-disk spiral of vsh_soft_disk_sample: point i at radius
    sqrt((i + 0.5) / n), angle i x golden angle + turn."""
    i = np.arange(n)
    r = np.sqrt((i + 0.5) / n)
    a = i * GOLDEN_ANGLE + turn
    return np.stack([r * np.cos(a), r * np.sin(a)], -1)


def lit(points, disk):
    """(len(points), len(disk)): 1 where the segment from the plane point to
    the light point misses the sphere."""
    light = np.stack([LIGHT_RADIUS * disk[:, 0], LIGHT_RADIUS * disk[:, 1],
                      np.full(len(disk), LIGHT_HEIGHT)], -1)
    d = light[None] - points[:, None]
    f = points[:, None] - CENTRE
    a = (d * d).sum(-1)
    b = 2.0 * (f * d).sum(-1)
    c = (f * f).sum(-1) - SPHERE_RADIUS ** 2
    disc = b * b - 4.0 * a * c
    root = np.sqrt(np.maximum(disc, 0.0))
    t1, t2 = (-b - root) / (2.0 * a), (-b + root) / (2.0 * a)
    hit = (disc > 0.0) & (((t1 > 0.0) & (t1 < 1.0)) | ((t2 > 0.0) & (t2 < 1.0)))
    return (~hit).astype(float)


def visibility(points, disk, chunk=4000):
    return np.concatenate([lit(points[i:i + chunk], disk).mean(1)
                           for i in range(0, len(points), chunk)])


def interleaved(points, grid, n):
    """N passes, point i on pixel class i mod 4, then a 2x2 box average."""
    rows, cols = np.meshgrid(np.arange(grid), np.arange(grid), indexing="ij")
    cls = ((rows % 2) * 2 + (cols % 2)).reshape(-1)
    disk = vogel(n)
    per = np.zeros(len(points))
    for c in range(4):
        mine = cls == c
        if len(disk[c::4]):
            per[mine] = visibility(points[mine], disk[c::4])
    image = np.pad(per.reshape(grid, grid), ((0, 1), (0, 1)), mode="edge")
    box = (image[:-1, :-1] + image[1:, :-1] + image[:-1, 1:] + image[1:, 1:]) / 4.0
    return box.reshape(-1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--size", type=int, default=160, help="grid points per side (default 160)")
    parser.add_argument("--samples", default="4,8,16,32,64", help="N values (default 4,8,16,32,64)")
    args = parser.parse_args()
    if args.size < 8:
        parser.error("--size: %d is below 8" % args.size)
    try:
        counts = [int(s) for s in args.samples.split(",")]
    except ValueError:
        parser.error("--samples: %r is not a list of integers" % args.samples)
    if not counts or min(counts) < 1:
        parser.error("--samples: %r needs integers >= 1" % args.samples)
    xs = np.linspace(-1.2, 1.2, args.size)
    x, y = np.meshgrid(xs, xs, indexing="ij")
    points = np.stack([x, y, np.zeros_like(x)], -1).reshape(-1, 3)
    ref = visibility(points, vogel(8192))
    pen = (ref > 0.02) & (ref < 0.98)
    rng = np.random.default_rng(1)
    print("penumbra points: %d of %d" % (pen.sum(), len(points)))
    print("| N | fixed | turned per pixel | interleaved 2x2 (same passes) |")
    print("|---:|---:|---:|---:|")
    for n in counts:
        fixed = visibility(points, vogel(n))
        turns = rng.uniform(0.0, 2.0 * np.pi, len(points))
        turned = np.array([lit(points[j:j + 1], vogel(n, turns[j]))[0].mean()
                           for j in range(len(points))])
        mixed = interleaved(points, args.size, n)
        print("| %d | %.4f | %.4f | %.4f |" % tuple(
            [n] + [np.abs(v - ref)[pen].mean() for v in (fixed, turned, mixed)]), flush=True)


if __name__ == "__main__":
    main()
