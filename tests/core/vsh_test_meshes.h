/* vsh_test_meshes.h - small meshes the topology and silhouette tests build:
 * a box with its corners repeated per face (as vtkCubeSource makes it, so
 * it needs welding), an open or capped cylinder, a UV sphere with a seam,
 * and transforms of them (offset, scale). Plain arrays, fixed capacity. */
#ifndef VSH_TEST_MESHES_H
#define VSH_TEST_MESHES_H

#include <stdint.h>
#include <string.h>

#define TM_MAX_V 4096
#define TM_MAX_T 8192

typedef struct test_mesh {
  size_t nv, nt;
  double p[3 * TM_MAX_V];
  uint32_t t[3 * TM_MAX_T];
} test_mesh;

static inline uint32_t tm_vertex(test_mesh *m, double x, double y, double z) {
  m->p[3 * m->nv] = x;
  m->p[3 * m->nv + 1] = y;
  m->p[3 * m->nv + 2] = z;
  return (uint32_t)m->nv++;
}

static inline void tm_triangle(test_mesh *m, uint32_t a, uint32_t b, uint32_t c) {
  m->t[3 * m->nt] = a;
  m->t[3 * m->nt + 1] = b;
  m->t[3 * m->nt + 2] = c;
  ++m->nt;
}

/* A quad a b c d (counter-clockwise seen from its front) as two triangles. */
static inline void tm_quad(test_mesh *m, uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
  tm_triangle(m, a, b, c);
  tm_triangle(m, a, c, d);
}

/* Axis-aligned box [lo, hi]^3 per axis, outward faces, 4 own vertices per
 * face (24 vertices, 12 triangles). */
static inline void tm_box(test_mesh *m, const double lo[3], const double hi[3]) {
  for (int axis = 0; axis < 3; ++axis) {
    for (int side = 0; side < 2; ++side) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      uint32_t q[4];
      const double uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
      for (int k = 0; k < 4; ++k) {
        double x[3];
        x[axis] = side ? hi[axis] : lo[axis];
        x[u] = uv[k][0] ? hi[u] : lo[u];
        x[v] = uv[k][1] ? hi[v] : lo[v];
        q[k] = tm_vertex(m, x[0], x[1], x[2]);
      }
      /* (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +axis. */
      if (side)
        tm_quad(m, q[0], q[1], q[2], q[3]);
      else
        tm_quad(m, q[0], q[3], q[2], q[1]);
    }
  }
}

/* Cylinder of radius r, z in [z0, z1], n sides, outward; the seam repeats
 * the first column of vertices. caps != 0 closes both ends with fans. */
static inline void tm_cylinder(test_mesh *m, double r, double z0, double z1, int n, int caps) {
  const uint32_t base = (uint32_t)m->nv;
  for (int i = 0; i <= n; ++i) {
    const double a = 2.0 * 3.14159265358979323846 * (i % n) / n;
    tm_vertex(m, r * cos(a), r * sin(a), z0);
    tm_vertex(m, r * cos(a), r * sin(a), z1);
  }
  for (int i = 0; i < n; ++i)
    tm_quad(m, base + 2 * i, base + 2 * i + 2, base + 2 * i + 3, base + 2 * i + 1);
  if (!caps) return;
  const uint32_t bottom = tm_vertex(m, 0, 0, z0), top = tm_vertex(m, 0, 0, z1);
  for (int i = 0; i < n; ++i) {
    tm_triangle(m, bottom, base + 2 * i + 2, base + 2 * i);
    tm_triangle(m, top, base + 2 * i + 1, base + 2 * i + 3);
  }
}

/* UV sphere (rings x segments), outward, radius r(theta, phi) from
 * radius(): a star-shaped closed surface. Poles are repeated per segment
 * and the seam per ring, so it needs welding; pole triangles are kept as
 * quads' halves (the degenerate halves are left out). */
static inline void tm_sphere(test_mesh *m, int rings, int segments,
                             double (*radius)(int ring, int segment, void *), void *user) {
  const uint32_t base = (uint32_t)m->nv;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j <= segments; ++j) {
      const double th = pi * i / rings, ph = 2 * pi * (j % segments) / segments;
      const int jj = (i == 0 || i == rings) ? 0 : j % segments;
      const double r = radius ? radius(i, jj, user) : 1.0;
      /* Exact poles: sin(pi) is not 0 in double. */
      const double s = (i == 0 || i == rings) ? 0.0 : sin(th);
      const double c = i == 0 ? 1.0 : i == rings ? -1.0 : cos(th);
      tm_vertex(m, r * s * cos(ph), r * s * sin(ph), r * c);
    }
  const uint32_t w = (uint32_t)segments + 1;
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = base + i * w + j, b = base + (i + 1) * w + j;
      if (i != 0) tm_triangle(m, a, b, a + 1);
      if (i != rings - 1) tm_triangle(m, a + 1, b, b + 1);
    }
}

/* p -> p * scale + offset for every vertex from `first` on. */
static inline void tm_transform(test_mesh *m, size_t first, double scale, const double offset[3]) {
  for (size_t i = 3 * first; i < 3 * m->nv; ++i) m->p[i] = m->p[i] * scale + offset[i % 3];
}

#endif
