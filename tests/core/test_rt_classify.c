/* test_rt_classify.c - unit tests of vsh_rt_classify: every pixel tube the
 * map decides agrees with an exact double-precision shadow ray (against
 * every triangle) from the surface point the tube holds, for a directional,
 * a narrow spot and a point light (six faces) over a floor, a box, a
 * tilted plate, a sphere and a terrain; most tubes are decided; tubes on
 * a sharp valley's floor; folded, interpenetrating and open shapes; and
 * the degenerate
 * cases (no casters, geometry at the light, a tube across many texels, a
 * tube behind the light, a non-caster floor, bad input). */
#include "vsh_check.h"
#include "vsh_random.h"
#include "vsh_rt_classify.h"
#include "vsh_vec3.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define MAX_TRIANGLES 8192
static double tris[MAX_TRIANGLES * 9];
static unsigned char flags[MAX_TRIANGLES];
static int placement[MAX_TRIANGLES]; /* one per shape, as an actor's */
static int shape;
static size_t count;

static void add_triangle(const double a[3], const double b[3], const double c[3], int flag)
{
  memcpy(tris + 9 * count, a, 3 * sizeof(double));
  memcpy(tris + 9 * count + 3, b, 3 * sizeof(double));
  memcpy(tris + 9 * count + 6, c, 3 * sizeof(double));
  placement[count] = shape;
  flags[count++] = (unsigned char)flag;
}

static void add_quad(const double a[3], const double b[3], const double c[3], const double d[3],
                     int flag)
{
  add_triangle(a, b, c, flag);
  add_triangle(a, c, d, flag);
}

static void add_box(const double lo[3], const double hi[3])
{
  double v[8][3];
  for (int k = 0; k < 8; ++k) {
    v[k][0] = k & 1 ? hi[0] : lo[0];
    v[k][1] = k & 2 ? hi[1] : lo[1];
    v[k][2] = k & 4 ? hi[2] : lo[2];
  }
  static const int faces[6][4] = { { 0, 2, 3, 1 }, { 4, 5, 7, 6 }, { 0, 1, 5, 4 },
                                   { 2, 6, 7, 3 }, { 0, 4, 6, 2 }, { 1, 3, 7, 5 } };
  for (int f = 0; f < 6; ++f) {
    add_quad(v[faces[f][0]], v[faces[f][1]], v[faces[f][2]], v[faces[f][3]],
             VSH_RT_CLASSIFY_CASTS);
  }
}

static void add_sphere(const double c[3], double r, int rings, int segments)
{
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      double p[4][3];
      for (int k = 0; k < 4; ++k) {
        const double th = M_PI * (i + (k >> 1)) / rings, ph = 2 * M_PI * (j + (k & 1)) / segments;
        p[k][0] = c[0] + r * sin(th) * cos(ph);
        p[k][1] = c[1] + r * sin(th) * sin(ph);
        p[k][2] = c[2] + r * cos(th);
      }
      add_quad(p[0], p[1], p[3], p[2], VSH_RT_CLASSIFY_CASTS);
    }
  }
}

/* Height z(x, y) of the terrain: gentle hills, one valley along x = -4
 * whose sides bend sharply (slope 1.5) and one gentle valley. */
static double terrain_height(double x, double y)
{
  return 0.4 + 0.1 * sin(3 * x) * cos(2.5 * y) + (fabs(x + 4) < 0.26 ? 1.5 * fabs(x + 4) : 0.39) +
         0.05 * fabs(y - 3.5);
}

/* An open sheet over [-5.5, -2.5] x [1.5, 5.5], 24 x 16 cells (the
 * valley's floor on a grid line). */
static void add_terrain(void)
{
  for (int i = 0; i < 24; ++i) {
    for (int j = 0; j < 16; ++j) {
      double p[4][3];
      for (int k = 0; k < 4; ++k) {
        p[k][0] = -5.5 + 0.125 * (i + (k & 1));
        p[k][1] = 1.5 + 0.25 * (j + (k >> 1));
        p[k][2] = terrain_height(p[k][0], p[k][1]);
      }
      add_quad(p[0], p[1], p[3], p[2], VSH_RT_CLASSIFY_CASTS);
    }
  }
}

