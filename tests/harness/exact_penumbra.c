/* exact_penumbra.c - the exact penumbra of a sphere over a plane under a
 * light with a size, per pixel, compared with a renderer's visibility.
 *
 *   exact_penumbra SCENE LIGHT VIS.png MASK.png [EXACT_OUT.png]
 *
 * SCENE's object 0 must be a sphere (the occluder), object 1 a plane (the
 * receiver) and light LIGHT a point light or a directional light (with or
 * without a size). The image size is that of VIS.png (the renderer's,
 * e.g. the harness's --scale). Each pixel's ray (the camera model of
 * docs/harness.md: through the pixel centre) is intersected with the true
 * sphere (pixel left out) and the plane; on the plane the visibility is the
 * unoccluded fraction of the light, integrated numerically by vsh_soft
 * (64 x 256 cells). Pixels count where MASK.png is non-zero. Prints one
 * JSON object: the penumbra metrics of VIS against the exact image
 * (vshm_penumbra.h) and its whole-image mean absolute error. Exit 0, or 2
 * on bad input. The exact image goes to EXACT_OUT.png when given.
 *
 *   exact_penumbra --field-out FIELD SCENE LIGHT VIS.png MASK.png [EXACT_OUT.png]
 *   exact_penumbra --field-in FIELD SCENE LIGHT VIS.png MASK.png [EXACT_OUT.png]
 *
 * The same, and also writes the exact per-pixel values to FIELD
 * (exact_field.h), or takes them from FIELD instead of integrating them: they
 * depend on the scene, the light and VIS's size only, so
 * tests/harness/exact_cache.py computes them once for all the renders it
 * compares. The output is the same either way.
 *
 *   exact_penumbra --noise A.png B.png MASK.png [SCENE LIGHT]
 *
 * A renderer's own noise from two renders with different seeds: over the
 * penumbra mask of A (vshm_penumbra_mask), sigma = std(A - B) / sqrt(2)
 * (the noise of one render, independent renders). With SCENE and LIGHT,
 * only the plane's pixels count (as for the exact comparison): Cycles'
 * per-sample N.L makes a curved caster's terminator far noisier. */
#include "exact_field.h"
#include "vshm_metrics.h"
#include "vshm_penumbra.h"
#include "vshm_png.h"
#include "vsh_scene.h"
#include "vsh_soft.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static void sub(const double a[3], const double b[3], double o[3]) {
  o[0] = a[0] - b[0], o[1] = a[1] - b[1], o[2] = a[2] - b[2];
}
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

/* The camera rays of docs/harness.md ("Camera: one ray per pixel"). */
typedef struct cam {
  double e[3], f[3], r[3], u[3], t, a;
} cam;

static void camera_of(const vsh_camera *c, int w, int h, cam *o) {
  memcpy(o->e, c->position, sizeof o->e);
  sub(c->focal_point, c->position, o->f);
  unit(o->f);
  cross(o->f, c->view_up, o->r);
  unit(o->r);
  cross(o->r, o->f, o->u);
  o->t = tan(c->view_angle * PI / 360.0);
  o->a = (double)w / h;
}

/* Visibility at pixel (i, j): -1 when the pixel does not see the plane
 * inside its parallelogram in front of the sphere. */
static double pixel(const vsh_scene *s, const cam *c, int k, int i, int j, int w, int h) {
  const vsh_object *sp = &s->objects[0], *pl = &s->objects[1];
  const vsh_light *L = &s->lights[k];
  double d[3], e1[3], e2[3], n[3], q[3], p[3], x = (2.0 * (i + 0.5) / w - 1.0) * c->t * c->a,
                                               y = (1.0 - 2.0 * (j + 0.5) / h) * c->t;
  for (int m = 0; m < 3; ++m) d[m] = c->f[m] + x * c->r[m] + y * c->u[m];
  sub(pl->point1, pl->origin, e1);
  sub(pl->point2, pl->origin, e2);
  cross(e1, e2, n);
  sub(pl->origin, c->e, q);
  double tp = dot(q, n) / dot(d, n);
  if (!(tp > 0.0)) return -1.0;
  if (vsh_soft_ray_hits_sphere(c->e, d, 0.0, tp, sp->center, sp->radius)) return -1.0;
  for (int m = 0; m < 3; ++m) p[m] = c->e[m] + tp * d[m];
  /* Inside the parallelogram: p - origin = s e1 + t e2 with s, t in [0, 1]. */
  {
    double rel[3], c1[3], c2[3], nn = dot(n, n), ss, tt;
    sub(p, pl->origin, rel);
    cross(rel, e2, c1);
    cross(e1, rel, c2);
    ss = dot(c1, n) / nn;
    tt = dot(c2, n) / nn;
    if (ss < 0 || ss > 1 || tt < 0 || tt > 1) return -1.0;
  }
  if (L->type == VSH_LIGHT_DIRECTIONAL) {
    double l[3] = {-L->direction[0], -L->direction[1], -L->direction[2]};
    return vsh_soft_sphere_visibility_sun(p, sp->center, sp->radius, l, L->angle, 64, 256);
  }
  return vsh_soft_sphere_visibility_disk(p, sp->center, sp->radius, L->position, L->radius, 64,
                                         256);
}

static int usage_error(const char *msg, const char *what) {
  fprintf(stderr, "exact_penumbra: %s%s\n", msg, what ? what : "");
  return 2;
}

