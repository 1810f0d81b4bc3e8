/* vsh_raytrace.h - the math of ray-traced shadows from a depth buffer.
 *
 * A ray-traced shadow pass rasterizes the scene's depth, turns each pixel's
 * depth back into the surface point it shows, and traces a ray from that
 * point towards each light. This header holds the pure parts, in double
 * precision and CAMERA-RELATIVE (the eye at the origin, world axes):
 *
 *   - vsh_rt_view / vsh_rt_pixel_ray: window depth -> point, and the short
 *     primary ray through the pixel centre that lands exactly on the
 *     triangle (depth quantization puts the depth point slightly off it);
 *   - vsh_rt_offset_*: how far a shadow ray's origin moves off the surface;
 *   - vsh_rt_light_*: the direction and distance to a point, directional or
 *     spot light, the spot cone, and sample points on a light of a given
 *     radius (or angle) for soft shadows;
 *   - vsh_rt_cost_*: a frame's cost estimate from measured rays per second.
 *
 * Matrices follow vsh_mat4.h (row-major, column vectors). Functions returning
 * int return 0 on success; outputs are finite on failure too.
 */
#ifndef VSH_RAYTRACE_H
#define VSH_RAYTRACE_H

#ifdef __cplusplus
extern "C" {
#endif

/* One step of a 24-bit depth buffer, in window depth. */
#define VSH_RT_DEPTH_QUANTUM (1.0 / 16777215.0)

/* A shadow ray starts this far (relative to the magnitude of the
 * coordinates the tracer computes in) off the surface: 8 float ulps, above
 * the rounding of a float ray-triangle hit and of the instance transform (a
 * few ulps), and small because a grazing light moves a shadow's far end by
 * offset / tan(angle to the surface): at 89.9 degrees, 573 times the offset
 * (64 ulps put 5 pixels of a test's floor into the wrong state there). */
#define VSH_RT_OFFSET_RELATIVE (8.0 / 16777216.0)

/* Status codes. */
#define VSH_RT_OK 0
#define VSH_RT_BACKGROUND 1 /* depth 1: nothing drawn at the pixel */
#define VSH_RT_DEGENERATE 2 /* singular camera, w <= 0, non-finite input */

typedef struct vsh_rt_view {
  /* (projection x view rotation)^-1: clip space -> camera-relative world. */
  double inv_clip[16];
  int width, height; /* the viewport in pixels */
} vsh_rt_view;

/* `projection` is eye -> clip (vtkCamera::GetProjectionTransformMatrix(aspect,
 * -1, 1)), `view` is world -> eye (vtkCamera::GetViewTransformMatrix); its
 * translation is ignored, so points come out relative to the eye. Works for
 * perspective and parallel projections. Non-zero (identity) when singular. */
int vsh_rt_view_init(const double projection[16], const double view[16], int width, int height,
                     vsh_rt_view *out);

/* The camera-relative point at pixel coordinates (x, y) (GL window
 * coordinates inside the viewport: the centre of pixel (i, j) is (i + 0.5,
 * j + 0.5), row 0 at the bottom) and window depth `depth` in [0, 1].
 * VSH_RT_DEGENERATE when w <= 0 or the result is not finite (out = 0). */
int vsh_rt_unproject(const vsh_rt_view *view, double x, double y, double depth, double out[3]);

typedef struct vsh_rt_pixel_ray {
  double origin[3];    /* camera-relative, on the near plane (depth 0) */
  double direction[3]; /* unit, into the scene */
  double distance;     /* origin -> the depth point */
  double lo, hi;       /* distances of depth -/+ tolerance, lo <= distance <= hi */
  double point[3];     /* the depth point, origin + distance direction */
} vsh_rt_pixel_ray;

/* The primary ray through the centre of pixel (i, j) (row 0 at the bottom)
 * and the interval of distances along it that window depths within
 * `tolerance` of `depth` cover: a ray limited to [lo, hi] lands on the
 * rasterized triangle, exactly, without reaching a surface further than the
 * depth buffer's error. VSH_RT_BACKGROUND for depth >= 1 (nothing drawn),
 * VSH_RT_DEGENERATE when the camera cannot be inverted there. */
int vsh_rt_pixel_ray_init(const vsh_rt_view *view, int i, int j, double depth, double tolerance,
                          vsh_rt_pixel_ray *out);

/* How far from its interval [lo, hi] a landing on the hit triangle's
 * plane (in double) may fall and still be the pixel's surface: half the
 * interval plus 1e-6 of the distance. vtkShadowRayTracer keeps such a
 * landing, and the classifier's tube reaches that far. */
double vsh_rt_landing_slack(const vsh_rt_pixel_ray *ray);

/* How far past lo the refinement ray's float hit may lie and still count
 * as inside the interval: the interval, 1e-5 of it for the float origin's
 * rounding, and four offsets (vsh_rt_offset_distance) of the distance. */
double vsh_rt_refine_reach(const vsh_rt_pixel_ray *ray);

/* The offset of a shadow ray's origin off a surface whose coordinates (in
 * the tracer's float frame) have magnitude `magnitude`:
 * VSH_RT_OFFSET_RELATIVE * magnitude, and never 0 (a tiny floor of
 * 1e-300). */
double vsh_rt_offset_distance(double magnitude);

/* origin = point + offset * normal (normal unit, on the side facing the light). */
void vsh_rt_offset_origin(const double point[3], const double normal[3], double magnitude,
                          double out[3]);

/* Whether the tracer's float frame may stay at `origin_to_eye` (the eye
 * minus the frame's origin, world units) for a camera whose nearest visible
 * surface is at least `near_distance` from the eye (the near clipping
 * plane). A visible point at distance d from the eye has coordinates of
 * magnitude at most d + |origin_to_eye| in that frame, so its float rounding
 * and the shadow ray's offset (vsh_rt_offset_distance) grow with it: a frame
 * centred on a 2e5-wide scene puts a floor 2 units from the camera at 1e5,
 * offsets its rays by 0.05 and lifts them over the contact shadow of a
 * 1-unit box (hard/near-far-1e6). The frame is usable while
 * |origin_to_eye| <= near_distance, i.e. every visible point keeps at least
 * half the precision of a frame at the eye; else the caller moves the origin
 * to the eye. 0 for non-finite input or near_distance <= 0 unless the origin
 * is the eye. */
int vsh_rt_frame_usable(const double origin_to_eye[3], double near_distance);

/* The world radius of what VTK 9.1's vtkOpenGLPolyDataMapper draws
 * `pixels` wide at world point `p` (row-major `projection` eye -> clip and
 * `view` world -> eye as for vsh_rt_view_init, viewport `width` pixels
 * wide): a point of size `pixels` (a sprite `pixels` across; with
 * RenderPointsAsSpheres a sphere impostor) or a line of width `pixels` (with
 * RenderLinesAsTubes a tube impostor; its geometry shader widens each
 * segment by pixels / 2 either side). Half the width, turned from pixels to
 * world units at p's clip w exactly as the mapper's depth correction does
 * (its ZCalcR uniform is pixels / (width * P00), the impostor radius per
 * unit of w):
 *
 *   radius = pixels * |w| / (width * projection[0][0]),
 *
 * i.e. for a perspective camera pixels * d * tan(view angle / 2) / height
 * (d: p's distance along the view direction, w = d) and for a parallel one
 * pixels * parallel scale / height (w = 1), with VTK's vertical view angle.
 * |w|: a point behind the eye, which VTK does not draw, casts at the size
 * it would have in front (it can still shadow the view). 0 when the input
 * is degenerate (width < 1, P00 == 0, non-finite). */
double vsh_rt_impostor_radius(const double projection[16], const double view[16], int width,
                              double pixels, const double p[3]);

typedef enum vsh_rt_light_kind {
  VSH_RT_DIRECTIONAL = 0,
  VSH_RT_POINT = 1,
  VSH_RT_SPOT = 2
} vsh_rt_light_kind;

typedef struct vsh_rt_light {
  vsh_rt_light_kind kind;
  double position[3];  /* point, spot: camera-relative position */
  double direction[3]; /* directional: unit direction TOWARDS the light; spot: unit axis (the way it shines) */
  double cos_cone;     /* spot: cosine of the cone's half angle (VTK's cone angle) */
  double radius;       /* point, spot: radius of the light's disk (0 = a point) */
  double angle;        /* directional: angular DIAMETER in radians (0 = hard) */
} vsh_rt_light;

/* A light from VTK's description, camera-relative: `homogeneous` is
 * (position - eye, 1) or (direction towards the light, 0) as
 * vtkshadow::LightHomogeneous gives it (minus the eye), `focal` the focal
 * point relative to the eye (spot axis), cone_degrees VTK's cone angle
 * (>= 90 or a directional light: no cone). Non-zero for a zero direction or
 * axis (the light is then a point light / points down -z). */
int vsh_rt_light_init(const double homogeneous[4], const double focal[3], double cone_degrees,
                      double radius, double angle, vsh_rt_light *out);

/* Unit direction from `point` to the light's centre and the distance to it
 * (HUGE_VAL for directional lights). Non-zero when the point is at the
 * light (direction = 0, distance = 0). */
int vsh_rt_light_direction(const vsh_rt_light *light, const double point[3], double dir[3],
                           double *distance);

/* 1 when a spot light reaches the direction `to_light` (from the surface to
 * the light): dot(-to_light, axis) >= cos_cone, as VTK's shader tests it;
 * 1 for point and directional lights. */
int vsh_rt_light_in_cone(const vsh_rt_light *light, const double to_light[3]);

/* Sample k of n on the unit disk: a Vogel (golden-angle) spiral, area
 * uniform and evenly spread for any n, rotated by `rotation` radians (a
 * per-pixel rotation turns banding into noise). n <= 1: the centre. */
void vsh_rt_disk_sample(int k, int n, double rotation, double out[2]);

/* Direction (unit) and distance from `point` to sample k of n of the light:
 * point and spot lights are a disk of `radius` facing the point (as Cycles
 * 3.4 samples them), directional lights the directions
 * normalize(L + tan(angle / 2) disk). With radius / angle 0 or n <= 1 this is
 * vsh_rt_light_direction. Non-zero when the point is at the light. */
int vsh_rt_light_sample(const vsh_rt_light *light, const double point[3], int k, int n,
                        double rotation, double dir[3], double *distance);

/* A rotation in [0, 2 pi) from a pixel's coordinates (integer hash): the
 * same pixel gets the same pattern every frame (no crawling noise). */
double vsh_rt_pixel_rotation(unsigned int x, unsigned int y);

/* The cost of a frame of ray-traced shadows (for auto's choice). */
typedef struct vsh_rt_cost_model {
  double rays_per_second_per_thread; /* occlusion rays, measured */
  double pixel_ns;                   /* per pixel: depth read, reconstruction, upload */
  double frame_ms;                   /* per frame: depth pass set-up, top-level commit */
} vsh_rt_cost_model;

typedef struct vsh_rt_cost_input {
  double pixels;   /* viewport pixels */
  double coverage; /* fraction of them showing geometry a light faces, in [0, 1] */
  int lights;      /* lights traced */
  int samples;     /* rays per pixel and light (1 = hard) */
  int threads;     /* worker threads */
  /* Adaptive ray counts (vsh_rt_adaptive.h): each pixel traces `first`
   * rays, and the rest of `samples` only where they disagree, a `penumbra`
   * fraction of pixels. first 0 (or >= samples): every pixel traces
   * samples. */
  int first;
  double penumbra;
  /* The fraction of (pixel, light) pairs the classifier leaves to rays
   * (vsh_rt_classify.h), in (0, 1]; 0 counts as 1 (no classifier). Its
   * own cost is in the measured rays per second: the rate is the rays
   * traced over the whole stage's time. */
  double traced;
} vsh_rt_cost_input;

/* Conservative defaults (measured on llvmpipe's machine class, one core of
 * a loaded 2-core VM: see docs/raytraced-shadows.md). */
void vsh_rt_cost_model_default(vsh_rt_cost_model *model);

/* Fold a frame's measurement into the model (exponential average, weight
 * 1/4): `rays` traced by `threads` threads in `seconds` of wall time.
 * Ignored when any input is not positive. */
void vsh_rt_cost_model_observe(vsh_rt_cost_model *model, double rays, double seconds,
                               int threads);

/* Rays a frame traces: coverage x pixels x traced x (1 primary refinement
 * ray + lights x rays per pixel), rays per pixel samples, or with adaptive
 * counts first + penumbra x (samples - first). */
double vsh_rt_cost_rays(const vsh_rt_cost_input *input);

/* Estimated milliseconds of shadow work per frame (a moving camera: a still
 * frame costs nothing). Negative inputs count as 0; threads < 1 as 1. */
double vsh_rt_cost_ms(const vsh_rt_cost_model *model, const vsh_rt_cost_input *input);

#ifdef __cplusplus
}
#endif

#endif
