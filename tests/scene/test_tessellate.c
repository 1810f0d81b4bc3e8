/* test_tessellate.c - primitive tessellation: counts, unit normals, outward
 * counter-clockwise winding, closed surfaces, transforms, analytic areas. */
#include "vsh_check.h"
#include "vsh_scene.h"

#include <stdlib.h>

#define PI 3.14159265358979323846

static const double identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

static void sub(const double *a, const double *b, double *o) {
  o[0] = a[0] - b[0];
  o[1] = a[1] - b[1];
  o[2] = a[2] - b[2];
}
static void cross(const double *a, const double *b, double *o) {
  o[0] = a[1] * b[2] - a[2] * b[1];
  o[1] = a[2] * b[0] - a[0] * b[2];
  o[2] = a[0] * b[1] - a[1] * b[0];
}
static double dot(const double *a, const double *b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static double len(const double *a) { return sqrt(dot(a, a)); }

static vsh_object make(vsh_object_kind kind) {
  vsh_object o;
  memset(&o, 0, sizeof o);
  o.kind = kind;
  memcpy(o.transform, identity, sizeof identity);
  o.casts = 1;
  o.color[0] = o.color[1] = o.color[2] = 1;
  return o;
}

static vsh_object sphere(double r, int res) {
  vsh_object o = make(VSH_OBJECT_SPHERE);
  o.radius = r;
  o.resolution = res;
  return o;
}

static vsh_object cylinder(const double base[3], const double top[3], double r, int res) {
  vsh_object o = make(VSH_OBJECT_CYLINDER);
  memcpy(o.base, base, sizeof o.base);
  memcpy(o.top, top, sizeof o.top);
  o.radius = r;
  o.resolution = res;
  return o;
}

static vsh_object box(const double lo[3], const double hi[3]) {
  vsh_object o = make(VSH_OBJECT_BOX);
  memcpy(o.min, lo, sizeof o.min);
  memcpy(o.max, hi, sizeof o.max);
  return o;
}

static void set_transform(vsh_object *o, const double m[16]) {
  memcpy(o->transform, m, 16 * sizeof(double));
  o->has_transform = 1;
}

typedef struct stats {
  double area, volume; /* volume by the divergence theorem: > 0 iff outward */
  double min_orientation; /* min over triangles and corners of (e1 x e2).n / |e1 x e2| */
  double max_normal_error; /* max | |n| - 1 | */
  int indices_ok;
} stats;

static stats measure(const vsh_mesh *m) {
  stats s;
  size_t t, i;
  s.area = s.volume = 0;
  s.min_orientation = 1;
  s.max_normal_error = 0;
  s.indices_ok = 1;
  for (i = 0; i < m->point_count; ++i) {
    double e = fabs(len(m->normals + 3 * i) - 1);
    if (e > s.max_normal_error) s.max_normal_error = e;
  }
  for (t = 0; t < m->triangle_count; ++t) {
    const uint32_t *tri = m->triangles + 3 * t;
    const double *a, *b, *c;
    double e1[3], e2[3], n[3], bc[3], l;
    int k;
    if (tri[0] >= m->point_count || tri[1] >= m->point_count || tri[2] >= m->point_count) {
      s.indices_ok = 0;
      continue;
    }
    a = m->points + 3 * tri[0];
    b = m->points + 3 * tri[1];
    c = m->points + 3 * tri[2];
    sub(b, a, e1);
    sub(c, a, e2);
    cross(e1, e2, n);
    l = len(n);
    s.area += 0.5 * l;
    cross(b, c, bc);
    s.volume += dot(a, bc) / 6;
    for (k = 0; k < 3; ++k) {
      double o = l > 0 ? dot(n, m->normals + 3 * tri[k]) / l : -1;
      if (o < s.min_orientation) s.min_orientation = o;
    }
  }
  return s;
}

static void test_sphere(void) {
  int res[] = {3, 4, 5, 16, 64, 256};
  double prev_error = 1e9;
  size_t i, k;
  for (i = 0; i < sizeof res / sizeof res[0]; ++i) {
    vsh_object o = sphere(1.5, res[i]);
    vsh_mesh m;
    size_t nlat = res[i] / 2 > 2 ? (size_t)res[i] / 2 : 2;
    stats s;
    double area = 4 * PI * 1.5 * 1.5, error;
    o.center[0] = 1;
    o.center[1] = -2;
    o.center[2] = 3;
    CHECK(vsh_object_tessellate(&o, &m) == 0);
    CHECK(m.point_count == 2 + (nlat - 1) * (size_t)res[i]);
    CHECK(m.triangle_count == 2 * (size_t)res[i] * (nlat - 1));
    s = measure(&m);
    CHECK(s.indices_ok);
    CHECK(s.max_normal_error < 1e-12);
    CHECK(s.min_orientation > 0);
    CHECK(s.volume > 0);
    /* Points on the sphere, normals analytic (p - c) / r. */
    for (k = 0; k < m.point_count; ++k) {
      double d[3];
      sub(m.points + 3 * k, o.center, d);
      CHECK_NEAR(len(d), 1.5, 1e-12);
      CHECK_NEAR(d[0] / 1.5, m.normals[3 * k], 1e-12);
      CHECK_NEAR(d[2] / 1.5, m.normals[3 * k + 2], 1e-12);
    }
    /* Poles are single vertices at exactly +-r on z. */
    CHECK_NEAR(m.points[2], 3 + 1.5, 0);
    CHECK_NEAR(m.points[3 * (m.point_count - 1) + 2], 3 - 1.5, 0);
    /* The area converges to 4 pi r^2 from below as the resolution grows. */
    error = (area - s.area) / area;
    CHECK(error > 0);
    if (res[i] >= 16) CHECK(error < prev_error);
    prev_error = error;
    if (res[i] == 256) {
      CHECK(error < 1e-3);
      CHECK_NEAR(s.volume, 4.0 / 3 * PI * 1.5 * 1.5 * 1.5, 1e-2);
    }
    vsh_mesh_free(&m);
  }
}

static void test_plane(void) {
  vsh_object o = make(VSH_OBJECT_PLANE);
  double o_[3] = {1, 2, 3}, p1[3] = {4, 2, 3}, p2[3] = {1, 2.5, 5};
  double e1[3], e2[3], c[3];
  vsh_mesh m;
  stats s;
  size_t k;
  memcpy(o.origin, o_, sizeof o_);
  memcpy(o.point1, p1, sizeof p1);
  memcpy(o.point2, p2, sizeof p2);
  o.receiver = 1;
  CHECK(vsh_object_tessellate(&o, &m) == 0);
  CHECK(m.point_count == 4 && m.triangle_count == 2);
  s = measure(&m);
  sub(p1, o_, e1);
  sub(p2, o_, e2);
  cross(e1, e2, c);
  CHECK_NEAR(s.area, len(c), 1e-12); /* parallelogram area |e1 x e2| */
  CHECK(s.min_orientation > 1 - 1e-12); /* counter-clockwise seen from the normal side */
  for (k = 0; k < 4; ++k) {
    CHECK_NEAR(m.normals[3 * k + 0], c[0] / len(c), 1e-15);
    CHECK_NEAR(m.normals[3 * k + 1], c[1] / len(c), 1e-15);
    CHECK_NEAR(m.normals[3 * k + 2], c[2] / len(c), 1e-15);
  }
  /* The fourth corner is point1 + point2 - origin. */
  CHECK_NEAR(m.points[6], 4, 0);
  CHECK_NEAR(m.points[7], 2.5, 0);
  CHECK_NEAR(m.points[8], 5, 0);
  vsh_mesh_free(&m);

  /* Degenerate planes are refused (the parser reports them first). */
  memcpy(o.point2, o.point1, sizeof o.point1);
  CHECK(vsh_object_tessellate(&o, &m) != 0);
  CHECK(m.points == NULL && m.point_count == 0);
}

static void test_box(void) {
  double lo[3] = {-1, 0, 2}, hi[3] = {1, 3, 2.5};
  vsh_object o = box(lo, hi);
  vsh_mesh m;
  stats s;
  size_t k;
  CHECK(vsh_object_tessellate(&o, &m) == 0);
  CHECK(m.point_count == 24 && m.triangle_count == 12);
  s = measure(&m);
  CHECK(s.indices_ok);
  CHECK(s.max_normal_error == 0);
  CHECK(s.min_orientation > 1 - 1e-12); /* flat faces: exactly aligned */
  CHECK_NEAR(s.area, 2 * (2 * 3 + 3 * 0.5 + 0.5 * 2), 1e-12);
  CHECK_NEAR(s.volume, 2 * 3 * 0.5, 1e-12);
  /* Normals point away from the centre. */
  for (k = 0; k < 24; ++k) {
    double ctr[3] = {0, 1.5, 2.25}, d[3];
    sub(m.points + 3 * k, ctr, d);
    CHECK(dot(d, m.normals + 3 * k) > 0);
  }
  vsh_mesh_free(&m);
  o.max[1] = o.min[1];
  CHECK(vsh_object_tessellate(&o, &m) != 0);
}

static void test_cylinder(void) {
  double base[3] = {1, 1, 1}, top[3] = {2, 3, 4}, axis[3], h;
  int res[] = {3, 8, 64, 512};
  size_t i, k;
  sub(top, base, axis);
  h = len(axis);
  for (i = 0; i < sizeof res / sizeof res[0]; ++i) {
    vsh_object o = cylinder(base, top, 0.25, res[i]);
    vsh_mesh m;
    stats s;
    size_t n = (size_t)res[i];
    CHECK(vsh_object_tessellate(&o, &m) == 0);
    CHECK(m.point_count == 4 * n + 2 && m.triangle_count == 4 * n);
    s = measure(&m);
    CHECK(s.indices_ok);
    CHECK(s.max_normal_error < 1e-12);
    CHECK(s.min_orientation > 0);
    CHECK(s.volume > 0);
    /* Every point is on a cap disc or at distance r from the axis. */
    for (k = 0; k < m.point_count; ++k) {
      double d[3], c[3], along, radial;
      sub(m.points + 3 * k, base, d);
      along = dot(d, axis) / h;
      cross(d, axis, c);
      radial = len(c) / h;
      CHECK(fabs(along) < 1e-12 || fabs(along - h) < 1e-12);
      CHECK(radial < 1e-12 || fabs(radial - 0.25) < 1e-12);
    }
    if (res[i] == 512) {
      CHECK_NEAR(s.area, 2 * PI * 0.25 * h + 2 * PI * 0.25 * 0.25, 1e-3);
      CHECK_NEAR(s.volume, PI * 0.25 * 0.25 * h, 1e-3);
    }
    vsh_mesh_free(&m);
  }
  {
    vsh_object o = cylinder(base, base, 0.25, 8);
    vsh_mesh m;
    CHECK(vsh_object_tessellate(&o, &m) != 0);
    o = cylinder(base, top, 0.25, 2);
    CHECK(vsh_object_tessellate(&o, &m) != 0);
  }
}

static void test_transform(void) {
  /* Scale 2 then translate (1, 2, 3), row-major. */
  const double st[16] = {2, 0, 0, 1, 0, 2, 0, 2, 0, 0, 2, 3, 0, 0, 0, 1};
  double lo[3] = {0, 0, 0}, hi[3] = {1, 2, 3};
  vsh_object o = sphere(1, 32);
  vsh_mesh m;
  stats s;
  size_t k;
  set_transform(&o, st);
  CHECK(vsh_object_tessellate(&o, &m) == 0);
  s = measure(&m);
  CHECK(s.min_orientation > 0 && s.max_normal_error < 1e-12);
  for (k = 0; k < m.point_count; ++k) {
    double c[3] = {1, 2, 3}, d[3];
    sub(m.points + 3 * k, c, d);
    CHECK_NEAR(len(d), 2, 1e-12);
    CHECK_NEAR(d[0] / 2, m.normals[3 * k], 1e-12); /* uniform scale keeps normals */
  }
  vsh_mesh_free(&m);

  o = box(lo, hi);
  set_transform(&o, st);
  CHECK(vsh_object_tessellate(&o, &m) == 0);
  s = measure(&m);
  CHECK_NEAR(s.volume, 8 * 6, 1e-9);
  for (k = 0; k < m.point_count; ++k) {
    CHECK(m.points[3 * k] == 1 || m.points[3 * k] == 3);
    CHECK(m.points[3 * k + 1] == 2 || m.points[3 * k + 1] == 6);
    CHECK(m.points[3 * k + 2] == 3 || m.points[3 * k + 2] == 9);
  }
  vsh_mesh_free(&m);

  /* Non-uniform scale: normals follow the inverse-transpose, i.e. stay
   * perpendicular to the ellipsoid: n ~ (x/a^2, y/b^2, z/c^2). */
  {
    const double ns[16] = {1, 0, 0, 0, 0, 2, 0, 0, 0, 0, 5, 0, 0, 0, 0, 1};
    o = sphere(1, 48);
    set_transform(&o, ns);
    CHECK(vsh_object_tessellate(&o, &m) == 0);
    s = measure(&m);
    CHECK(s.min_orientation > 0 && s.max_normal_error < 1e-12 && s.volume > 0);
    for (k = 0; k < m.point_count; ++k) {
      const double *p = m.points + 3 * k;
      double g[3] = {p[0], p[1] / 4, p[2] / 25}, c[3];
      cross(g, m.normals + 3 * k, c);
      CHECK(len(c) / len(g) < 1e-12);
      CHECK(dot(g, m.normals + 3 * k) > 0);
    }
    vsh_mesh_free(&m);
  }

  /* A mirror keeps normals outward and the winding counter-clockwise. */
  {
    const double mirror[16] = {-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const double shear[16] = {1, 0.5, 0, 0, 0, 1, 0.25, 0, 0, 0, -3, 1, 0, 0, 0, 1};
    const double *ms[2] = {mirror, shear};
    int j;
    for (j = 0; j < 2; ++j) {
      double b0[3] = {0, 0, 0}, b1[3] = {0, 0, 2};
      vsh_object objs[3];
      int q;
      objs[0] = sphere(1, 16);
      objs[1] = box(lo, hi);
      objs[2] = cylinder(b0, b1, 1, 16);
      for (q = 0; q < 3; ++q) {
        set_transform(&objs[q], ms[j]);
        CHECK(vsh_object_tessellate(&objs[q], &m) == 0);
        s = measure(&m);
        CHECK(s.min_orientation > 0);
        CHECK(s.volume > 0);
        CHECK(s.max_normal_error < 1e-12);
        vsh_mesh_free(&m);
      }
    }
  }

  /* vsh_mesh_transform on its own, with identity: nothing moves. */
  o = sphere(1, 8);
  CHECK(vsh_object_tessellate(&o, &m) == 0);
  {
    double before = m.points[5];
    vsh_mesh_transform(&m, identity);
    CHECK(m.points[5] == before);
  }
  vsh_mesh_free(&m);
  vsh_mesh_free(&m); /* freeing twice is harmless: free zeroes the struct */
}

/* Regressions found by the mutation fuzzer: extreme but valid scales must
 * still give unit normals with the right direction. */
static void test_extreme_scales(void) {
  const double aniso[16] = {1e200, 0, 0, 0, 0, 1e-200, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  double lo[3] = {-1, -1, -1}, hi[3] = {1, 1, 1};
  double scales[2] = {1e200, 1e-200};
  vsh_object o = box(lo, hi);
  vsh_mesh m;
  size_t k;
  int i;
  set_transform(&o, aniso);
  CHECK(vsh_object_tessellate(&o, &m) == 0);
  for (k = 0; k < m.point_count; ++k) {
    const double *n = m.normals + 3 * k;
    CHECK_NEAR(len(n), 1, 1e-12);
    /* Axis-aligned scale: face normals stay on their axis, same sign as before. */
    CHECK(fabs(n[0]) == 1 || fabs(n[1]) == 1 || fabs(n[2]) == 1);
  }
  vsh_mesh_free(&m);
  o = sphere(1, 16);
  set_transform(&o, aniso);
  CHECK(vsh_object_tessellate(&o, &m) == 0);
  for (k = 0; k < m.point_count; ++k) CHECK_NEAR(len(m.normals + 3 * k), 1, 1e-12);
  vsh_mesh_free(&m);

  for (i = 0; i < 2; ++i) {
    vsh_object p = make(VSH_OBJECT_PLANE);
    p.point1[0] = scales[i];
    p.point2[1] = scales[i];
    CHECK(vsh_object_tessellate(&p, &m) == 0);
    if (m.normals) {
      CHECK_NEAR(m.normals[2], 1, 0);
      CHECK_NEAR(m.normals[0], 0, 0);
    }
    vsh_mesh_free(&m);
  }
}

/* Points: one closed outward sphere per position, of its radius; a
 * polyline adds an outward frustum per segment whose ends have the
 * vertices' radii. */
static void test_impostor_solids(void) {
  double pos[9] = {0, 0, 0, 4, 0, 0, 4, 3, 0}, radii[3] = {1, 0.5, 0.25};
  vsh_object o = make(VSH_OBJECT_POINTS);
  vsh_mesh m;
  stats st;
  size_t i, near_a = 0, near_b = 0;
  o.positions = pos;
  o.radii = radii;
  o.position_count = 3;
  o.resolution = 32;
  CHECK(vsh_object_tessellate(&o, &m) == 0);
  st = measure(&m);
  CHECK(st.indices_ok && st.min_orientation > 0.9 && st.max_normal_error < 1e-12);
  /* three inscribed UV spheres: just under the sum of the balls' volumes */
  {
    const double balls = 4.0 / 3.0 * PI * (1 + 0.125 + 0.015625);
    CHECK(st.volume < balls && st.volume > 0.97 * balls);
  }
  for (i = 0; i < m.point_count; ++i) {
    const double *p = m.points + 3 * i;
    double d0 = len(p), q[3] = {p[0] - 4, p[1], p[2]};
    if (fabs(d0 - 1) < 1e-12) ++near_a;
    if (fabs(len(q) - 0.5) < 1e-12) ++near_b;
  }
  CHECK(near_a > 0 && near_b > 0 && near_a + near_b < m.point_count);
  vsh_mesh_free(&m);

  o.kind = VSH_OBJECT_POLYLINE;
  CHECK(vsh_object_tessellate(&o, &m) == 0);
  st = measure(&m);
  CHECK(st.indices_ok && st.min_orientation > 0.5 && st.max_normal_error < 1e-12);
  {
    /* the frustums (sides only, their ends lie inside the balls): 2 rings of
     * 32 per segment, the first ring on the circle of radius 1 around the
     * first vertex, the last on the circle of 0.25 around the last */
    const size_t balls = 3 * (2 + 15 * 32);
    const double *first = m.points + 3 * balls, *last = m.points + 3 * (m.point_count - 1);
    double q[3] = {last[0] - 4, last[1] - 3, last[2]};
    CHECK(m.point_count == balls + 2 * 2 * 32);
    CHECK(fabs(len(first) - 1) < 1e-12 && fabs(first[0]) < 1e-12);
    CHECK(fabs(len(q) - 0.25) < 1e-12 && fabs(q[1]) < 1e-12);
  }
  vsh_mesh_free(&m);

  /* a zero-length segment has no frustum axis */
  pos[3] = pos[0];
  pos[4] = pos[1];
  pos[5] = pos[2];
  CHECK(vsh_object_tessellate(&o, &m) != 0);
  o.kind = VSH_OBJECT_VOLUME; /* no surface */
  CHECK(vsh_object_tessellate(&o, &m) != 0);
}

static void test_refusals(void) {
  vsh_object o = make(VSH_OBJECT_MESH);
  vsh_mesh m;
  CHECK(vsh_object_tessellate(&o, &m) != 0);
  CHECK(m.points == NULL && m.triangles == NULL && m.point_count == 0);
  o = sphere(1, 2);
  CHECK(vsh_object_tessellate(&o, &m) != 0);
  o = sphere(0, 8);
  CHECK(vsh_object_tessellate(&o, &m) != 0);
  o = sphere(1, 8);
  CHECK(vsh_object_tessellate(&o, NULL) != 0);
  CHECK(vsh_object_tessellate(NULL, &m) != 0);
}

int main(void) {
  test_sphere();
  test_plane();
  test_box();
  test_cylinder();
  test_transform();
  test_extreme_scales();
  test_impostor_solids();
  test_refusals();
  return vsh_check_report("scene.tessellate");
}