/* The scene: a floor (a caster, or drawn only), a box on it, a tilted
 * plate, a sphere above it and a terrain (an open sheet). */
static void make_scene(int floor_casts)
{
  count = 0;
  const double f[4][3] = { { -6, -6, 0 }, { 6, -6, 0 }, { 6, 6, 0 }, { -6, 6, 0 } };
  shape = 0;
  add_quad(f[0], f[1], f[2], f[3], floor_casts ? VSH_RT_CLASSIFY_CASTS : 0);
  shape = 1;
  const double lo[3] = { -2, -1, 0 }, hi[3] = { -1, 0.5, 1.2 };
  add_box(lo, hi);
  const double p[4][3] = { { 1, 1, 1.5 }, { 2.5, 1, 1.9 }, { 2.5, 2.5, 2.2 }, { 1, 2.5, 1.8 } };
  shape = 2;
  add_quad(p[0], p[1], p[2], p[3], VSH_RT_CLASSIFY_CASTS);
  shape = 3;
  const double c[3] = { 1.5, -2, 1.3 };
  add_sphere(c, 0.8, 12, 20);
  shape = 4;
  add_terrain();
}

/* Distance along the ray from o (unit d) to triangle t, or -1. */
static double hit_distance(const double o[3], const double d[3], size_t t)
{
  const double *a = tris + 9 * t;
  double e1[3], e2[3], pv[3], tv[3], qv[3];
  vsh_vec3_sub(a + 3, a, e1);
  vsh_vec3_sub(a + 6, a, e2);
  vsh_vec3_cross(d, e2, pv);
  const double det = vsh_vec3_dot(e1, pv);
  if (fabs(det) < 1e-300) {
    return -1;
  }
  vsh_vec3_sub(o, a, tv);
  const double u = vsh_vec3_dot(tv, pv) / det;
  vsh_vec3_cross(tv, e1, qv);
  const double v = vsh_vec3_dot(d, qv) / det, h = vsh_vec3_dot(e2, qv) / det;
  return u >= 0 && v >= 0 && u + v <= 1 && h > 0 ? h : -1;
}

/* Exact: does a ray from q along unit d, up to tmax, meet a caster? */
static int blocked(const double q[3], const double d[3], double tmax)
{
  for (size_t t = 0; t < count; ++t) {
    const double h = hit_distance(q, d, t);
    if ((flags[t] & VSH_RT_CLASSIFY_CASTS) && h > 0 && h < tmax) {
      return 1;
    }
  }
  return 0;
}

/* Nearest hit along a ray from o (unit d) on any triangle: its distance
 * and triangle, or -1. */
static double nearest(const double o[3], const double d[3], size_t *hit)
{
  double best = HUGE_VAL;
  for (size_t t = 0; t < count; ++t) {
    const double h = hit_distance(o, d, t);
    if (h > 0 && h < best) {
      best = h;
      *hit = t;
    }
  }
  return best < HUGE_VAL ? best : -1;
}

/* A triangle chosen with probability proportional to its area (a
 * picture's pixels fall on surfaces by area, not by triangle count). */
static size_t pick_by_area(double x)
{
  double total = 0, sum = 0;
  for (int pass = 0; pass < 2; ++pass) {
    for (size_t t = 0; t < count; ++t) {
      double e1[3], e2[3], n[3];
      vsh_vec3_sub(tris + 9 * t + 3, tris + 9 * t, e1);
      vsh_vec3_sub(tris + 9 * t + 6, tris + 9 * t, e2);
      vsh_vec3_cross(e1, e2, n);
      const double area = vsh_vec3_length(n);
      if (pass == 0) {
        total += area;
      } else if ((sum += area) >= x * total) {
        return t;
      }
    }
  }
  return count - 1;
}

/* The tracer's shadow-ray origin for surface point s on triangle t seen
 * along dir: offset off the triangle towards the camera. */