static int noise(int argc, char **argv) {
  char err[1024];
  float *a = NULL, *b = NULL, *m = NULL;
  int w, h, w2, h2, w3, h3;
  if (argc != 5 && argc != 7)
    return usage_error("usage: exact_penumbra --noise A.png B.png MASK.png [SCENE LIGHT]", NULL);
  if (vshm_png_read_gray(argv[2], &a, &w, &h, NULL, err, sizeof err) ||
      vshm_png_read_gray(argv[3], &b, &w2, &h2, NULL, err, sizeof err) ||
      vshm_png_read_gray(argv[4], &m, &w3, &h3, NULL, err, sizeof err) || w != w2 || w != w3 ||
      h != h2 || h != h3)
    return usage_error("cannot read the images: ", err);
  size_t np = (size_t)w * h;
  unsigned char *valid = malloc(np), *mask = malloc(np);
  double sum = 0, sum2 = 0;
  long n = 0;
  for (size_t i = 0; i < np; ++i) valid[i] = m[i] > 0.5f;
  if (argc == 7) {
    vsh_scene *s = NULL;
    cam c;
    int k = atoi(argv[6]);
    if (vsh_scene_load(argv[5], &s, err, sizeof err)) return usage_error(err, NULL);
    if (k < 0 || (size_t)k >= s->light_count || s->object_count < 2)
      return usage_error("bad scene or light: ", argv[5]);
    camera_of(&s->camera, w, h, &c);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i)
        if (valid[(size_t)j * w + i] && pixel(s, &c, k, i, j, w, h) < 0) valid[(size_t)j * w + i] = 0;
    vsh_scene_free(s);
  }
  vshm_penumbra_mask(a, valid, w, h, mask);
  for (size_t i = 0; i < np; ++i)
    if (mask[i]) {
      double d = (double)a[i] - (double)b[i];
      sum += d, sum2 += d * d, ++n;
    }
  double var = n > 1 ? (sum2 - sum * sum / n) / (n - 1) : 0.0;
  printf("{\"pen_pixels\": %ld, \"sigma\": %.6g, \"mean_difference\": %.6g}\n", n,
         sqrt(var / 2.0), n ? sum / n : 0.0);
  free(a), free(b), free(m), free(valid), free(mask);
  return 0;
}

int main(int argc, char **argv) {
  if (argc > 1 && strcmp(argv[1], "--noise") == 0) return noise(argc, argv);
  const char *field_in, *field_out;
  exact_field_options(&argc, &argv, &field_in, &field_out);
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene *s = NULL;
  float *vis = NULL, *mask = NULL;
  int w, h, w2, h2, k;
  if (argc != 5 && argc != 6)
    return usage_error("usage: exact_penumbra [--field-in|--field-out FIELD] SCENE LIGHT VIS.png "
                       "MASK.png [EXACT.png]",
                       NULL);
  if (vsh_scene_load(argv[1], &s, err, sizeof err)) return usage_error(err, NULL);
  k = atoi(argv[2]);
  if (k < 0 || (size_t)k >= s->light_count || s->object_count < 2 ||
      s->objects[0].kind != VSH_OBJECT_SPHERE || s->objects[1].kind != VSH_OBJECT_PLANE ||
      s->objects[0].has_transform || s->objects[1].has_transform ||
      s->lights[k].type == VSH_LIGHT_SPOT)
    return usage_error("need a sphere, a plane and a point or directional light: ", argv[1]);
  if (vshm_png_read_gray(argv[3], &vis, &w, &h, NULL, err, sizeof err) ||
      vshm_png_read_gray(argv[4], &mask, &w2, &h2, NULL, err, sizeof err) || w != w2 || h != h2)
    return usage_error("cannot read the images: ", err);
  cam c;
  camera_of(&s->camera, w, h, &c);
  size_t np = (size_t)w * h;
  /* The exact visibility per pixel, -1 off the plane: all that the
   * integration gives; the comparison below reads only this. */
  double *field = malloc(np * sizeof *field);
  if (field_in) {
    if (exact_field_read(field_in, field, w, h, 1, err, sizeof err)) return usage_error(err, NULL);
  } else {
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) field[(size_t)j * w + i] = pixel(s, &c, k, i, j, w, h);
    if (field_out && exact_field_write(field_out, field, w, h, 1, err, sizeof err)) {
      fprintf(stderr, "exact_penumbra: %s\n", err);
      return 1;
    }
  }
  float *exact = calloc(np, sizeof *exact);
  unsigned char *valid = calloc(np, 1);
  double sum = 0.0;
  long count = 0;
  for (size_t idx = 0; idx < np; ++idx) {
    double v = field[idx];
    exact[idx] = (float)(v < 0 ? 0 : v);
    valid[idx] = v >= 0 && mask[idx] > 0.5f;
    if (valid[idx]) sum += fabs((double)vis[idx] - v), ++count;
  }
  vshm_penumbra p;
  int rc = vshm_penumbra_compute(vis, exact, valid, NULL, w, h, &p);
  if (argc == 6) vshm_png_write_gray16_float(argv[5], exact, w, h, err, sizeof err);
  printf("{\"pixels\": %ld, \"mae\": %.6g, \"pen_pixels\": %ld, \"pen_mae\": %.6g, "
         "\"pen_bias\": %.6g, \"leak_pct\": %.6g, \"false_shadow_pct\": %.6g, "
         "\"width_ratio\": %.6g, \"contour_05_px\": %.6g, \"status\": %d}\n",
         count, count ? sum / count : 0.0, p.penumbra_pixels, p.pen_mae, p.pen_bias, p.leak_pct,
         p.false_shadow_pct, p.width_ratio, p.contour_px[1], rc);
  free(field), free(exact), free(valid), free(vis), free(mask);
  vsh_scene_free(s);
  return rc < 0 ? 1 : 0;
}
