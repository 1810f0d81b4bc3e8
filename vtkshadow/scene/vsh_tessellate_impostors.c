/* vsh_tessellate_impostors.c - the solids of points drawn as spheres and of
 * a polyline drawn as a tube, for the ray tracers (docs/scene-format.md).
 *
 * VTK draws a tube impostor a constant number of pixels wide, so its world
 * radius grows linearly with depth, and depth is affine along a segment:
 * the tube between two vertices is exactly a cone frustum between their
 * radii. The joints and ends are round (a sphere of the vertex's radius),
 * as Embree's round curves are; the pieces overlap, which a ray tracer
 * does not mind (every piece is closed).
 */
#include "vsh_scene_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* Appends `part` to `all` (both valid meshes); frees `part`. */
static int append(vsh_mesh *all, vsh_mesh *part) {
  vsh_mesh joined;
  size_t i;
  if (vsh__mesh_alloc(&joined, all->point_count + part->point_count,
                      all->triangle_count + part->triangle_count)) {
    vsh_mesh_free(part);
    return -1;
  }
  if (all->point_count) {
    memcpy(joined.points, all->points, 3 * all->point_count * sizeof(double));
    memcpy(joined.normals, all->normals, 3 * all->point_count * sizeof(double));
    memcpy(joined.triangles, all->triangles, 3 * all->triangle_count * sizeof(uint32_t));
  }
  memcpy(joined.points + 3 * all->point_count, part->points,
         3 * part->point_count * sizeof(double));
  memcpy(joined.normals + 3 * all->point_count, part->normals,
         3 * part->point_count * sizeof(double));
  for (i = 0; i < 3 * part->triangle_count; ++i)
    joined.triangles[3 * all->triangle_count + i] =
        part->triangles[i] + (uint32_t)all->point_count;
  vsh_mesh_free(all);
  vsh_mesh_free(part);
  *all = joined;
  return 0;
}

/* The side of the cone frustum from a (radius ra) to b (radius rb): `res`
 * quads, normals tilted by the slope so they are perpendicular to it. */
static int frustum(const double a[3], double ra, const double b[3], double rb, int res,
                   vsh_mesh *m) {
  const size_t n = (size_t)res;
  double axis[3], len, u[3], v[3], slope;
  size_t j, k = 0;
  int i;
  for (i = 0; i < 3; ++i) axis[i] = b[i] - a[i];
  len = vsh__norm3(axis);
  if (!vsh__normalize3(axis, axis) || !(len > 0.0)) return -1;
  vsh__frame_around(axis, u, v);
  /* The outward normal of a cone whose radius shrinks by (ra - rb) over len
   * leans towards b by that slope. */
  slope = (ra - rb) / len;
  if (vsh__mesh_alloc(m, 2 * n, 2 * n)) return -1;
  for (j = 0; j < n; ++j) {
    double t = 2.0 * VSH_PI * (double)j / (double)n, c = cos(t), s = sin(t);
    double d[3], nrm[3], pa[3], pb[3];
    for (i = 0; i < 3; ++i) {
      d[i] = c * u[i] + s * v[i];
      nrm[i] = d[i] + slope * axis[i];
      pa[i] = a[i] + ra * d[i];
      pb[i] = b[i] + rb * d[i];
    }
    vsh__normalize3(nrm, nrm);
    memcpy(m->points + 3 * j, pa, sizeof pa);
    memcpy(m->points + 3 * (n + j), pb, sizeof pb);
    memcpy(m->normals + 3 * j, nrm, sizeof nrm);
    memcpy(m->normals + 3 * (n + j), nrm, sizeof nrm);
  }
  for (j = 0; j < n; ++j) {
    uint32_t j0 = (uint32_t)j, j1 = (uint32_t)((j + 1) % n), top = (uint32_t)n;
    uint32_t *t = m->triangles + 6 * k++;
    t[0] = j0;
    t[1] = j1;
    t[2] = top + j1;
    t[3] = j0;
    t[4] = top + j1;
    t[5] = top + j0;
  }
  return 0;
}

int vsh__tessellate_points(const vsh_object *o, vsh_mesh *out) {
  size_t i;
  memset(out, 0, sizeof *out);
  for (i = 0; i < o->position_count; ++i) {
    vsh_mesh ball;
    if (vsh__sphere_mesh(o->positions + 3 * i, o->radii[i], o->resolution, &ball) ||
        append(out, &ball))
      return -1;
  }
  return out->triangle_count ? 0 : -1;
}

int vsh__tessellate_polyline(const vsh_object *o, vsh_mesh *out) {
  size_t i;
  if (vsh__tessellate_points(o, out)) return -1;
  for (i = 1; i < o->position_count; ++i) {
    vsh_mesh side;
    if (frustum(o->positions + 3 * (i - 1), o->radii[i - 1], o->positions + 3 * i, o->radii[i],
                o->resolution, &side) ||
        append(out, &side))
      return -1;
  }
  return 0;
}
