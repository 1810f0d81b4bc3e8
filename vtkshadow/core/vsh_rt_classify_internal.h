/* vsh_rt_classify_internal.h - what the map's builder and its classifier
 * share (vsh_rt_classify.h): keys and tolerances. */
#ifndef VSH_RT_CLASSIFY_INTERNAL_H
#define VSH_RT_CLASSIFY_INTERNAL_H

#include "vsh_rt_classify.h"
#include "vsh_vec3.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* How far (relative to the map's scale) a triangle's edge may be from
 * where Embree's float copy of it is: every overlap grows and every full
 * cover shrinks by it (64 of the tracer's offsets, ~4e-6 of the scene). */
#define VSH_RT_CLASSIFY_MARGIN (64.0 * VSH_RT_OFFSET_RELATIVE)

/* Planes are grouped by their unit normal rounded to this and their
 * offset rounded to this times the scale: triangles of one group lie
 * within about that of each other's plane, far below the tracer's offset
 * (8 float ulps, ~5e-7 of the scene), so a ray leaving one of them towards
 * the light meets none of the others. */
#define VSH_RT_CLASSIFY_NORMAL_QUANTUM 1e-12
#define VSH_RT_CLASSIFY_OFFSET_QUANTUM 1e-10

/* The most texels a tube's footprint may cover (its box): a longer tube
 * (a far or grazing surface's depth interval) is traced. */
#define VSH_RT_CLASSIFY_MAX_TEXELS 16
/* The same for a block of pixels, and the most it reads texel by texel
 * (beyond, only the 8 x 8 blocks' summaries). */
#define VSH_RT_CLASSIFY_MAX_BLOCK_TEXELS 4096
#define VSH_RT_CLASSIFY_MAX_FINE_TEXELS 256

/* Texel (i, j)'s place in a face's array: blocks of 8 x 8 texels, each
 * block's texels together, so a pixel's neighbours, which land on nearby
 * texels in any direction, mostly read memory already in the cache (a
 * row-major map puts the texel above 20 kB away). n is a multiple of 8. */
static inline size_t vsh_rtc_texel_index(const vsh_rt_classify_face *face, int i, int j)
{
  const size_t block = (size_t)(j >> 3) * (size_t)(face->n >> 3) + (size_t)(i >> 3);
  return 64 * block + (size_t)((j & 7) * 8 + (i & 7));
}

/* Triangle t's unit normal (its winding's) into out; returns the cross
 * product's length, 0 for a degenerate triangle (out = 0). */
static inline double vsh_rtc_unit_normal(const vsh_rt_classify_map *map, size_t t, double out[3])
{
  const double *v = map->triangles + 9 * t;
  double e1[3], e2[3];
  vsh_vec3_sub(v + 3, v, e1);
  vsh_vec3_sub(v + 6, v, e2);
  vsh_vec3_cross(e1, e2, out);
  return vsh_vec3_normalize(out, out);
}

/* Point p (anchor-relative) in face coordinates (x, y, z): x, y along the
 * image plane's axes, z along the face's axis (from the light for a
 * perspective face). */
static inline void vsh_rtc_face_point(const vsh_rt_classify_map *map,
                                      const vsh_rt_classify_face *face, const double p[3],
                                      double out[3])
{
  double q[3];
  for (int r = 0; r < 3; ++r) {
    q[r] = p[r] - (face->perspective ? map->light.position[r] : 0.0);
  }
  out[0] = vsh_vec3_dot(q, face->e1);
  out[1] = vsh_vec3_dot(q, face->e2);
  out[2] = vsh_vec3_dot(q, face->axis);
}

/* The key of depth z along a face's axis: nearer the light is smaller. */
static inline double vsh_rt_classify_key(const vsh_rt_classify_face *face, double z)
{
  return face->perspective ? -1.0 / z : z;
}

/* A triangle clipped to a face and projected: up to 8 vertices (five clip
 * planes) in (u, v) with their keys, and its key plane when it has one. */
#define MAX_VERTICES 8
typedef struct polygon {
  int count;
  double u[MAX_VERTICES], v[MAX_VERTICES], key[MAX_VERTICES];
  double key_min, key_max;
  double umin, umax, vmin, vmax;
  int has_plane; /* key = a u + b v + c over the polygon */
  double a, b, c;
  double area2; /* twice the signed area; 0: seen edge-on */
  double margin; /* world margin in (u, v) units at the polygon */
} polygon;


/* Per-face scratch of one placement's union cover: the texels its opaque
 * triangles overlap (mark bit 1) with their largest far key, and those its
 * contour edges (bit 2) or concave edges (bit 4) cross. */
typedef struct vsh_rtc_scratch {
  float *hi;
  unsigned char *mark;
  size_t *touched;
  size_t count;
} vsh_rtc_scratch;

/* Whether texel [u0, u1] x [v0, v1] overlaps the polygon, the texel
 * grown by the polygon's margin (separating axes). */
int vsh_rtc_overlaps(const polygon *p, double u0, double u1, double v0, double v1);

/* The polygon's key range over the texel (grown by its margin). */
void vsh_rtc_key_range(const polygon *p, double u0, double u1, double v0, double v1, double *lo,
                       double *hi);

/* The texels [range[0], range[1]] x [range[2], range[3]] that a (u, v) box
 * grown by m covers, clamped to the face; 0 when it misses the face. */
int vsh_rtc_texel_range(const vsh_rt_classify_face *face, double umin, double umax, double vmin,
                        double vmax, double m, int range[4]);

float vsh_rtc_round_down(double x);
/* Whether face f's occluders keep every impostor over the footprint
 * [umin, umax] x [vmin, vmax] farther than key_hi (1), or may not (0). */
int vsh_rtc_occluders_clear(const vsh_rt_classify_occluders *occluders,
                            const vsh_rt_classify_face *face, int f, double umin, double umax,
                            double vmin, double vmax, float key_hi);
float vsh_rtc_round_up(double x);
/* Whether face f's occluders may hold an impostor with a key in [key_lo,
 * key_hi] over the footprint (1), or surely not (0). */
int vsh_rtc_occluders_reach(const vsh_rt_classify_occluders *occluders,
                            const vsh_rt_classify_face *face, int f, double umin, double umax,
                            double vmin, double vmax, float key_lo, float key_hi);

/* Triangle `tri` (9 doubles; a segment as (a, b, b)) clipped to the
 * face's frustum and projected: 0 when nothing of it is in the face. */
int vsh_rtc_project(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                    const double *tri, polygon *poly);

/* Triangle t into the face's texels: pass 0 near, full (and the
 * placement's scratch, when given, for opaque casters), pass 1 rest. */
void vsh_rtc_rasterize(vsh_rt_classify_map *map, vsh_rt_classify_face *face, size_t t, int pass,
                       vsh_rtc_scratch *scratch);

/* Segment a-b clipped and projected into the face as a polygon of up to
 * 8 vertices (a, b, b through the triangles' clip), and which two of them
 * are the clipped segment's ends (the farthest apart); 0 when nothing of
 * it is in the face. */
int vsh_rtc_project_segment(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                            const double a[3], const double b[3], polygon *p, int ends[2]);

/* Mark (with `bits`) every texel the segment a-b crosses, each texel
 * grown by at least `margin` (the largest margin its run's triangles
 * overlap texels with: a union's boundary within any overlap's reach is
 * marked). */
void vsh_rtc_mark_segment(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face,
                          const double a[3], const double b[3], double margin,
                          unsigned char bits, vsh_rtc_scratch *scratch);

/* The margin triangle t's projection into the face overlaps texels with
 * (0 when it is not in the face). */
double vsh_rtc_margin(const vsh_rt_classify_map *map, const vsh_rt_classify_face *face, size_t t);

/* Each triangle's plane group (vsh_rt_classify_map.group): the lowest
 * index of the triangles with its rounded plane. Non-zero when out of
 * memory. */
int vsh_rtc_plane_groups(vsh_rt_classify_map *map);

/* Each triangle's unit normal turned towards the light (3 doubles per
 * triangle) and whether it faces the light by VSH_RT_CLASSIFY_MIN_COS over
 * the whole triangle (facing, 1 per triangle). */
void vsh_rtc_light_normals(const vsh_rt_classify_map *map, double *normals,
                           unsigned char *facing);

/* Per edge (3 per triangle, edge k from vertex k to k + 1) of the opaque
 * casters: */
#define VSH_RTC_SMOOTH 0  /* two neighbours, unfolded, not bent towards the light */
#define VSH_RTC_CONTOUR 1 /* bounds the run's projected union: on one triangle
                           * only, on more than two, or folded (both
                           * neighbours on one side of the plane through
                           * the edge and the light) */
#define VSH_RTC_CONCAVE 2 /* unfolded, but one neighbour bends towards the
                           * light over the other's plane */

/* Each run's (one placement's) edges, classed as above, and for the
 * unfolded ones the triangle across (partner, -1 elsewhere). Non-zero
 * when out of memory. */
int vsh_rtc_contours(const vsh_rt_classify_map *map, const int *placements,
                     const double *normals, unsigned char *contour, int *partner);

/* The union cover of every run of one placement into the face's cover_far
 * (pass 0 of its triangles included), and per texel (crossed) whether a
 * contour or a concave edge of any run crosses it (bits below). */
#define VSH_RTC_CROSSED_CONTOUR 1
#define VSH_RTC_CROSSED_CONCAVE 2
int vsh_rtc_cover_face(vsh_rt_classify_map *map, vsh_rt_classify_face *face,
                       const int *placements, const unsigned char *contour,
                       unsigned char *crossed);

/* Whether segment (a, b) meets the box [u0, u1] x [v0, v1]. */
int vsh_rtc_segment_meets_box(const double a[2], const double b[2], double u0, double u1,
                              double v0, double v1);

/* Whether segments (a, b) and (c, d) come within `reach` of each other. */
int vsh_rtc_segments_within(const double a[2], const double b[2], const double c[2],
                            const double d[2], double reach);

/* Per-triangle facts LIT (c)'s layers are found from. */
typedef struct vsh_rtc_layer_input {
  const int *placements;
  const double *normals;       /* vsh_rtc_light_normals */
  const unsigned char *facing; /* vsh_rtc_light_normals */
  const int *partner;          /* vsh_rtc_contours */
  const unsigned char *contour; /* vsh_rtc_contours */
  const unsigned char *crossed; /* vsh_rtc_cover_face, this face's */
} vsh_rtc_layer_input;

/* LIT (c)'s facts of one face: every texel's sheet, the blocks' normal
 * boxes and the concave edges near each block (vsh_rt_classify_sheet.c).
 * Non-zero when out of memory. */
int vsh_rtc_sheet_face(const vsh_rt_classify_map *map, vsh_rt_classify_face *face,
                       const vsh_rtc_layer_input *in);

#endif
