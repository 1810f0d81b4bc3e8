/* vsh_tessellate.c - primitives -> triangles, in double precision.
 *
 * Every renderer (VTK, POV-Ray, Cycles) draws the triangles made here rather
 * than its own native sphere or cylinder, so a comparison measures shadow
 * algorithms and not differences in tessellation. Conventions, checked by
 * tests/scene/test_tessellate.c:
 *   - triangles are counter-clockwise seen from outside (from the normal side);
 *   - normals are unit length: analytic on curved surfaces, flat on faces;
 *   - the object's transform is applied last (vsh_mesh_transform).
 */
#include "vsh_scene_internal.h"

#include <math.h>
#include <string.h>

static void put(vsh_mesh *m, size_t i, const double p[3], const double n[3]) {
  memcpy(m->points + 3 * i, p, 3 * sizeof(double));
  memcpy(m->normals + 3 * i, n, 3 * sizeof(double));
}

static void tri(vsh_mesh *m, size_t *k, size_t a, size_t b, size_t c) {
  uint32_t *t = m->triangles + 3 * (*k)++;
  t[0] = (uint32_t)a;
  t[1] = (uint32_t)b;
  t[2] = (uint32_t)c;
}

static int valid_resolution(int r) { return r >= 3 && r <= 4096; }

/* UV sphere around the z axis: `res` meridians, max(2, res/2) latitude bands,
 * a single vertex at each pole (no seam: there are no texture coordinates). */
static int sphere(const vsh_object *o, vsh_mesh *m) {
  const size_t nlon = (size_t)o->resolution;
  const size_t nlat = o->resolution / 2 > 2 ? (size_t)(o->resolution / 2) : 2;
  const size_t rings = nlat - 1, south = 1 + rings * nlon;
  size_t r, j, k = 0;
  double n[3], p[3];
  if (!valid_resolution(o->resolution) || !(o->radius > 0.0) || !isfinite(o->radius)) return -1;
  if (vsh__mesh_alloc(m, 2 + rings * nlon, 2 * nlon * rings)) return -1;

  for (r = 0; r <= nlat; ++r) {
    double phi = VSH_PI * (double)r / (double)nlat;
    /* Exact poles and equator-symmetric rings: sin(pi) is not 0 in floating point. */
    double sp = (r == 0 || r == nlat) ? 0.0 : sin(phi);
    double cp = r == 0 ? 1.0 : r == nlat ? -1.0 : cos(phi);
    for (j = 0; j < ((r == 0 || r == nlat) ? 1 : nlon); ++j) {
      double theta = 2.0 * VSH_PI * (double)j / (double)nlon;
      size_t idx = r == 0 ? 0 : r == nlat ? south : 1 + (r - 1) * nlon + j;
      n[0] = sp * cos(theta);
      n[1] = sp * sin(theta);
      n[2] = cp;
      p[0] = o->center[0] + o->radius * n[0];
      p[1] = o->center[1] + o->radius * n[1];
      p[2] = o->center[2] + o->radius * n[2];
      put(m, idx, p, n);
    }
  }
  for (j = 0; j < nlon; ++j) {
    size_t j1 = (j + 1) % nlon;
    tri(m, &k, 0, 1 + j, 1 + j1); /* north cap */
    for (r = 0; r + 1 < rings; ++r) {
      size_t a = 1 + r * nlon, b = a + nlon; /* ring r above ring r+1 */
      tri(m, &k, a + j, b + j, b + j1);
      tri(m, &k, a + j, b + j1, a + j1);
    }
    tri(m, &k, 1 + (rings - 1) * nlon + j, south, 1 + (rings - 1) * nlon + j1); /* south cap */
  }
  return 0;
}

/* Two triangles over the parallelogram origin, point1, point1+point2-origin, point2. */
static int plane(const vsh_object *o, vsh_mesh *m) {
  double e1[3], e2[3], c[3], n[3], q[3];
  size_t k = 0;
  int i;
  for (i = 0; i < 3; ++i) {
    e1[i] = o->point1[i] - o->origin[i];
    e2[i] = o->point2[i] - o->origin[i];
    q[i] = o->origin[i] + e1[i] + e2[i];
  }
  /* Cross the unit edges, not the raw ones: with edges of 1e200 or 1e-200
   * the raw cross product overflows or underflows (found by fuzzing). */
  if (!vsh__normalize3(e1, e1) || !vsh__normalize3(e2, e2)) return -1;
  vsh__cross3(e1, e2, c);
  if (!vsh__normalize3(c, n)) return -1;
  if (vsh__mesh_alloc(m, 4, 2)) return -1;
  put(m, 0, o->origin, n);
  put(m, 1, o->point1, n);
  put(m, 2, q, n);
  put(m, 3, o->point2, n);
  tri(m, &k, 0, 1, 2);
  tri(m, &k, 0, 2, 3);
  return 0;
}

