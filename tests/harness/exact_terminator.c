/* exact_terminator.c - the exact visibility on a sphere's own terminator
 * under a light with a size, both definitions, against a renderer's.
 *
 *   exact_terminator SCENE LIGHT VIS.png MASK.png
 *
 * SCENE's object 0 must be a sphere, light LIGHT a point light or a
 * directional light with a size. Each pixel's ray through the pixel centre
 * (the camera model of docs/harness.md) that meets the true sphere gives a
 * point p with normal n = (p - centre) / R; over the light's disk (64 x 256
 * cells of equal area, vsh_soft_disk_sample's rings and sectors) with a
 * cell free when its ray misses the sphere:
 *   weighted   = sum free max(0, n.l) / sum max(0, n.l)  (I_on / I_off,
 *                as Cycles renders it; vsh_rt_weight.h)
 *   unweighted = the free fraction of the disk (the plain ray average).
 * Only the sphere shadows the sphere, so every cell above the horizon is
 * free and weighted = 1 wherever any of the light is above it; the plain
 * fraction is the part above the horizon. Counted: pixels valid in MASK
 * whose unweighted value is in (0.02, 0.98) (the light straddles the
 * horizon: the terminator band) and whose weighted sum is > 0. Prints one
 * JSON object: the pixel count and VIS's mean absolute error against each
 * definition. Exit 0, or 2 on bad input.
 *
 *   exact_terminator --field-out FIELD SCENE LIGHT VIS.png MASK.png
 *   exact_terminator --field-in FIELD SCENE LIGHT VIS.png MASK.png
 *
 * The same, and also writes both definitions per pixel (every pixel of
 * the sphere, whatever the mask; NaN where there is no value) to FIELD
 * (exact_field.h), or takes them from FIELD instead of integrating them:
 * they depend on the scene, the light and VIS's size only
 * (tests/harness/exact_cache.py keeps them). The output is the same either
 * way. */
#include "exact_field.h"
#include "vshm_png.h"
#include "vsh_scene.h"
#include "vsh_soft.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
#define RINGS 64
#define SECTORS 256

static double dot(const double a[3], const double b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static void cross(const double a[3], const double b[3], double o[3]) {
  o[0] = a[1] * b[2] - a[2] * b[1], o[1] = a[2] * b[0] - a[0] * b[2],
  o[2] = a[0] * b[1] - a[1] * b[0];
}
static void unit(double v[3]) {
  double n = sqrt(dot(v, v));
  v[0] /= n, v[1] /= n, v[2] /= n;
}

/* Both definitions at sphere point p (normal n): 0, or -1 when the light
 * is wholly below the horizon (no weight). */
static int visibility(const vsh_light *L, const double s[3], double R, const double p[3],
                      const double n[3], double *weighted, double *plain) {
  double wsum = 0, wfree = 0;
  long cells = 0, free_cells = 0;
  const double l[3] = {-L->direction[0], -L->direction[1], -L->direction[2]};
  for (int i = 0; i < RINGS; ++i)
    for (int j = 0; j < SECTORS; ++j) {
      /* The midpoint of cell (i, j): rings of equal area, sectors of equal angle. */
      const double rho = sqrt((i + 0.5) / RINGS), phi = 2 * PI * (j + 0.5) / SECTORS;
      const double q[2] = {rho * cos(phi), rho * sin(phi)};
      double d[3], tmax = HUGE_VAL;
      if (L->type == VSH_LIGHT_DIRECTIONAL) {
        if (vsh_soft_sun_direction(l, L->angle, q, d)) return -1;
      } else {
        double x[3];
        if (vsh_soft_light_point(L->position, L->radius, p, q, x)) return -1;
        for (int m = 0; m < 3; ++m) d[m] = x[m] - p[m];
        tmax = 1.0;
      }
      const double len = sqrt(dot(d, d)), w = fmax(0.0, dot(n, d) / len);
      /* Start a hair off the surface: the point itself is on the sphere. */
      const int hit = vsh_soft_ray_hits_sphere(p, d, 1e-9 * (1.0 + R) / len, tmax, s, R);
      ++cells, wsum += w;
      if (!hit) ++free_cells, wfree += w;
    }
  *plain = (double)free_cells / cells;
  if (!(wsum > 0)) return -1;
  *weighted = wfree / wsum;
  return 0;
}

static int fail(const char *msg, const char *what) {
  fprintf(stderr, "exact_terminator: %s%s\n", msg, what ? what : "");
  return 2;
}

/* Both definitions at every pixel whose ray meets the sphere, into
 * field[2 * pixel] (weighted) and [2 * pixel + 1] (unweighted); NaN at the
 * others and where the light is wholly below the horizon. */
static void integrate(const vsh_scene *sc, int k, int w, int h, double *field) {
  const vsh_camera *c = &sc->camera;
  const double *s = sc->objects[0].center, R = sc->objects[0].radius;
  double e[3], f[3], r[3], u[3];
  memcpy(e, c->position, sizeof e);
  for (int m = 0; m < 3; ++m) f[m] = c->focal_point[m] - e[m];
  unit(f), cross(f, c->view_up, r), unit(r), cross(r, f, u);
  const double t = tan(c->view_angle * PI / 360.0), a = (double)w / h;
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      double d[3], oc[3], p[3], n[3], vw, vu, *out = field + 2 * ((size_t)j * w + i);
      const double x = (2.0 * (i + 0.5) / w - 1.0) * t * a, y = (1.0 - 2.0 * (j + 0.5) / h) * t;
      out[0] = out[1] = NAN;
      for (int m = 0; m < 3; ++m) d[m] = f[m] + x * r[m] + y * u[m], oc[m] = e[m] - s[m];
      /* The nearest root of |e + t d - s|^2 = R^2. */
      const double A = dot(d, d), B = dot(oc, d), C = dot(oc, oc) - R * R, D = B * B - A * C;
      if (D < 0) continue;
      const double tt = (-B - sqrt(D)) / A;
      if (!(tt > 0)) continue;
      for (int m = 0; m < 3; ++m) p[m] = e[m] + tt * d[m], n[m] = (p[m] - s[m]) / R;
      if (visibility(&sc->lights[k], s, R, p, n, &vw, &vu)) continue;
      out[0] = vw, out[1] = vu;
    }
}

