/* vsh_mesh_topology.h - the connectivity of a triangle mesh: welded
 * vertices, an edge table that keeps every face using each edge (so open,
 * non-manifold and inconsistently oriented meshes are all represented),
 * closedness, connected components and convexity.
 *
 * Silhouettes (vsh_silhouette.h) and shadow volumes are built on it: a
 * silhouette needs, per edge, the faces on either side and which way each
 * one runs along the edge.
 *
 * Input: positions as x,y,z doubles, triangles as three vertex indices each.
 * The input is only read; the topology copies what it needs and owns its
 * arrays until vsh_mesh_topology_free. Nothing here is VTK or GL.
 *
 * Welding: vertex j is welded to vertex i < j when |p_j - p_i| <= tolerance
 * (Euclidean) and i is not itself welded to an earlier vertex; j takes the
 * smallest such i. Tolerance 0 welds exactly equal positions only (-0 and
 * +0 are equal). Seams (a sphere's first and last meridian, a box's corners
 * repeated per face) become shared vertices, so the edges across them are
 * found. Cost O(n log n) plus the scan of the points in each tolerance cell.
 */
#ifndef VSH_MESH_TOPOLOGY_H
#define VSH_MESH_TOPOLOGY_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Status of every call in vsh_mesh_topology.h and vsh_silhouette.h. */
typedef enum vsh_mesh_status {
  VSH_MESH_OK = 0,
  /* NULL pointer, negative or non-finite tolerance, a non-finite position,
   * a triangle index out of range, a light that is not homogeneous (all
   * zero or non-finite). Outputs are left empty (zeroed). */
  VSH_MESH_INVALID = 1,
  /* More vertices, triangles or edges than 32-bit indices can number. */
  VSH_MESH_TOO_LARGE = 2,
  /* malloc failed. Outputs are left empty (zeroed). */
  VSH_MESH_NO_MEMORY = 3,
  /* The query needs a closed mesh (vsh_mesh_is_convex) and this one is not. */
  VSH_MESH_NOT_CLOSED = 4
} vsh_mesh_status;

/* A short English name of a status ("ok", "invalid input", ...). */
const char *vsh_mesh_status_name(vsh_mesh_status status);

/* "No vertex / component" marker in the index arrays. */
#define VSH_MESH_NONE UINT32_MAX

/* One face's use of an edge. sign = +1 when the face runs a -> b (the edge's
 * own direction, a < b), -1 when it runs b -> a. */
typedef struct vsh_edge_use {
  uint32_t face;
  int32_t sign;
} vsh_edge_use;

/* An undirected edge between welded vertices a < b, with the faces using it.
 * forward (a -> b) and backward (b -> a) count those faces by direction:
 *   closed, consistently oriented 2-manifold edge: forward = backward = 1;
 *   border (open) edge: one face, forward + backward = 1;
 *   non-manifold edge: forward + backward > 2;
 *   inconsistently oriented neighbours: forward = 2 or backward = 2.
 * net = forward - backward is the signed sum of the faces using it. The uses
 * are uses[first_use .. first_use + forward + backward - 1] of the topology,
 * in increasing face order. */
typedef struct vsh_mesh_edge {
  uint32_t a, b;
  uint32_t forward, backward;
  uint32_t first_use;
} vsh_mesh_edge;

typedef struct vsh_mesh_topology {
  /* Welded vertices: their positions (a copy of the representative's),
   * 3 * vertex_count doubles, in increasing order of the representative's
   * input index. Every representative is kept, used by a face or not. */
  size_t vertex_count;
  double *positions;
  /* For each input vertex, its welded vertex. */
  size_t input_vertex_count;
  uint32_t *vertex_of_input;
  /* The triangles over welded vertices, 3 * triangle_count, in input order
   * (degenerate ones included, see below). */
  size_t triangle_count;
  uint32_t *triangles;
  /* Triangles with two equal welded vertices: they have no edges of their
   * own in the table (they bound nothing and have no area) and do not count
   * for `closed`. */
  size_t degenerate_count;
  /* The edges, sorted by (a, b), and their face uses. */
  size_t edge_count;
  vsh_mesh_edge *edges;
  size_t use_count;
  vsh_edge_use *uses;
  /* Connected components (through shared welded vertices) of the vertices
   * that faces use, numbered in order of first appearance in vertex order;
   * component[v] = VSH_MESH_NONE for a vertex no face uses. */
  uint32_t *component;
  size_t component_count;
  /* 1 when the mesh has a non-degenerate triangle and every
   * edge has forward = backward = 1: a closed, consistently oriented
   * 2-manifold (possibly several components, possibly inside-out). */
  int closed;
  /* Edge counts by kind, for statistics and for choosing a safe path. */
  size_t border_edges;       /* one face */
  size_t non_manifold_edges; /* three faces or more */
  size_t misoriented_edges;  /* two faces running the same way */
} vsh_mesh_topology;

/* Builds the topology of `triangle_count` triangles (3 indices each into
 * `vertex_count` positions), welding with `weld_tolerance` (>= 0, absolute,
 * in the positions' units). `out` is overwritten (not freed first); on any
 * status but VSH_MESH_OK it is left zeroed and owns nothing. An empty mesh
 * (no triangles) is VSH_MESH_OK with closed = 0. */
vsh_mesh_status vsh_mesh_topology_build(const double *positions, size_t vertex_count,
                                        const uint32_t *triangles, size_t triangle_count,
                                        double weld_tolerance, vsh_mesh_topology *out);

/* Frees what the topology owns and zeroes it. NULL and zeroed are fine. */
void vsh_mesh_topology_free(vsh_mesh_topology *topology);

/* The welding alone: out_map[i] = the input index of vertex i's
 * representative (out_map[i] = i for representatives), rule as above.
 * out_map has vertex_count entries; *out_representatives (may be NULL)
 * gets how many vertices are their own representative. */
vsh_mesh_status vsh_mesh_weld(const double *positions, size_t vertex_count, double tolerance,
                              uint32_t *out_map, size_t *out_representatives);

/* Whether a closed mesh is convex: one component with a sphere's Euler
 * characteristic (V - E + F = 2, so not two bodies pinched at a vertex),
 * and along every edge the
 * far vertex of the neighbouring triangle is at most `tolerance` (absolute,
 * >= 0) in front of the other triangle's plane, with "in front" meaning
 * outwards (the orientation of the faces decides outwards: an inside-out
 * mesh, negative signed volume, is judged with its faces turned over). A
 * convex closed surface cannot shadow itself. *out_convex = 1 or 0;
 * VSH_MESH_NOT_CLOSED (and *out_convex = 0) when the mesh is not closed. */
vsh_mesh_status vsh_mesh_is_convex(const vsh_mesh_topology *topology, double tolerance,
                                   int *out_convex);

/* Six times the signed volume enclosed by the faces (positive when they
 * face outwards), summed relative to the first vertex of the first face
 * so the result does not lose digits far from the origin. Meaningful for
 * closed meshes; 0 for an empty one. */
double vsh_mesh_signed_volume6(const vsh_mesh_topology *topology);

#ifdef __cplusplus
}
#endif

#endif
