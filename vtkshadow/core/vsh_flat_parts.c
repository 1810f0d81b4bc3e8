/* vsh_flat_parts.c - grouping a mesh's triangles by their plane. */
#include "vsh_flat_parts.h"

#include "vsh_bounds.h"
#include "vsh_vec3.h"

#include <math.h>
#include <stdlib.h>

/* One triangle's plane, quantized into a sort key, with its area. */
typedef struct tri_plane {
  long long key[4];
  double plane[4];
  double area;
} tri_plane;

static int compare_keys(const void *a, const void *b) {
  const tri_plane *x = a, *y = b;
  for (int k = 0; k < 4; ++k) {
    if (x->key[k] != y->key[k]) return x->key[k] < y->key[k] ? -1 : 1;
  }
  return 0;
}

static int compare_area_desc(const void *a, const void *b) {
  const vsh_flat_part *x = a, *y = b;
  return x->area > y->area ? -1 : (x->area < y->area ? 1 : 0);
}

static int same_plane(const double a[4], const double b[4], double normal_tolerance,
                      double offset_tolerance) {
  for (int k = 0; k < 3; ++k) {
    if (fabs(a[k] - b[k]) > normal_tolerance) return 0;
  }
  return fabs(a[3] - b[3]) <= offset_tolerance;
}

/* The diagonal of the points' bounding box; -1 for a non-finite point. */
static double points_size(const double *points, size_t n_points) {
  vsh_bounds box;
  vsh_bounds_init_empty(&box);
  for (size_t i = 0; i < n_points; ++i) {
    if (!vsh_bounds_add_point(&box, points + 3 * i)) return -1.0;
  }
  return vsh_bounds_diagonal_length(&box);
}

/* Each triangle's plane and area, keyed by its quantized plane. Returns
 * the number of triangles with area, or -1 for an index out of range. */
static long long triangle_planes(const double *points, size_t n_points,
                                 const long long *triangles, size_t n_triangles,
                                 double normal_step, double offset_step, tri_plane *out,
                                 double *total_area) {
  long long n = 0;
  *total_area = 0.0;
  for (size_t t = 0; t < n_triangles; ++t) {
    const double *p[3];
    for (int c = 0; c < 3; ++c) {
      const long long i = triangles[3 * t + c];
      if (i < 0 || (size_t)i >= n_points) return -1;
      p[c] = points + 3 * i;
    }
    double e1[3], e2[3], n_raw[3];
    vsh_vec3_sub(p[1], p[0], e1);
    vsh_vec3_sub(p[2], p[0], e2);
    vsh_vec3_cross(e1, e2, n_raw);
    const double twice_area = vsh_vec3_length(n_raw);
    if (!(twice_area > 0.0)) continue;
    tri_plane *tp = &out[n++];
    for (int k = 0; k < 3; ++k) tp->plane[k] = n_raw[k] / twice_area;
    /* The offset through the centroid: the triangle's own rounding spreads
     * evenly around it. */
    double c[3];
    for (int k = 0; k < 3; ++k) c[k] = (p[0][k] + p[1][k] + p[2][k]) / 3.0;
    tp->plane[3] = -vsh_vec3_dot(tp->plane, c);
    tp->area = 0.5 * twice_area;
    *total_area += tp->area;
    for (int k = 0; k < 3; ++k) tp->key[k] = llround(tp->plane[k] / normal_step);
    tp->key[3] = llround(tp->plane[3] / offset_step);
  }
  return n;
}

/* Adds a group (area-weighted plane sums) to the parts, merging it into a
 * kept part on the same plane: one face split by the quantization (a
 * normal on a step boundary) is one part again. */
static int add_group(vsh_flat_part *parts, int count, int capacity, const double sum[4],
                     double area, double normal_tolerance, double offset_tolerance) {
  double plane[4];
  const double len = vsh_vec3_length(sum);
  if (!(len > 0.0)) return count;
  for (int k = 0; k < 3; ++k) plane[k] = sum[k] / len;
  plane[3] = sum[3] / area;
  for (int i = 0; i < count; ++i) {
    if (same_plane(parts[i].plane, plane, 2.0 * normal_tolerance, 2.0 * offset_tolerance)) {
      const double total = parts[i].area + area;
      for (int k = 0; k < 4; ++k) {
        parts[i].plane[k] = (parts[i].plane[k] * parts[i].area + plane[k] * area) / total;
      }
      parts[i].area = total;
      return count;
    }
  }
  if (count == capacity) return count;
  for (int k = 0; k < 4; ++k) parts[count].plane[k] = plane[k];
  parts[count].area = area;
  return count + 1;
}

int vsh_flat_parts(const double *points, size_t n_points, const long long *triangles,
                   size_t n_triangles, double normal_tolerance, double rel_tolerance,
                   double min_fraction, vsh_flat_part *out, int max_parts) {
  if ((n_points && !points) || (n_triangles && !triangles) || (max_parts > 0 && !out) ||
      !(normal_tolerance > 0.0) || !isfinite(normal_tolerance) || !(rel_tolerance > 0.0) ||
      !isfinite(rel_tolerance) || !(min_fraction >= 0.0) || !isfinite(min_fraction)) {
    return -1;
  }
  const double size = points_size(points, n_points);
  if (size < 0.0) return -1;
  if (n_triangles == 0 || max_parts <= 0 || !(size > 0.0)) return 0;
  const double offset_tolerance = rel_tolerance * size;
  tri_plane *tris = malloc(n_triangles * sizeof *tris);
  /* Candidates are groups of at least half the threshold, so at most
   * 2 / min_fraction of them: 64 is room enough for min_fraction >= 1/32. */
  const int capacity = 64;
  vsh_flat_part *parts = malloc(capacity * sizeof *parts);
  if (!tris || !parts) {
    free(tris);
    free(parts);
    return -1;
  }
  double total = 0.0;
  const long long n = triangle_planes(points, n_points, triangles, n_triangles,
                                      normal_tolerance, offset_tolerance, tris, &total);
  int count = 0;
  if (n < 0) {
    count = -1;
  } else if (n > 0) {
    qsort(tris, (size_t)n, sizeof *tris, compare_keys);
    /* Runs of equal keys are groups; only groups big enough alone, or
     * possibly together with a split-off neighbour (half the threshold),
     * are kept as candidates. */
    for (long long i = 0; i < n;) {
      long long j = i;
      double sum[4] = {0, 0, 0, 0}, area = 0.0;
      for (; j < n && compare_keys(&tris[i], &tris[j]) == 0; ++j) {
        for (int k = 0; k < 4; ++k) sum[k] += tris[j].plane[k] * tris[j].area;
        area += tris[j].area;
      }
      if (area >= 0.5 * min_fraction * total) {
        count = add_group(parts, count, capacity, sum, area, normal_tolerance,
                          offset_tolerance);
      }
      i = j;
    }
    qsort(parts, (size_t)count, sizeof *parts, compare_area_desc);
    int kept = 0;
    for (int i = 0; i < count && kept < max_parts; ++i) {
      if (parts[i].area >= min_fraction * total) out[kept++] = parts[i];
    }
    count = kept;
  }
  free(tris);
  free(parts);
  return count;
}
