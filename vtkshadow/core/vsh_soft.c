/* vsh_soft.c - sample positions on lights with a size, and the exact
 * (numerically integrated) penumbra of a sphere; see vsh_soft.h. */
#include "vsh_soft.h"

#include <math.h>

#define VSH_SOFT_PI 3.14159265358979323846
/* pi (3 - sqrt 5): consecutive spiral samples never line up. */
#define VSH_GOLDEN_ANGLE 2.39996322972865332

int vsh_soft_frame(const double n[3], double u[3], double v[3]) {
  /* Scaled by the largest component first: 1e-300 or 1e300 long vectors
   * neither underflow nor overflow when squared. */
  double m = fmax(fabs(n[0]), fmax(fabs(n[1]), fabs(n[2]))), len = 0.0, w[3], h[3], k;
  int i;
  if (m > 0.0 && isfinite(m))
    len = m * sqrt((n[0] / m) * (n[0] / m) + (n[1] / m) * (n[1] / m) + (n[2] / m) * (n[2] / m));
  if (!(len > 0.0) || !isfinite(len)) {
    u[0] = 1.0, u[1] = 0.0, u[2] = 0.0;
    v[0] = 0.0, v[1] = 1.0, v[2] = 0.0;
    return -1;
  }
  for (i = 0; i < 3; ++i) w[i] = (n[i] / m) / (len / m);
  /* The helper axis least aligned with w keeps u well conditioned. */
  h[0] = 0.0, h[1] = 0.0, h[2] = 0.0;
  if (fabs(w[0]) <= fabs(w[1]) && fabs(w[0]) <= fabs(w[2]))
    h[0] = 1.0;
  else if (fabs(w[1]) <= fabs(w[2]))
    h[1] = 1.0;
  else
    h[2] = 1.0;
  u[0] = h[1] * w[2] - h[2] * w[1];
  u[1] = h[2] * w[0] - h[0] * w[2];
  u[2] = h[0] * w[1] - h[1] * w[0];
  k = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  for (i = 0; i < 3; ++i) u[i] /= k;
  /* v = w x u, so (u, v, w) is right-handed. */
  v[0] = w[1] * u[2] - w[2] * u[1];
  v[1] = w[2] * u[0] - w[0] * u[2];
  v[2] = w[0] * u[1] - w[1] * u[0];
  return 0;
}

int vsh_soft_disk_sample(int i, int n, double turn, double out[2]) {
  double rho, phi;
  if (n < 1 || i < 0 || i >= n || !isfinite(turn)) return -1;
  rho = sqrt((i + 0.5) / n);
  phi = i * VSH_GOLDEN_ANGLE + turn;
  out[0] = rho * cos(phi);
  out[1] = rho * sin(phi);
  return 0;
}

int vsh_soft_light_point(const double c[3], double r, const double p[3], const double q[2],
                         double out[3]) {
  double n[3], u[3], v[3];
  int i;
  for (i = 0; i < 3; ++i) n[i] = p[i] - c[i];
  if (vsh_soft_frame(n, u, v)) return -1;
  for (i = 0; i < 3; ++i) out[i] = c[i] + r * (q[0] * u[i] + q[1] * v[i]);
  return 0;
}