static void ray_origin(const double s[3], size_t t, const double dir[3], double q[3])
{
  const double *a = tris + 9 * t;
  double e1[3], e2[3], nrm[3];
  vsh_vec3_sub(a + 3, a, e1);
  vsh_vec3_sub(a + 6, a, e2);
  vsh_vec3_cross(e1, e2, nrm);
  vsh_vec3_normalize(nrm, nrm);
  const double side = vsh_vec3_dot(nrm, dir) > 0 ? -1.0 : 1.0;
  for (int r = 0; r < 3; ++r) {
    q[r] = s[r] + side * vsh_rt_offset_distance(12.0) * nrm[r];
  }
}

/* A random point on the surfaces (by area) and its triangle, and a random
 * camera position above the floor. */
static size_t random_point(double s[3], double eye[3])
{
  const size_t t = pick_by_area(vsh_test_rnd(0, 1));
  const double *a = tris + 9 * t;
  double u = vsh_test_rnd(0, 1), v = vsh_test_rnd(0, 1);
  if (u + v > 1) {
    u = 1 - u, v = 1 - v;
  }
  for (int r = 0; r < 3; ++r) {
    s[r] = a[r] + u * (a[3 + r] - a[r]) + v * (a[6 + r] - a[r]);
  }
  eye[0] = vsh_test_rnd(-9, 9), eye[1] = vsh_test_rnd(-9, 9), eye[2] = vsh_test_rnd(0.5, 9);
  return t;
}

/* A random surface point seen from a random camera, its tube, and the
 * exact answer at the ray's origin (offset towards the camera). */
static int check_light(const vsh_rt_light *light, int floor_casts, int resolution, double *decided)
{
  make_scene(floor_casts);
  vsh_rt_classify_map map;
  CHECK(vsh_rt_classify_build(&map, light, tris, flags, placement, count, resolution) == 0);
  CHECK(!map.unusable);
  int wrong = 0, n = 0, d = 0;
  for (int k = 0; k < 12000; ++k) {
    double s[3], eye[3], dir[3];
    const size_t t = random_point(s, eye);
    vsh_vec3_sub(s, eye, dir);
    const double dist = vsh_vec3_normalize(dir, dir);
    vsh_rt_pixel_ray ray;
    memset(&ray, 0, sizeof ray);
    memcpy(ray.origin, eye, sizeof eye);
    memcpy(ray.direction, dir, sizeof dir);
    ray.distance = dist;
    const double err = vsh_test_rnd(0, 1e-3) * dist;
    ray.lo = dist - err * vsh_test_rnd(0, 1);
    ray.hi = ray.lo + err;
    const double zero[3] = { 0, 0, 0 };
    vsh_rt_classify_tube tube;
    vsh_rt_classify_tube_init(&ray, zero, 12.0, &tube);
    const int c = vsh_rt_classify_pixel(&map, &tube);
    double q[3], to[3], tmax;
    ray_origin(s, t, dir, q);
    CHECK(vsh_rt_light_direction(light, q, to, &tmax) == VSH_RT_OK);
    ++n;
    if (c == VSH_RT_CLASSIFY_UNDECIDED) {
      continue;
    }
    ++d;
    int truth;
    if (c == VSH_RT_CLASSIFY_OUTSIDE_CONE) {
      truth = !vsh_rt_light_in_cone(light, to);
      wrong += !truth;
      continue;
    }
    truth = blocked(q, to, tmax) ? VSH_RT_CLASSIFY_SHADOWED : VSH_RT_CLASSIFY_LIT;
    if (truth != c) {
      ++wrong;
      if (wrong < 5) {
        fprintf(stderr, "  tube on triangle %zu at (%g %g %g): map %d, ray %d\n", t, s[0], s[1],
                s[2], c, truth);
      }
    }
  }
  *decided = (double)d / n;
  vsh_rt_classify_free(&map);
  return wrong;
}

/* Blocks of pixels: a camera-depth slab between 4 corner rays around a
 * random surface point; every surface point inside it that the camera
 * sees (sampled rays) must have the block's class. */
