/* vsh_cells_check.c - checks of decoded geometry (after a VTK reader ran):
 * cell arrays whose offsets and point ids are consistent, and finite points.
 * Used for VTP, whose many encodings (inline, appended, base64, compressed)
 * are best checked after vtkXMLPolyDataReader has decoded them, before any
 * filter walks the cells (vtkTriangleFilter crashes on an id past the
 * points). */
#include "vsh_mesh_check_internal.h"

#include <inttypes.h>
#include <math.h>

static int64_t at(const void *a, int is_64bit, size_t i) {
  return is_64bit ? ((const int64_t *)a)[i] : (int64_t)((const int32_t *)a)[i];
}

int vsh_cells_check(const vsh_cell_arrays *c, const char *what, size_t point_count,
                    uint64_t *triangles, char *err, size_t n) {
  size_t cell, k;
  int64_t previous;
  if (c->offset_count == 0) {
    if (c->connectivity_count == 0) return 0;
    return vsh__mc_fail(err, n, "%s connectivity has %zu ids but no offsets", what,
                        c->connectivity_count);
  }
  if (at(c->offsets, c->is_64bit, 0) != 0)
    return vsh__mc_fail(err, n, "%s offsets do not start at 0", what);
  previous = 0;
  for (cell = 0; cell + 1 < c->offset_count; ++cell) {
    const int64_t next = at(c->offsets, c->is_64bit, cell + 1);
    if (next < previous || (uint64_t)next > c->connectivity_count)
      return vsh__mc_fail(err, n, "%s %zu has offset %" PRId64 " after %" PRId64 " (connectivity "
                          "has %zu ids)", what, cell, next, previous, c->connectivity_count);
    for (k = (size_t)previous; k < (size_t)next; ++k) {
      const int64_t id = at(c->connectivity, c->is_64bit, k);
      if (id < 0 || (uint64_t)id >= point_count)
        return vsh__mc_fail(err, n, "%s %zu refers to point %" PRId64 " but the file has %zu",
                            what, cell, id, point_count);
    }
    if (triangles && next - previous >= 3) *triangles += (uint64_t)(next - previous - 2);
    previous = next;
  }
  if ((uint64_t)previous != c->connectivity_count)
    return vsh__mc_fail(err, n, "%s offsets end at %" PRId64 " but connectivity has %zu ids",
                        what, previous, c->connectivity_count);
  if (triangles && *triangles > VSH_MESH_MAX_TRIANGLES)
    return vsh__mc_fail(err, n, "more than %u triangles (the limit)", VSH_MESH_MAX_TRIANGLES);
  return 0;
}

int vsh_points_check_double(const double *xyz, size_t point_count, char *err, size_t n) {
  size_t i;
  if (point_count > VSH_MESH_MAX_POINTS)
    return vsh__mc_fail(err, n, "%zu points, over the limit of %u", point_count,
                        VSH_MESH_MAX_POINTS);
  for (i = 0; i < 3 * point_count; ++i)
    if (!isfinite(xyz[i]))
      return vsh__mc_fail(err, n, "point %zu has a coordinate that is not finite (got %g)", i / 3,
                          xyz[i]);
  return 0;
}

int vsh_points_check_float(const float *xyz, size_t point_count, char *err, size_t n) {
  size_t i;
  if (point_count > VSH_MESH_MAX_POINTS)
    return vsh__mc_fail(err, n, "%zu points, over the limit of %u", point_count,
                        VSH_MESH_MAX_POINTS);
  for (i = 0; i < 3 * point_count; ++i)
    if (!isfinite(xyz[i]))
      return vsh__mc_fail(err, n, "point %zu has a coordinate that is not finite (got %g)", i / 3,
                          (double)xyz[i]);
  return 0;
}