int main(int argc, char **argv) {
  const char *field_in, *field_out;
  exact_field_options(&argc, &argv, &field_in, &field_out);
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene *sc = NULL;
  float *vis = NULL, *mask = NULL;
  int w, h, w2, h2;
  if (argc != 5)
    return fail("usage: exact_terminator [--field-in|--field-out FIELD] SCENE LIGHT VIS.png "
                "MASK.png",
                NULL);
  if (vsh_scene_load(argv[1], &sc, err, sizeof err)) return fail(err, NULL);
  const int k = atoi(argv[2]);
  if (k < 0 || (size_t)k >= sc->light_count || sc->object_count < 1 ||
      sc->objects[0].kind != VSH_OBJECT_SPHERE || sc->objects[0].has_transform ||
      sc->lights[k].type == VSH_LIGHT_SPOT)
    return fail("need a sphere (object 0) and a point or directional light: ", argv[1]);
  if (vshm_png_read_gray(argv[3], &vis, &w, &h, NULL, err, sizeof err) ||
      vshm_png_read_gray(argv[4], &mask, &w2, &h2, NULL, err, sizeof err) || w != w2 || h != h2)
    return fail("cannot read the images: ", err);
  const size_t np = (size_t)w * h;
  double *field = malloc(2 * np * sizeof *field);
  if (field_in) {
    if (exact_field_read(field_in, field, w, h, 2, err, sizeof err)) return fail(err, NULL);
  } else {
    integrate(sc, k, w, h, field);
    if (field_out && exact_field_write(field_out, field, w, h, 2, err, sizeof err)) {
      fprintf(stderr, "exact_terminator: %s\n", err);
      return 1;
    }
  }
  long count = 0;
  double err_w = 0, err_u = 0;
  for (size_t idx = 0; idx < np; ++idx) {
    const double vw = field[2 * idx], vu = field[2 * idx + 1];
    if (!(mask[idx] > 0.5f) || isnan(vw) || !(vu > 0.02 && vu < 0.98)) continue;
    const double v = vis[idx];
    ++count, err_w += fabs(v - vw), err_u += fabs(v - vu);
  }
  printf("{\"pixels\": %ld, \"mae_weighted\": %.6g, \"mae_unweighted\": %.6g}\n", count,
         count ? err_w / count : 0.0, count ? err_u / count : 0.0);
  free(field), free(vis), free(mask);
  vsh_scene_free(sc);
  return 0;
}