static int check_blocks(const vsh_rt_light *light, int resolution, double *decided)
{
  make_scene(1);
  vsh_rt_classify_map map;
  CHECK(vsh_rt_classify_build(&map, light, tris, flags, placement, count, resolution) == 0);
  int wrong = 0, n = 0, d = 0;
  for (int k = 0; k < 1500; ++k) {
    double s[3], eye[3], w[3], x[3], y[3];
    random_point(s, eye);
    vsh_vec3_sub(s, eye, w);
    const double dist = vsh_vec3_normalize(w, w);
    const double up[3] = { 0, 0, 1 };
    vsh_vec3_cross(w, up, x);
    vsh_vec3_normalize(x, x);
    vsh_vec3_cross(x, w, y);
    /* 8 pixels of ~1/600 rad; depths of the block from the surface's
     * depth at its corners, with a tolerance. */
    const double half = 4 * vsh_test_rnd(0.5, 2) / 600.0, tol = vsh_test_rnd(0, 2e-3) * dist;
    vsh_rt_classify_region region;
    double zlo = HUGE_VAL, zhi = -HUGE_VAL, dirs[4][3];
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 3; ++r) {
        dirs[c][r] = w[r] + (c & 1 ? half : -half) * x[r] + (c & 2 ? half : -half) * y[r];
      }
      vsh_vec3_normalize(dirs[c], region.dir[c]);
      size_t h;
      const double hit = nearest(eye, region.dir[c], &h);
      const double z = hit > 0 ? hit * vsh_vec3_dot(region.dir[c], w) : dist;
      zlo = fmin(zlo, z), zhi = fmax(zhi, z);
    }
    zlo -= tol, zhi += tol;
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 3; ++r) {
        region.corner[c][r] = eye[r] + dirs[c][r] * zlo;
        region.corner[c + 4][r] = eye[r] + dirs[c][r] * zhi;
      }
    }
    region.radius = 5 * vsh_rt_offset_distance(12.0);
    region.reland = 0;
    const int cls = vsh_rt_classify_block(&map, &region);
    ++n;
    if (cls == VSH_RT_CLASSIFY_UNDECIDED) {
      continue;
    }
    ++d;
    for (int q = 0; q < 16; ++q) {
      const double fu = vsh_test_rnd(-1, 1), fv = vsh_test_rnd(-1, 1);
      double dir[3], p[3], to[3], tmax;
      for (int r = 0; r < 3; ++r) {
        dir[r] = w[r] + fu * half * x[r] + fv * half * y[r];
      }
      vsh_vec3_normalize(dir, dir);
      size_t h = 0;
      const double hit = nearest(eye, dir, &h);
      if (hit < 0 || hit * vsh_vec3_dot(dir, w) < zlo || hit * vsh_vec3_dot(dir, w) > zhi) {
        continue; /* not a pixel of this block */
      }
      double on[3];
      for (int r = 0; r < 3; ++r) {
        on[r] = eye[r] + hit * dir[r];
      }
      ray_origin(on, h, dir, p);
      CHECK(vsh_rt_light_direction(light, p, to, &tmax) == VSH_RT_OK);
      const int truth = cls == VSH_RT_CLASSIFY_OUTSIDE_CONE
                          ? (vsh_rt_light_in_cone(light, to) ? -2 : cls)
                          : (blocked(p, to, tmax) ? VSH_RT_CLASSIFY_SHADOWED : VSH_RT_CLASSIFY_LIT);
      if (truth != cls && ++wrong < 5) {
        fprintf(stderr, "  block at (%g %g %g): map %d, ray %d\n", p[0], p[1], p[2], cls, truth);
      }
    }
  }
  *decided = (double)d / n;
  vsh_rt_classify_free(&map);
  return wrong;
}

