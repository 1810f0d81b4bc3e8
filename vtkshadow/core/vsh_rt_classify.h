/* vsh_rt_classify.h - a light-space map that decides, without a ray, the
 * pixels whose hard shadow it can prove: ray-traced shadows at the cost of
 * a map (vtkShadowRayTracer traces only the pixels it leaves undecided).
 *
 * A shadow ray of a hard light runs from a surface point q towards the
 * light. Seen from the light (along the light's direction for a
 * directional light, through its position for point and spot lights) that
 * ray is ONE point (u, v) of the light's image plane, and the surfaces it
 * can meet are exactly those whose projection covers (u, v), nearer the
 * light than q. The map is a grid of texels over that plane; every texel
 * holds, from a conservative rasterization of every triangle that
 * overlaps it (an overlap test by separating axes, bounds from the
 * triangle's plane at the texel's corners clamped by its vertices):
 *
 *   near     the smallest key (nearness to the light) of any caster over
 *            the texel;
 *   full     the opaque caster triangle covering the WHOLE texel whose
 *            largest key over it is smallest (-1: none; stored as its
 *            plane group), and full_far that largest key;
 *   cover    the smallest, over the placements (actors) whose opaque
 *            triangles' UNION covers the whole texel, of the largest key
 *            of their triangles over it (vsh_rt_classify_cover.c says how
 *            the union is proved whole: no contour edge crosses it);
 *   rest     the smallest key over the texel of every surface (caster,
 *            translucent or only drawn) not in full's plane;
 *   sheet    where one LAYER of one placement's opaque triangles is
 *            alone near the texel (vsh_rt_classify_sheet.c): the smallest
 *            key over the texel of every other surface, its other layers
 *            included (-inf: no such layer).
 *
 * A pixel's surface point is not known to the map: the depth buffer puts
 * it on a short segment of the pixel's ray (the tracer's depth interval)
 * and the tracer moves the ray's origin a tiny offset off it. The map
 * classifies the whole tube (segment plus offset plus a float margin):
 *
 *   SHADOWED  every texel the tube's footprint touches has a full caster
 *             or a union cover whose far key is nearer than the tube's
 *             nearest point: any origin in the tube has an opaque triangle
 *             across its ray.
 *   LIT (a)   every such texel's near key is farther than the tube's
 *             farthest point: no caster is between any origin and the
 *             light.
 *   LIT (b)   every texel of the footprint has its full triangle in one
 *             plane P and its rest farther than the tube: the pixel's
 *             surface is then in P (any other surface there is behind the
 *             whole tube); P's side towards the camera faces the light
 *             (by at least VSH_RT_CLASSIFY_MIN_COS, and P is not seen
 *             edge-on), so the ray's origin is on the light's side of P,
 *             its ray moves away from P and from everything in P's plane,
 *             and everything else is behind it.
 *   LIT (c)   every texel of the footprint either passes LIT (a) or has
 *             a layer whose sheet is farther than the tube: the pixel's
 *             surface is then on that layer, which over the texel is one
 *             sheet, crossed by none of its placement's contour edges,
 *             the footprint clear of every edge where the layer bends
 *             towards the light (concave), every triangle of the layer
 *             facing the light by VSH_RT_CLASSIFY_MIN_COS;
 *             the camera sees the side facing the light (the 8 x 8 texel
 *             block's box of those triangles' normals against every view
 *             direction). The ray's origin is then on the light's side of
 *             the layer, and the ray, one point of the light's image
 *             plane, meets the layer only once: where it started.
 *   else      undecided: the tracer traces it.
 *
 * Keys: z (distance along the light's direction) for a directional light,
 * -1/z (z along the face's axis) for a perspective face: both grow away
 * from the light along a shadow ray and are linear in (u, v) over a planar
 * triangle, so a triangle's extremes over a convex region are at its
 * corners. Keys are stored in float, rounded outwards.
 *
 * Everything is double precision in an ANCHOR frame fixed when the map is
 * built (the caller's choice, e.g. the casters' centre), independent of
 * the camera: the map stays valid while only the camera moves.
 */
#ifndef VSH_RT_CLASSIFY_H
#define VSH_RT_CLASSIFY_H

#include "vsh_raytrace.h"

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The smallest cosine between P's normal and the light for LIT (b): nearer
 * grazing, the float rounding of the ray's origin can put it under P. */
#define VSH_RT_CLASSIFY_MIN_COS 0.01

