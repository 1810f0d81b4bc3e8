/* vsh_soft.h - lights with a size: where the samples on the light go, and the
 * exact penumbra of a sphere, for soft-shadow techniques and their tests.
 *
 * A light with a size is defined as Blender 3.4 Cycles samples it
 * (docs/scene-format.md, "Lights with a size"):
 *  - point and spot, radius r: a disk centred on the light position c,
 *    facing the shaded point p (normal (p - c) / |p - c|), sampled uniformly
 *    by area;
 *  - directional, angular diameter a: directions to the light
 *    normalize(l + tan(a/2) q), l the unit direction towards the light and
 *    q uniform on the unit disk perpendicular to l.
 * Visibility of p is the fraction of those samples whose shadow ray is not
 * blocked. Everything here is double precision and pure.
 */
#ifndef VSH_SOFT_H
#define VSH_SOFT_H

#ifdef __cplusplus
extern "C" {
#endif

/* Two unit vectors u, v with (u, v, n/|n|) right-handed and orthonormal,
 * for a non-zero finite n (any length). Returns 0, or -1 when n is zero or
 * not finite (u and v are then the x and y axes). */
int vsh_soft_frame(const double n[3], double u[3], double v[3]);

/* Sample i of n (0 <= i < n) on the unit disk, stratified by area: Vogel's
 * golden-angle spiral, radius sqrt((i + 0.5) / n) (each sample the middle of
 * its own ring of area pi/n) and angle i * golden angle + `turn` radians.
 * Any n works (no square grid), and `turn` rotates the whole set, e.g. per
 * pixel, which trades the banding of a fixed pattern for noise. Writes
 * out[0], out[1] with out[0]^2 + out[1]^2 < 1. Returns -1 for i or n out of
 * range. */
int vsh_soft_disk_sample(int i, int n, double turn, double out[2]);

/* The world position of disk sample q (from vsh_soft_disk_sample) on a
 * point / spot light of centre c and radius r facing the point p. Returns
 * -1 when p == c. */
int vsh_soft_light_point(const double c[3], double r, const double p[3], const double q[2],
                         double out[3]);

/* The unit direction towards a directional light for disk sample q: l is
 * the unit direction towards the light (minus the travel direction),
 * angle_deg the angular diameter in [0, 180). Returns -1 for a bad angle
 * or a zero l. */
int vsh_soft_sun_direction(const double l[3], double angle_deg, const double q[2],
                           double out[3]);

/* Whether the segment from p to p + d (t in (t_min, t_max)) meets the
 * sphere (centre s, radius R): the shadow test of one sample. */
int vsh_soft_ray_hits_sphere(const double p[3], const double d[3], double t_min, double t_max,
                             const double s[3], double R);

/* The exact penumbra of a sphere occluder (centre s, radius R) at point p
 * under a disk light (centre c, radius r, facing p): the unoccluded
 * fraction of the disk, integrated numerically by the midpoint rule on
 * `rings` x `sectors` cells of equal area (rings in sqrt(radius)). Error
 * about (length of the occluded region's rim inside the disk) x (cell
 * size) / (disk area); 256 x 1024 cells is below 1e-3. r = 0 gives the hard
 * test (1 or 0). Returns a value in [0, 1], or -1 for bad arguments. */
double vsh_soft_sphere_visibility_disk(const double p[3], const double s[3], double R,
                                       const double c[3], double r, int rings, int sectors);

/* The same for a directional light: l the unit direction towards the light,
 * angle_deg its angular diameter, rays unbounded. */
double vsh_soft_sphere_visibility_sun(const double p[3], const double s[3], double R,
                                      const double l[3], double angle_deg, int rings,
                                      int sectors);

/* The same as vsh_soft_sphere_visibility_disk, but the disk faces the point
 * `toward` (normal (toward - c)) for every p instead of facing p: the
 * approximation of a technique that turns the light once per caster
 * (vtkPlanarShadowPass's sampled area light faces each caster's centre),
 * for measuring what that costs. Returns -1 for bad arguments or toward ==
 * c. */
double vsh_soft_sphere_visibility_disk_facing(const double p[3], const double s[3], double R,
                                              const double c[3], double r,
                                              const double toward[3], int rings, int sectors);

/* Sample i of n of a light with a size, as a homogeneous light: `light` is
 * (L, 1) for a point / spot light at L or (l, 0) for a directional light
 * towards l (the convention of vsh_planar.h), size its radius (positional)
 * or angular diameter in degrees (directional). A positional light's disk
 * faces the point `toward`; a directional light ignores it. The samples
 * are vsh_soft_disk_sample(i, n, turn): out = (point, 1) or (direction, 0).
 * size 0 gives the light itself. Returns -1 for bad arguments (w neither 0
 * nor positive, a non-finite or negative size, toward at the light). */
int vsh_soft_sample_light(const double light[4], double size, const double toward[3], int i,
                          int n, double turn, double out[4]);

#ifdef __cplusplus
}
#endif
#endif