static vsh_rt_light make_light(int kind)
{
  vsh_rt_light light;
  if (kind == VSH_RT_DIRECTIONAL) {
    const double h[4] = { 0.3, -0.4, 1.0, 0.0 }, focal[3] = { 0, 0, 0 };
    CHECK(vsh_rt_light_init(h, focal, 180.0, 0, 0, &light) == VSH_RT_OK);
  } else if (kind == VSH_RT_SPOT) {
    const double h[4] = { 1.0, 1.0, 7.0, 1.0 }, focal[3] = { 0, 0, 0 };
    CHECK(vsh_rt_light_init(h, focal, 40.0, 0, 0, &light) == VSH_RT_OK);
  } else {
    const double h[4] = { 0.5, 0.3, 3.5, 1.0 }, focal[3] = { 0, 0, 0 };
    CHECK(vsh_rt_light_init(h, focal, 180.0, 0, 0, &light) == VSH_RT_OK);
  }
  return light;
}

static void test_agrees_with_rays(void)
{
  const char *names[3] = { "directional", "point", "spot" };
  for (int kind = 0; kind < 3; ++kind) {
    for (int floor_casts = 0; floor_casts < 2; ++floor_casts) {
      vsh_rt_light light = make_light(kind);
      double decided = 0;
      const int wrong = check_light(&light, floor_casts, 512, &decided);
      printf("%-11s floor %s: decided %.3f, wrong %d\n", names[kind],
             floor_casts ? "casts" : "drawn", decided, wrong);
      CHECK(wrong == 0);
      CHECK(decided > 0.85);
    }
  }
}

static void test_blocks_agree_with_rays(void)
{
  const char *names[3] = { "directional", "point", "spot" };
  for (int kind = 0; kind < 3; ++kind) {
    vsh_rt_light light = make_light(kind);
    double decided = 0;
    const int wrong = check_blocks(&light, 512, &decided);
    printf("%-11s blocks: decided %.3f, wrong %d\n", names[kind], decided, wrong);
    CHECK(wrong == 0);
    CHECK(decided > 0.4);
  }
}

/* Surface point s on triangle t seen from eye, with a depth interval of
 * +-1e-6: the map's class of its tube (return) and the exact ray's from
 * the offset origin (truth). */
static int tube_class(const vsh_rt_classify_map *map, const vsh_rt_light *light,
                      const double s[3], size_t t, const double eye[3], int *truth)
{
  double dir[3], q[3], to[3], tmax;
  vsh_rt_pixel_ray ray;
  memset(&ray, 0, sizeof ray);
  vsh_vec3_sub(s, eye, dir);
  ray.distance = vsh_vec3_normalize(dir, dir);
  memcpy(ray.origin, eye, sizeof ray.origin);
  memcpy(ray.direction, dir, sizeof dir);
  ray.lo = ray.distance - 1e-6;
  ray.hi = ray.distance + 1e-6;
  const double zero[3] = { 0, 0, 0 };
  vsh_rt_classify_tube tube;
  vsh_rt_classify_tube_init(&ray, zero, 12.0, &tube);
  ray_origin(s, t, dir, q);
  CHECK(vsh_rt_light_direction(light, q, to, &tmax) == VSH_RT_OK);
  *truth = blocked(q, to, tmax) ? VSH_RT_CLASSIFY_SHADOWED : VSH_RT_CLASSIFY_LIT;
  return vsh_rt_classify_pixel(map, &tube);
}

/* Surface points within 1e-9 of the terrain's sharp valley floor under a
 * light straight above: an origin offset off one side of the valley
 * stands below the other side's plane there (the bend, sin cos |grad h1 -
 * grad h| = 1.38, is above 1), so the exact ray meets the other side.
 * Every tube the map decides must agree; none may be lit there. */