/* Six faces of four vertices each (flat normals need unshared corners). */
static int box(const vsh_object *o, vsh_mesh *m) {
  size_t k = 0, v = 0;
  int axis, sign, i;
  for (i = 0; i < 3; ++i)
    if (!(o->min[i] < o->max[i])) return -1;
  if (vsh__mesh_alloc(m, 24, 12)) return -1;
  for (axis = 0; axis < 3; ++axis) {
    for (sign = -1; sign <= 1; sign += 2) {
      /* (a, b, axis) is a right-handed permutation, so walking (0,0) (1,0)
       * (1,1) (0,1) in (a, b) is counter-clockwise seen from +axis. */
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      static const int ccw[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      double n[3] = {0.0, 0.0, 0.0};
      int c;
      n[axis] = (double)sign;
      for (c = 0; c < 4; ++c) {
        /* Seen from -axis the same walk is clockwise: swap the roles of a and b. */
        int ua = sign > 0 ? ccw[c][0] : ccw[c][1], ub = sign > 0 ? ccw[c][1] : ccw[c][0];
        double p[3];
        p[axis] = sign > 0 ? o->max[axis] : o->min[axis];
        p[a] = ua ? o->max[a] : o->min[a];
        p[b] = ub ? o->max[b] : o->min[b];
        put(m, v + (size_t)c, p, n);
      }
      tri(m, &k, v, v + 1, v + 2);
      tri(m, &k, v, v + 2, v + 3);
      v += 4;
    }
  }
  return 0;
}

/* Capped cylinder from base to top: a side of `res` quads with radial normals,
 * and two fans with flat normals (caps and side do not share vertices). */
static int cylinder(const vsh_object *o, vsh_mesh *m) {
  const size_t n = (size_t)o->resolution;
  const size_t side_top = n, top_c = 2 * n, top_r = 2 * n + 1, bot_c = 3 * n + 1,
               bot_r = 3 * n + 2;
  double axis[3], a[3], u[3], v[3], na[3];
  size_t j, k = 0;
  int i;
  if (!valid_resolution(o->resolution) || !(o->radius > 0.0) || !isfinite(o->radius)) return -1;
  for (i = 0; i < 3; ++i) axis[i] = o->top[i] - o->base[i];
  if (!vsh__normalize3(axis, a)) return -1;
  vsh__frame_around(a, u, v);
  if (vsh__mesh_alloc(m, 4 * n + 2, 4 * n)) return -1;

  for (i = 0; i < 3; ++i) na[i] = -a[i];
  put(m, top_c, o->top, a);
  put(m, bot_c, o->base, na);
  for (j = 0; j < n; ++j) {
    double theta = 2.0 * VSH_PI * (double)j / (double)n, c = cos(theta), s = sin(theta);
    double d[3], pb[3], pt[3];
    for (i = 0; i < 3; ++i) {
      d[i] = c * u[i] + s * v[i];
      pb[i] = o->base[i] + o->radius * d[i];
      pt[i] = o->top[i] + o->radius * d[i];
    }
    put(m, j, pb, d);
    put(m, side_top + j, pt, d);
    put(m, top_r + j, pt, a);
    put(m, bot_r + j, pb, na);
  }
  for (j = 0; j < n; ++j) {
    size_t j1 = (j + 1) % n;
    tri(m, &k, side_top + j, j, j1);
    tri(m, &k, side_top + j, j1, side_top + j1);
    tri(m, &k, top_c, top_r + j, top_r + j1);
    tri(m, &k, bot_c, bot_r + j1, bot_r + j);
  }
  return 0;
}

int vsh__sphere_mesh(const double center[3], double radius, int resolution, vsh_mesh *out) {
  vsh_object o;
  memset(&o, 0, sizeof o);
  memcpy(o.center, center, sizeof o.center);
  o.radius = radius;
  o.resolution = resolution;
  return sphere(&o, out);
}

int vsh_object_tessellate(const vsh_object *object, vsh_mesh *out) {
  int rc;
  if (!out) return -1;
  memset(out, 0, sizeof *out);
  if (!object) return -1;
  switch (object->kind) {
  case VSH_OBJECT_SPHERE: rc = sphere(object, out); break;
  case VSH_OBJECT_PLANE: rc = plane(object, out); break;
  case VSH_OBJECT_BOX: rc = box(object, out); break;
  case VSH_OBJECT_CYLINDER: rc = cylinder(object, out); break;
  case VSH_OBJECT_POINTS: rc = vsh__tessellate_points(object, out); break;
  case VSH_OBJECT_POLYLINE: rc = vsh__tessellate_polyline(object, out); break;
  default: return -1; /* meshes are read by VTK in the C++ layer; a volume has no surface */
  }
  if (rc) {
    vsh_mesh_free(out);
    return rc;
  }
  if (object->has_transform) vsh_mesh_transform(out, object->transform);
  return 0;
}
