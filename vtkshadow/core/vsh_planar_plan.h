/* vsh_planar_plan.h - the plain planning behind the planar shadow pass: which
 * (receiver, light) pairs cast, with their oriented plane, camera-relative
 * shadow matrix and caster clip planes; which mask bit each pair owns; which
 * casters need clipping (the others may be drawn as silhouette fans); and the
 * screen rectangle the fans cover. No GL: vtkPlanarShadowPass turns the plan
 * into draw calls.
 *
 * Conventions as in vsh_planar.h (planes (N, d), homogeneous lights) and
 * vsh_mat4.h (row-major matrices, column vectors). Bounds are in VTK's order
 * (xmin, xmax, ymin, ymax, zmin, zmax), world coordinates; "relative"
 * quantities are relative to the eye (the camera position). */
#ifndef VSH_PLANAR_PLAN_H
#define VSH_PLANAR_PLAN_H

#ifdef __cplusplus
extern "C" {
#endif

/* Mask bits: four 32-bit channels, one bit per (receiver, light) pair. */
#define VSH_PLANAR_MAX_PAIRS 128

/* A light of the frame, in the mappers' numbering. */
typedef struct vsh_planar_light {
  double homogeneous[4]; /* (L, 1) for a positional light, (-D, 0) directional */
  int casts;             /* 0 when the pass skips it (headlight, another pass's) */
} vsh_planar_light;

/* One (receiver, light) pair that casts a shadow. */
typedef struct vsh_planar_pair {
  int receiver;        /* index into the receivers */
  int light;           /* index into the lights */
  int bit;             /* receiver * light_count + light: its bit in the mask */
  double plane[4];     /* the receiver's plane, its positive side towards the light */
  double shadow[16];   /* vsh_planar_shadow_matrix_relative(plane, light, eye) */
  double clip[2][4];   /* vsh_planar_caster_clip_planes_relative(plane, light, eye) */
} vsh_planar_pair;

/* Whether one more receiver fits the mask when `receivers` are already taken
 * and the frame has `lights` lights (at least one pair per receiver is
 * counted even without lights). */
int vsh_planar_receiver_fits(int receivers, int lights);

/* 32-bit channels the mask needs: 1 while every pair fits in one (<= 32
 * pairs: a quarter of the bytes to clear, write and read), else 4. */
int vsh_planar_mask_channels(int receivers, int lights);

/* bits = the four 32-bit words of the mask with only bit `bit` set (all zero
 * for a bit outside 0 .. VSH_PLANAR_MAX_PAIRS - 1). */
void vsh_planar_pair_bits(int bit, unsigned int bits[4]);

/* The pairs that cast, receiver-major (receiver 0 with lights 0, 1, ...):
 * `planes` holds 4 doubles per receiver. A pair is left out when its light
 * does not cast, its bit is VSH_PLANAR_MAX_PAIRS or more, or vsh_planar finds
 * no shadow (the light on, behind or parallel to the plane) or bad input.
 * Writes at most `capacity` pairs to `out` and returns how many it wrote;
 * -1 for a null or negative argument. */
int vsh_planar_plan_pairs(const double *planes, int receiver_count,
                          const vsh_planar_light *lights, int light_count, const double eye[3],
                          vsh_planar_pair *out, int capacity);

/* Whether an axis-aligned box (world bounds) lies in the plane within 1e-6 of
 * the box's largest extent: every corner. A caster lying in an explicit
 * receiver plane does not shadow it. */
int vsh_planar_bounds_in_plane(const double bounds[6], const double plane[4]);

/* Whether any corner of the box (world bounds) is cut by one of a pair's
 * camera-relative clip planes (c.(P - eye, 1) <= 0). A box kept whole needs
 * no clipping, and a closed caster in it may be drawn as silhouette fans. */
int vsh_planar_bounds_clipped(const double clip[2][4], const double bounds[6],
                              const double eye[3]);

/* Whether every corner of the box is cut by the same clip plane: all of it
 * behind the receiver or beyond the light, so it casts nothing on the pair. */
int vsh_planar_bounds_culled(const double clip[2][4], const double bounds[6],
                             const double eye[3]);

/* The screen rectangle of a pair's fans in normalized device coordinates, and
 * whether it is the whole viewport (a corner at or behind the camera). */
typedef struct vsh_planar_rect {
  double ndc[4]; /* x0, y0, x1, y1 */
  int full;
} vsh_planar_rect;

/* An empty rectangle. */
void vsh_planar_rect_init(vsh_planar_rect *rect);

/* Grows rect by the box's corners (world bounds) projected by `shadow_dc`
 * (the camera-relative shadow matrix followed by the camera's projection:
 * eye-relative world point to clip space). */
void vsh_planar_rect_add_bounds(vsh_planar_rect *rect, const double shadow_dc[16],
                                const double bounds[6], const double eye[3]);

/* The pixel box (x0, y0, x1, y1; x1, y1 exclusive) of rect in a viewport of
 * `size` pixels, widened by a pixel each side and kept inside the viewport.
 * Returns 1 when it is not empty. */
int vsh_planar_rect_pixels(const vsh_planar_rect *rect, const int size[2], int box[4]);

/* An explicit receiver plane for the receivers' fragment shaders: its normal
 * turned by the view rotation `view` (the view matrix without translation)
 * and its offset relative to the eye. */
void vsh_planar_plane_to_view(const double plane[4], const double view[16], const double eye[3],
                              double out[4]);

#ifdef __cplusplus
}
#endif

#endif