static void test_valley_floor(void)
{
  make_scene(1);
  vsh_rt_light light;
  const double h[4] = { 0, 0, 1, 0 }, focal[3] = { 0, 0, 0 };
  CHECK(vsh_rt_light_init(h, focal, 180.0, 0, 0, &light) == VSH_RT_OK);
  vsh_rt_classify_map map;
  CHECK(vsh_rt_classify_build(&map, &light, tris, flags, placement, count, 512) == 0);
  int wrong = 0, decided = 0, blocked_rays = 0;
  for (int k = 0; k < 4000; ++k) {
    const double x = -4 + (k % 2 ? 1 : -1) * vsh_test_rnd(1e-12, 1e-9), y = vsh_test_rnd(1.6, 5.4);
    const double above[3] = { x, y, 10 }, down[3] = { 0, 0, -1 };
    size_t t = 0;
    const double hit = nearest(above, down, &t);
    CHECK(hit > 0);
    const double s[3] = { x, y, 10 - hit };
    const double eye[3] = { x + vsh_test_rnd(-1, 1), y + vsh_test_rnd(-1, 1), vsh_test_rnd(3, 9) };
    int truth;
    const int c = tube_class(&map, &light, s, t, eye, &truth);
    blocked_rays += truth == VSH_RT_CLASSIFY_SHADOWED;
    decided += c != VSH_RT_CLASSIFY_UNDECIDED;
    wrong += c != VSH_RT_CLASSIFY_UNDECIDED && c != truth;
  }
  printf("valley floor: %d of 4000 rays blocked by the other side, decided %d, wrong %d\n",
         blocked_rays, decided, wrong);
  CHECK(blocked_rays > 100); /* the case this guards exists */
  CHECK(wrong == 0);
  vsh_rt_classify_free(&map);
}

/* Surface points within 1e-10 of any edge of the terrain (its gentle
 * valleys among them, which LIT (c) accepts) under a tilted light: every
 * decided tube agrees with the exact ray from its offset origin. */
static void test_terrain_edges(void)
{
  make_scene(1);
  const vsh_rt_light light = make_light(VSH_RT_DIRECTIONAL);
  vsh_rt_classify_map map;
  CHECK(vsh_rt_classify_build(&map, &light, tris, flags, placement, count, 512) == 0);
  const size_t first = count - 24 * 16 * 2; /* the terrain's triangles */
  int wrong = 0, decided = 0;
  for (int k = 0; k < 6000; ++k) {
    const size_t t = first + (size_t)vsh_test_rnd(0, (double)(count - first) - 1e-9);
    const int m = (int)vsh_test_rnd(0, 3 - 1e-9);
    const double *a = tris + 9 * t + 3 * m, *b = tris + 9 * t + 3 * ((m + 1) % 3);
    const double *c = tris + 9 * t + 3 * ((m + 2) % 3), u = vsh_test_rnd(0.01, 0.99);
    double s[3];
    for (int r = 0; r < 3; ++r) {
      s[r] = a[r] + u * (b[r] - a[r]);
      s[r] += 1e-10 * (c[r] - s[r]); /* just inside triangle t */
    }
    const double eye[3] = { vsh_test_rnd(-9, 9), vsh_test_rnd(-9, 9), vsh_test_rnd(2, 9) };
    int truth;
    const int cls = tube_class(&map, &light, s, t, eye, &truth);
    decided += cls != VSH_RT_CLASSIFY_UNDECIDED;
    wrong += cls != VSH_RT_CLASSIFY_UNDECIDED && cls != truth;
  }
  printf("terrain edges: decided %d of 6000, wrong %d\n", decided, wrong);
  CHECK(wrong == 0);
  CHECK(decided > 2000);
  vsh_rt_classify_free(&map);
}

/* A Z-folded sheet (three layers joined by two folds), two spheres that
 * interpenetrate (one placement: each one's rim crosses the other's
 * projection) and an open bowl (boundary edges), finely tessellated (few
 * texels lie inside one triangle), over a floor. */
