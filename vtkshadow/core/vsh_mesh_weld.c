/* vsh_mesh_weld.c - welding vertices by position within a tolerance.
 *
 * The points are sorted by the grid cell they fall in (cells twice the
 * tolerance wide); any point within the tolerance of p lies in one of the
 * 27 cells around p's,
 * so each vertex searches only those (binary search in the sorted cells). */
#include "vsh_mesh_topology.h"

#include <math.h>
#include <stdlib.h>

typedef struct weld_entry {
  double cell[3];
  uint32_t index;
} weld_entry;

static int compare_entry(const void *pa, const void *pb) {
  const weld_entry *a = (const weld_entry *)pa, *b = (const weld_entry *)pb;
  for (int k = 0; k < 3; ++k) {
    if (a->cell[k] < b->cell[k]) return -1;
    if (a->cell[k] > b->cell[k]) return 1;
  }
  return (a->index > b->index) - (a->index < b->index);
}

/* Compares a cell with an entry's cell only (index ignored). */
static int compare_cell(const double cell[3], const weld_entry *e) {
  for (int k = 0; k < 3; ++k) {
    if (cell[k] < e->cell[k]) return -1;
    if (cell[k] > e->cell[k]) return 1;
  }
  return 0;
}

/* First entry whose cell is not below `cell`. */
static size_t lower_bound(const weld_entry *entries, size_t n, const double cell[3]) {
  size_t lo = 0, hi = n;
  while (lo < hi) {
    const size_t mid = lo + (hi - lo) / 2;
    if (compare_cell(cell, &entries[mid]) > 0)
      lo = mid + 1;
    else
      hi = mid;
  }
  return lo;
}

/* The cell of a coordinate: the value itself for exact welding, else its
 * slot of twice the tolerance (a double, so huge ratios cannot overflow).
 * Twice: two coordinates within the tolerance are then at most half a cell
 * apart, so the rounding of the division can never put them two cells
 * apart and out of each other's 27-cell reach. */
static double cell_of(double x, double tolerance) {
  return tolerance > 0.0 ? floor(x / (2.0 * tolerance)) : x;
}

static double distance2(const double *p, const double *q) {
  const double d[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
  return d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
}

/* The smallest representative before vertex i within the tolerance in the
 * cell `cell`, or VSH_MESH_NONE. Entries of a cell are in index order, so
 * the first match is the smallest. */
static uint32_t search_cell(const weld_entry *entries, size_t n, const double cell[3],
                            const double *positions, const uint32_t *map, uint32_t i,
                            double tolerance) {
  const double *p = positions + 3 * (size_t)i;
  for (size_t e = lower_bound(entries, n, cell); e < n; ++e) {
    const uint32_t j = entries[e].index;
    if (compare_cell(cell, &entries[e]) != 0 || j >= i) break;
    if (map[j] == j && distance2(p, positions + 3 * (size_t)j) <= tolerance * tolerance)
      return j;
  }
  return VSH_MESH_NONE;
}

static uint32_t find_representative(const weld_entry *entries, size_t n, const double *positions,
                                    const uint32_t *map, uint32_t i, double tolerance) {
  const double *p = positions + 3 * (size_t)i;
  const double home[3] = {cell_of(p[0], tolerance), cell_of(p[1], tolerance),
                          cell_of(p[2], tolerance)};
  const int reach = tolerance > 0.0 ? 1 : 0;
  uint32_t best = VSH_MESH_NONE;
  for (int dx = -reach; dx <= reach; ++dx)
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dz = -reach; dz <= reach; ++dz) {
        const double cell[3] = {home[0] + dx, home[1] + dy, home[2] + dz};
        const uint32_t j = search_cell(entries, n, cell, positions, map, i, tolerance);
        if (j < best) best = j;
      }
  return best;
}

vsh_mesh_status vsh_mesh_weld(const double *positions, size_t vertex_count, double tolerance,
                              uint32_t *out_map, size_t *out_representatives) {
  if (out_representatives) *out_representatives = 0;
  if ((!positions && vertex_count) || (!out_map && vertex_count) || !(tolerance >= 0.0) ||
      !isfinite(tolerance))
    return VSH_MESH_INVALID;
  if (vertex_count >= VSH_MESH_NONE) return VSH_MESH_TOO_LARGE;
  for (size_t i = 0; i < 3 * vertex_count; ++i)
    if (!isfinite(positions[i])) return VSH_MESH_INVALID;
  if (vertex_count == 0) return VSH_MESH_OK;
  weld_entry *entries = (weld_entry *)malloc(vertex_count * sizeof(weld_entry));
  if (!entries) return VSH_MESH_NO_MEMORY;
  for (size_t i = 0; i < vertex_count; ++i) {
    for (int k = 0; k < 3; ++k) entries[i].cell[k] = cell_of(positions[3 * i + k], tolerance);
    entries[i].index = (uint32_t)i;
  }
  qsort(entries, vertex_count, sizeof(weld_entry), compare_entry);
  size_t representatives = 0;
  for (size_t i = 0; i < vertex_count; ++i) {
    const uint32_t j = find_representative(entries, vertex_count, positions, out_map,
                                           (uint32_t)i, tolerance);
    out_map[i] = j == VSH_MESH_NONE ? (uint32_t)i : j;
    representatives += out_map[i] == i;
  }
  free(entries);
  if (out_representatives) *out_representatives = representatives;
  return VSH_MESH_OK;
}