/* Per-triangle flags for vsh_rt_classify_build. */
#define VSH_RT_CLASSIFY_CASTS 1       /* an opaque caster: near, full, rest */
#define VSH_RT_CLASSIFY_TRANSLUCENT 2 /* a translucent caster: near, rest */
/* 0: drawn but not a caster: rest only (a pixel may show it). */

/* A pixel's (surface, light) pair, as decided. */
#define VSH_RT_CLASSIFY_UNDECIDED (-1)
#define VSH_RT_CLASSIFY_SHADOWED 0
#define VSH_RT_CLASSIFY_LIT 1
#define VSH_RT_CLASSIFY_OUTSIDE_CONE 2 /* a spot light's cone misses the whole tube */

/* One texel's facts (24 bytes; the classifier reads neighbours together). */
typedef struct vsh_rt_classify_texel {
  float near_key, full_far, rest, cover_far;
  float sheet; /* coarse: the smallest over the block of max(near_key, sheet) */
  int full;    /* the plane group (vsh_rt_classify_map.group) of full, or -1 */
} vsh_rt_classify_texel;

typedef struct vsh_rt_classify_face {
  int perspective;      /* 0: orthographic along axis (directional) */
  double axis[3];       /* the way light travels (orthographic), the face's axis (perspective) */
  double e1[3], e2[3];  /* the image plane's axes: u = p.e1 (/ z), v = p.e2 (/ z) */
  double u0, v0, texel; /* texel (i, j) covers [u0 + i texel, u0 + (i + 1) texel) x ... */
  int n;                /* n x n texels */
  vsh_rt_classify_texel *texels; /* n x n, in 8 x 8 blocks */
  /* Per 8 x 8 block, a conservative summary: the smallest near_key and
   * rest, in full_far the largest key a shadow rule accepts (min of
   * full_far and cover_far), full the group every texel shares (or -1). */
  vsh_rt_classify_texel *coarse;
  /* Per 8 x 8 block, the box (min x, y, z, max x, y, z) of the unit
   * normals, turned towards the light, of the layers LIT (c) may accept. */
  float *normal_box;
  /* Per texel, 1 where LIT (c)'s layer bends towards the light along an
   * edge across it: a footprint there must keep clear of the concave
   * edges listed for its block (bend_list[bend_start[b] ..
   * bend_start[b + 1]), indices into bends: 5 doubles each, the edge's
   * projected ends u0 v0 u1 v1 and its margin). */
  unsigned char *bent;
  int *bend_start, *bend_list;
  double *bends;
} vsh_rt_classify_face;

typedef struct vsh_rt_classify_map {
  vsh_rt_light light;  /* the light, ANCHOR-relative position */
  int faces;           /* 1 (directional, narrow spot) or 6 (point, wide spot) */
  vsh_rt_classify_face face[6];
  double *triangles;   /* 9 per triangle, anchor-relative (a copy) */
  unsigned char *flags; /* per triangle (a copy) */
  int *group;          /* per triangle: the lowest index of its plane's triangles */
  size_t count;
  double scale;        /* the extent of the triangles and the light, for tolerances */
  double near_z;       /* perspective: geometry nearer the light than this clips */
  int unusable;        /* geometry at the light: every pixel undecided */
  double build_seconds;
} vsh_rt_classify_map;

/* Build the map of `light` (anchor-relative) over `count` triangles (9
 * doubles each, anchor-relative) with `flags` per triangle and the
 * placement (an actor drawn somewhere) each belongs to, a placement's
 * triangles one after another (NULL: one placement), `resolution` texels a
 * side (16..8192, a multiple of 8). The map owns copies. Non-zero (map empty, every pixel
 * undecided) on bad input or out of memory. */
int vsh_rt_classify_build(vsh_rt_classify_map *map, const vsh_rt_light *light,
                          const double *triangles, const unsigned char *flags,
                          const int *placements, size_t count, int resolution);

void vsh_rt_classify_free(vsh_rt_classify_map *map);

/* Bytes the map holds. */
size_t vsh_rt_classify_bytes(const vsh_rt_classify_map *map);

/* One pixel's tube, anchor-relative: the points origin + t dir for t in
 * [t0, t1], thickened by `radius` (the largest offset of the ray's origin
 * plus the float margin). */
typedef struct vsh_rt_classify_tube {
  double origin[3];
  double dir[3]; /* unit */
  double t0, t1;
  double radius;
  /* How far before t0 and past t1 a landing on an impostor may move the
   * surface point along dir (the tracer re-traces a pixel that meets a
   * sphere or tube from twice the largest impostor radius before it);
   * 0 without impostors. vsh_rt_classify_tube_init sets 0. */
  double reland;
} vsh_rt_classify_tube;