static void make_folds(void)
{
  count = 0;
  shape = 0;
  const double f[4][3] = { { -3, -3, 0 }, { 3, -3, 0 }, { 3, 3, 0 }, { -3, 3, 0 } };
  add_quad(f[0], f[1], f[2], f[3], VSH_RT_CLASSIFY_CASTS);
  shape = 1;
  /* Layers A (z 1, x -1..1), B (back to x -0.5, rising to 1.2) and C (on
   * to x 1.5, rising to 1.4), each 16 x 24 cells. */
  const double corner[4][2] = { { -1, 1.0 }, { 1, 1.0 }, { -0.5, 1.2 }, { 1.5, 1.4 } };
  for (int layer = 0; layer < 3; ++layer) {
    const double *a = corner[layer], *b = corner[layer + 1];
    for (int i = 0; i < 16; ++i) {
      for (int j = 0; j < 24; ++j) {
        double p[4][3];
        for (int k = 0; k < 4; ++k) {
          const double w = (i + (k & 1)) / 16.0;
          p[k][0] = a[0] + w * (b[0] - a[0]);
          p[k][1] = -1.5 + 0.125 * (j + (k >> 1));
          p[k][2] = a[1] + w * (b[1] - a[1]);
        }
        add_quad(p[0], p[1], p[3], p[2], VSH_RT_CLASSIFY_CASTS);
      }
    }
  }
  shape = 2;
  const double c1[3] = { 1.6, -2.0, 1.2 }, c2[3] = { 2.2, -2.0, 1.3 };
  add_sphere(c1, 0.5, 16, 24);
  add_sphere(c2, 0.5, 16, 24);
  shape = 3;
  for (int i = 8; i < 16; ++i) { /* the lower half of a sphere */
    for (int j = 0; j < 24; ++j) {
      double p[4][3];
      for (int k = 0; k < 4; ++k) {
        const double th = M_PI * (i + (k >> 1)) / 16, ph = 2 * M_PI * (j + (k & 1)) / 24;
        p[k][0] = -2.0 + 0.6 * sin(th) * cos(ph);
        p[k][1] = 2.0 + 0.6 * sin(th) * sin(ph);
        p[k][2] = 1.4 + 0.6 * cos(th);
      }
      add_quad(p[0], p[1], p[3], p[2], VSH_RT_CLASSIFY_CASTS);
    }
  }
}

/* The folds scene under a tilted directional and a point light: every
 * tube decided agrees with the exact ray from its offset origin, on any
 * surface and on the floor in the casters' shadows, where contour edges
 * cross many texels (folds inside the projections, the spheres' rims over
 * each other) and most tubes are still decided shadowed. */
static void test_folds(void)
{
  for (int kind = 0; kind < 2; ++kind) {
    vsh_rt_light light = make_light(kind ? VSH_RT_POINT : VSH_RT_DIRECTIONAL);
    make_folds();
    vsh_rt_classify_map map;
    CHECK(vsh_rt_classify_build(&map, &light, tris, flags, placement, count, 512) == 0);
    int wrong = 0, shadows = 0, decided = 0;
    for (int k = 0; k < 8000; ++k) {
      double s[3], eye[3];
      size_t t = random_point(s, eye);
      if (k % 2) { /* on the floor */
        s[0] = vsh_test_rnd(-3, 3), s[1] = vsh_test_rnd(-3, 3), s[2] = 0;
        t = s[0] - s[1] < 0 ? 1 : 0; /* the floor's triangle holding it */
      }
      int truth;
      const int c = tube_class(&map, &light, s, t, eye, &truth);
      wrong += c != VSH_RT_CLASSIFY_UNDECIDED && c != truth;
      if (k % 2 && truth == VSH_RT_CLASSIFY_SHADOWED) {
        ++shadows;
        decided += c == VSH_RT_CLASSIFY_SHADOWED;
      }
    }
    printf("folds, %s: floor in shadow decided %d of %d, wrong %d\n",
           kind ? "point" : "directional", decided, shadows, wrong);
    CHECK(wrong == 0);
    CHECK(shadows > 200);
    CHECK(decided > 0.9 * shadows);
    vsh_rt_classify_free(&map);
  }
}

