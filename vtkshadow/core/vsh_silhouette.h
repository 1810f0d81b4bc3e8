/* vsh_silhouette.h - silhouette edges of a mesh for a light, with their
 * multiplicity, from the edge table of vsh_mesh_topology.h.
 *
 * Light, homogeneous, in the same coordinates as the topology's positions:
 *   positional (point, spot) at L:              (L, 1), or any (w L, w), w != 0
 *   directional, travelling along D:            (-D, 0)  (towards the light)
 * A triangle (a, b, c) FACES the light when ((b - a) x (c - a)) . (l_xyz -
 * l_w a) > 0 (w taken positive): strictly, so a triangle edge-on to the
 * light, or without area, does not face it.
 *
 * Multiplicity. Every face's boundary is a cycle, so any sum of faces'
 * boundaries is a cycle too; the silhouette is such a sum, and each edge's
 * coefficient in it is its multiplicity m (the edge is listed m times, in
 * the direction that makes m positive):
 *   VSH_SILHOUETTE_LIT_FACES: the boundary of the faces that face the light,
 *     m(a->b) = (lit faces running a->b) - (lit faces running b->a).
 *     For a closed mesh m is 0 or 1 and the edges are the classic
 *     silhouette, oriented as in their lit face. Projected from the light,
 *     the winding number of these loops around a point counts the lit faces
 *     covering it, so it is non-zero exactly on the shadow of a closed mesh.
 *   VSH_SILHOUETTE_BOTH_SIDES: every face turned to face the light,
 *     m(a->b) = sum over faces using a->b or b->a of (+1 facing, -1 not)
 *     times (+1 a->b, -1 b->a). Open and non-manifold meshes: a single quad
 *     facing away still has its border as silhouette (m = 1), and the
 *     winding number counts every face (either side) covering a point, so
 *     it is non-zero exactly on the shadow. A closed mesh gets m = 2 on its
 *     silhouette (each point is behind a lit and an unlit face).
 * Whatever an edge-on face is counted as, the sum stays a cycle and the
 * winding number is unchanged (the face projects to a segment): the
 * degenerate "light in the plane of a face" case needs no special care.
 *
 * Fans: the winding number of a cycle around a point is the signed count
 * of the triangles (centre, from, to) that cover it, for any centre. One
 * centre per connected component (the first silhouette vertex met in it)
 * keeps the fan triangles as small as the component.
 */
#ifndef VSH_SILHOUETTE_H
#define VSH_SILHOUETTE_H

#include "vsh_mesh_topology.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum vsh_silhouette_mode {
  VSH_SILHOUETTE_LIT_FACES = 0,
  VSH_SILHOUETTE_BOTH_SIDES = 1
} vsh_silhouette_mode;

typedef struct vsh_silhouette_edge {
  uint32_t from, to;     /* welded vertices, in the direction of positive m */
  uint32_t multiplicity; /* m >= 1 */
  uint32_t edge;         /* index into the topology's edges */
} vsh_silhouette_edge;

typedef struct vsh_silhouette {
  size_t count;              /* edges with m != 0, in edge-table order */
  vsh_silhouette_edge *edges;
  size_t total_multiplicity; /* sum of m: fan triangles, shadow-volume quads */
} vsh_silhouette;

/* 1 when triangle (v[0], v[1], v[2]) of `positions` faces the light (rule
 * above), else 0. No checks: the caller guarantees valid indices. */
int vsh_triangle_faces_light(const double *positions, const uint32_t v[3], const double light[4]);

/* out_facing[f] = 1 or 0 for every triangle of the topology
 * (triangle_count bytes, caller-owned). VSH_MESH_INVALID for NULL or a
 * light that is non-finite or all zero. */
vsh_mesh_status vsh_silhouette_facing(const vsh_mesh_topology *topology, const double light[4],
                                      unsigned char *out_facing);

/* The silhouette for `light` in `mode`. `out` is overwritten (not freed
 * first) and owns its edges until vsh_silhouette_free; on failure it is
 * left zeroed. */
vsh_mesh_status vsh_silhouette_build(const vsh_mesh_topology *topology, const double light[4],
                                     vsh_silhouette_mode mode, vsh_silhouette *out);

/* 1 when a camera at `eye` (homogeneous like the light: (E, 1), or
 * (towards the camera, 0) for a parallel projection) sees some triangle
 * from the side that does not face the light: the triangle's plane
 * separates eye and light strictly. A volume of a mesh that is not closed
 * needs z-fail exactly then (vtkShadowVolumePass's open_zfail): there the
 * prisms of the faces reach from the surface towards the eye. 0 when no
 * triangle is (degenerate and edge-on ones are skipped); 1, the safe
 * answer, for NULL or an unusable light or eye. */
int vsh_silhouette_seen_unlit(const vsh_mesh_topology *topology, const double light[4],
                              const double eye[4]);

/* Frees the edges and zeroes *silhouette. NULL and zeroed are fine. */
void vsh_silhouette_free(vsh_silhouette *silhouette);

/* The length of the silhouette as the light sees it: each edge without its
 * component along the ray to the light from its middle, times its
 * multiplicity. A mesh's silhouette zig-zags along the light direction
 * across a smooth terminator, and that part does not lengthen the outline
 * of the shadow: this is the length of the outline the caster throws on a
 * surface facing the light. */
vsh_mesh_status vsh_silhouette_length(const vsh_mesh_topology *topology,
                                      const vsh_silhouette *silhouette, const double light[4],
                                      double *out_length);

/* The fan triangles (centre, from, to), welded vertex indices, each
 * silhouette edge repeated `multiplicity` times: 3 * total_multiplicity
 * entries into caller-owned out_triangles. */
vsh_mesh_status vsh_silhouette_fans(const vsh_mesh_topology *topology,
                                    const vsh_silhouette *silhouette, uint32_t *out_triangles);

#ifdef __cplusplus
}
#endif

#endif