/* The tube of the pixel ray `ray` (vsh_rt_pixel_ray_init, camera-relative)
 * for a tracer whose points are `magnitude` (the largest magnitude of a
 * coordinate in its float frame, plus the largest instance radius) and
 * whose camera-relative origin is `eye_to_anchor` (eye - anchor) away. The
 * segment covers the depth interval, the slack the tracer keeps its exact
 * landing within, and its float origin; the radius the ray's offset
 * (vsh_rt_offset_distance) and four times that for Embree's float rounding. */
void vsh_rt_classify_tube_init(const vsh_rt_pixel_ray *ray, const double eye_to_anchor[3],
                               double magnitude, vsh_rt_classify_tube *out);

/* The tube's class under the map's light: VSH_RT_CLASSIFY_*. */
int vsh_rt_classify_pixel(const vsh_rt_classify_map *map, const vsh_rt_classify_tube *tube);

/* A block of pixels at once: the hull of 8 anchor-relative corners that
 * holds every point any of its pixels' tubes holds, grown by `radius`, and
 * the unit view directions of its 4 corner pixels (a block whose class is
 * decided costs one call instead of one per pixel and light). */
typedef struct vsh_rt_classify_region {
  double corner[8][3]; /* corner k (near) and k + 4 (far) on pixel ray k */
  double dir[4][3];
  double radius;
  double reland; /* as the tube's, along each corner's ray */
} vsh_rt_classify_region;

/* The region's class: every pixel of the block has it. */
int vsh_rt_classify_block(const vsh_rt_classify_map *map, const vsh_rt_classify_region *region);

/* Spheres, tubes and flat quads (VTK's impostors) are not in the maps:
 * VTK sizes them for the camera, so they change whenever it moves, while
 * the maps are kept. OCCLUDERS stand in for them, built each frame from
 * conservative bounds: per face of a map and per 8 x 8 block of its
 * texels, the smallest key of any impostor whose projection may overlap
 * the block. Each impostor is given as a CAPSULE, the convex hull of two
 * balls (8 doubles, anchor-relative: a[3], ra, b[3], rb): a sphere (a = b),
 * a tube segment (its round cone lies in the hull of its end balls), a
 * quad (its bounding ball).
 *
 * With occluders, a LIT class stands only where every block the footprint
 * touches keeps its impostors farther than the whole tube (or hull): then
 * no impostor is between any origin and the light, and the pixel's surface
 * is not on one (an impostor under the tube has a key at most the tube's),
 * so the triangle rules' reasoning holds with every surface. SHADOWED
 * needs nothing (an opaque triangle is across every origin's ray).
 * Where an impostor may meet the tube grown by its reland distance (a
 * block of its footprint holds impostors whose keys span part of its own),
 * a landing on that impostor may leave the tube: the grown tube is
 * classified instead, which holds every landing (and is then never LIT). */
typedef struct vsh_rt_classify_occluder_face {
  int blocks;       /* blocks a side: the map face's n / 8 */
  float *keys;      /* blocks x blocks row-major, +inf where no impostor */
  float *far_keys;  /* the largest key of those impostors, -inf where none */
  float outside;    /* the smallest key of any impostor projecting beyond the face */
  float outside_far; /* and the largest */
  float everywhere; /* the smallest key of a ball reaching a perspective face's plane */
} vsh_rt_classify_occluder_face;

typedef struct vsh_rt_classify_occluders {
  int faces; /* as the map's */
  vsh_rt_classify_occluder_face face[6];
  size_t count; /* capsules */
} vsh_rt_classify_occluders;

/* Build `out` for `map` over `count` capsules (8 doubles each). Non-zero on
 * bad input or out of memory (then every LIT class is undecided). */
int vsh_rt_classify_occluders_build(vsh_rt_classify_occluders *out,
                                    const vsh_rt_classify_map *map, const double *capsules,
                                    size_t count);
void vsh_rt_classify_occluders_free(vsh_rt_classify_occluders *occluders);

/* vsh_rt_classify_pixel and _block among occluders (NULL: none). */
int vsh_rt_classify_pixel_among(const vsh_rt_classify_map *map,
                                const vsh_rt_classify_occluders *occluders,
                                const vsh_rt_classify_tube *tube);
int vsh_rt_classify_block_among(const vsh_rt_classify_map *map,
                                const vsh_rt_classify_occluders *occluders,
                                const vsh_rt_classify_region *region);

#ifdef __cplusplus
}
#endif

#endif