static void test_degenerate(void)
{
  vsh_rt_light light = make_light(VSH_RT_DIRECTIONAL);
  vsh_rt_classify_map map;
  /* Nothing casts: every tube lit. */
  CHECK(vsh_rt_classify_build(&map, &light, NULL, NULL, NULL, 0, 64) == 0);
  vsh_rt_classify_tube tube = { { 0, 0, 5 }, { 0, 0, -1 }, 4.9, 5.1, 1e-6, 0 };
  CHECK(vsh_rt_classify_pixel(&map, &tube) == VSH_RT_CLASSIFY_LIT);
  vsh_rt_classify_free(&map);
  /* Bad input: refused, and the map decides nothing. */
  make_scene(1);
  CHECK(vsh_rt_classify_build(&map, &light, tris, flags, placement, count, 8) != 0);
  CHECK(vsh_rt_classify_pixel(&map, &tube) == VSH_RT_CLASSIFY_UNDECIDED);
  vsh_rt_classify_free(&map);
  double bad[9] = { 0, 0, 0, 1, 0, 0, 0, NAN, 0 };
  const unsigned char one = VSH_RT_CLASSIFY_CASTS;
  CHECK(vsh_rt_classify_build(&map, &light, bad, &one, NULL, 1, 64) != 0);
  CHECK(vsh_rt_classify_pixel(&map, &tube) == VSH_RT_CLASSIFY_UNDECIDED);
  vsh_rt_classify_free(&map);
  CHECK(vsh_rt_classify_pixel(NULL, &tube) == VSH_RT_CLASSIFY_UNDECIDED);
  /* A tube across many texels (a depth interval a whole scene long). */
  CHECK(vsh_rt_classify_build(&map, &light, tris, flags, placement, count, 512) == 0);
  vsh_rt_classify_tube wide = { { -8, -8, 1 }, { 0.7071067811865476, 0.7071067811865476, 0 },
                                0, 20, 1e-6, 0 };
  CHECK(vsh_rt_classify_pixel(&map, &wide) == VSH_RT_CLASSIFY_UNDECIDED);
  /* Under the box, far below the floor: the floor covers it. */
  vsh_rt_classify_tube below = { { -1.5, -0.2, -3 }, { 0, 0, -1 }, 0, 1e-4, 1e-7, 0 };
  CHECK(vsh_rt_classify_pixel(&map, &below) == VSH_RT_CLASSIFY_SHADOWED);
  /* Above everything: lit. */
  vsh_rt_classify_tube above = { { 0, 0, 9 }, { 0, 0, -1 }, 0, 1e-4, 1e-7, 0 };
  CHECK(vsh_rt_classify_pixel(&map, &above) == VSH_RT_CLASSIFY_LIT);
  /* An inverted interval. */
  vsh_rt_classify_tube inverted = above;
  inverted.t1 = -1;
  CHECK(vsh_rt_classify_pixel(&map, &inverted) == VSH_RT_CLASSIFY_UNDECIDED);
  vsh_rt_classify_free(&map);
  /* A point light touching the floor: nothing decided. */
  vsh_rt_light at;
  const double h[4] = { 0, 0, 0, 1 }, focal[3] = { 0, 0, -1 };
  CHECK(vsh_rt_light_init(h, focal, 180.0, 0, 0, &at) == VSH_RT_OK);
  CHECK(vsh_rt_classify_build(&map, &at, tris, flags, placement, count, 64) == 0);
  CHECK(map.unusable);
  CHECK(vsh_rt_classify_pixel(&map, &above) == VSH_RT_CLASSIFY_UNDECIDED);
  vsh_rt_classify_free(&map);
  /* A tube behind a point light's face (at the light): undecided. */
  vsh_rt_light point = make_light(VSH_RT_POINT);
  CHECK(vsh_rt_classify_build(&map, &point, tris, flags, placement, count, 64) == 0);
  vsh_rt_classify_tube through = { { 0.5, 0.3, 3.4 }, { 0, 0, 1 }, 0, 0.2, 1e-7, 0 };
  CHECK(vsh_rt_classify_pixel(&map, &through) == VSH_RT_CLASSIFY_UNDECIDED);
  CHECK(vsh_rt_classify_bytes(&map) > 6 * 64 * 64 * 16);
  vsh_rt_classify_free(&map);
}

int main(void)
{
  test_agrees_with_rays();
  test_blocks_agree_with_rays();
  test_valley_floor();
  test_terrain_edges();
  test_folds();
  test_degenerate();
  return vsh_check_report("rt_classify");
}