int vsh_soft_sun_direction(const double l[3], double angle_deg, const double q[2],
                           double out[3]) {
  double u[3], v[3], t, d[3], len;
  int i;
  if (!(angle_deg >= 0.0 && angle_deg < 180.0)) return -1;
  if (vsh_soft_frame(l, u, v)) return -1;
  t = tan(angle_deg * VSH_SOFT_PI / 360.0);
  /* u x v is l's unit direction (right-handed frame). */
  {
    double w[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    for (i = 0; i < 3; ++i) d[i] = w[i] + t * (q[0] * u[i] + q[1] * v[i]);
  }
  len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  for (i = 0; i < 3; ++i) out[i] = d[i] / len;
  return 0;
}

int vsh_soft_ray_hits_sphere(const double p[3], const double d[3], double t_min, double t_max,
                             const double s[3], double R) {
  /* |p + t d - s|^2 = R^2: a t^2 - 2 b t + c = 0 with the half-b form, which
   * keeps the roots accurate when the sphere is far (no 4ac cancellation). */
  double m[3] = {s[0] - p[0], s[1] - p[1], s[2] - p[2]};
  double a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  double b = m[0] * d[0] + m[1] * d[1] + m[2] * d[2];
  double cc = m[0] * m[0] + m[1] * m[1] + m[2] * m[2] - R * R;
  double disc, root, t0, t1, q;
  if (!(a > 0.0)) return 0;
  disc = b * b - a * cc;
  if (disc < 0.0) return 0;
  root = sqrt(disc);
  q = b >= 0.0 ? b + root : b - root;
  if (q == 0.0) return 0;
  t0 = q / a;
  t1 = cc / q;
  if (t0 > t1) {
    double tmp = t0;
    t0 = t1;
    t1 = tmp;
  }
  /* The ray meets the solid ball where t in [t0, t1]. */
  return t1 > t_min && t0 < t_max;
}

/* Midpoint rule over equal-area cells of the unit disk: ring k spans
 * radii sqrt(k/rings)..sqrt((k+1)/rings), each ring cut into `sectors`.
 * `blocked` is the shadow test of one disk point. */
typedef int (*vsh_soft_test)(const void *ctx, const double q[2]);

static double integrate_disk(vsh_soft_test blocked, const void *ctx, int rings, int sectors) {
  long open = 0, total = 0;
  int k, j;
  for (k = 0; k < rings; ++k) {
    double rho = sqrt((k + 0.5) / rings);
    for (j = 0; j < sectors; ++j) {
      double phi = 2.0 * VSH_SOFT_PI * (j + 0.5) / sectors, q[2];
      q[0] = rho * cos(phi);
      q[1] = rho * sin(phi);
      open += blocked(ctx, q) ? 0 : 1;
      ++total;
    }
  }
  return (double)open / (double)total;
}

typedef struct disk_ctx {
  const double *p, *s, *c;
  const double *toward; /* the point the disk faces: p, or a fixed point */
  double R, r;
} disk_ctx;

static int disk_blocked(const void *vctx, const double q[2]) {
  const disk_ctx *x = (const disk_ctx *)vctx;
  double at[3], d[3];
  int i;
  if (vsh_soft_light_point(x->c, x->r, x->toward, q, at)) return 0;
  for (i = 0; i < 3; ++i) d[i] = at[i] - x->p[i];
  return vsh_soft_ray_hits_sphere(x->p, d, 0.0, 1.0, x->s, x->R);
}

double vsh_soft_sphere_visibility_disk(const double p[3], const double s[3], double R,
                                       const double c[3], double r, int rings, int sectors) {
  disk_ctx x;
  if (!(R > 0.0) || !(r >= 0.0) || rings < 1 || sectors < 1) return -1.0;
  if (p[0] == c[0] && p[1] == c[1] && p[2] == c[2]) return -1.0;
  x.p = p, x.s = s, x.c = c, x.R = R, x.r = r, x.toward = p;
  if (r == 0.0) {
    const double q[2] = {0.0, 0.0};
    return disk_blocked(&x, q) ? 0.0 : 1.0;
  }
  return integrate_disk(disk_blocked, &x, rings, sectors);
}

typedef struct sun_ctx {
  const double *p, *s, *l;
  double R, angle;
} sun_ctx;

static int sun_blocked(const void *vctx, const double q[2]) {
  const sun_ctx *x = (const sun_ctx *)vctx;
  double d[3];
  if (vsh_soft_sun_direction(x->l, x->angle, q, d)) return 0;
  return vsh_soft_ray_hits_sphere(x->p, d, 0.0, HUGE_VAL, x->s, x->R);
}

double vsh_soft_sphere_visibility_sun(const double p[3], const double s[3], double R,
                                      const double l[3], double angle_deg, int rings,
                                      int sectors) {
  sun_ctx x;
  if (!(R > 0.0) || !(angle_deg >= 0.0 && angle_deg < 180.0) || rings < 1 || sectors < 1)
    return -1.0;
  if (!(fabs(l[0]) + fabs(l[1]) + fabs(l[2]) > 0.0)) return -1.0;
  x.p = p, x.s = s, x.l = l, x.R = R, x.angle = angle_deg;
  if (angle_deg == 0.0) {
    const double q[2] = {0.0, 0.0};
    return sun_blocked(&x, q) ? 0.0 : 1.0;
  }
  return integrate_disk(sun_blocked, &x, rings, sectors);
}

double vsh_soft_sphere_visibility_disk_facing(const double p[3], const double s[3], double R,
                                              const double c[3], double r,
                                              const double toward[3], int rings, int sectors) {
  disk_ctx x;
  if (!(R > 0.0) || !(r >= 0.0) || rings < 1 || sectors < 1) return -1.0;
  if (toward[0] == c[0] && toward[1] == c[1] && toward[2] == c[2]) return -1.0;
  if (p[0] == c[0] && p[1] == c[1] && p[2] == c[2]) return -1.0;
  x.p = p, x.s = s, x.c = c, x.R = R, x.r = r, x.toward = toward;
  return integrate_disk(disk_blocked, &x, rings, sectors);
}

int vsh_soft_sample_light(const double light[4], double size, const double toward[3], int i,
                          int n, double turn, double out[4]) {
  double q[2];
  if (!(size >= 0.0) || !isfinite(size) || !(light[3] >= 0.0)) return -1;
  if (vsh_soft_disk_sample(i, n, turn, q)) return -1;
  if (light[3] > 0.0) {
    const double c[3] = {light[0] / light[3], light[1] / light[3], light[2] / light[3]};
    if (vsh_soft_light_point(c, size, toward, q, out)) return -1;
    out[3] = 1.0;
    return 0;
  }
  if (vsh_soft_sun_direction(light, size, q, out)) return -1;
  out[3] = 0.0; /* a unit direction: vsh_planar needs only the direction */
  return 0;
}
