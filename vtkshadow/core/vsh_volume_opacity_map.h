/* vsh_volume_opacity_map.h - an opacity shadow map of volumes: per texel
 * of a light-space grid, the light a ray from the light keeps through every
 * volume (vsh_volume_march) and the light distances where the ray enters
 * the first box and leaves the last one. The screen-space techniques
 * (csm's resolve, stencil shadow volumes) multiply a light's visibility by
 * it at every visible pixel (docs/cascaded-shadow-maps.md, "Volumes").
 *
 * The grid covers the volumes' world boxes as the light sees them:
 *   - directional light: an orthographic frame perpendicular to the light's
 *     direction; a texel's ray starts on a plane upstream of every box and
 *     its distance is measured from that plane;
 *   - point or spot light: a perspective frame from the light's position,
 *     its axis towards the boxes' centre; a texel's ray starts at the light
 *     and its distance is the distance from the light.
 * A receiver at light distance d keeps 1 before the entry, T past the exit
 * and T^((d - entry) / (exit - entry)) in between: the optical depth taken
 * as even along the crossing (exact for a constant opacity; the map stores
 * only the total).
 *
 * Coordinates are relative to an origin the caller chooses (the volumes'
 * centre in the VTK layer), in double: the map does not move with the
 * camera, and vsh_volume_opacity_map_view_matrix takes a camera-relative
 * view position into it.
 *
 * Pure functions on plain data (no allocation, no GL). */
#ifndef VSH_VOLUME_OPACITY_MAP_H
#define VSH_VOLUME_OPACITY_MAP_H

#include "vsh_volume_march.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The map's default size per side: a texel per voxel column of a 256-point
 * grid seen face-on. The trilinear field is smooth within a voxel, so more
 * texels add rays (each marching the whole crossing) and no detail for the
 * grids VTK volume renders typically show; 65,536 rays and a 1 MiB float
 * texture per light. */
#define VSH_VOLUME_MAP_SIZE 256

/* A texel whose ray misses every box stores this entry and exit: a
 * receiver is always before it (keeps 1). */
#define VSH_VOLUME_MAP_NONE 3.0e38

/* One volume: its grid, opacity unit distance (world length), the matrix
 * from the caller's frame (world relative to its origin) to the grid's data
 * coordinates (row major 3x4, affine), and its opacity sampler. */
typedef struct vsh_volume_map_volume {
  vsh_volume_grid grid;
  double unit;
  double to_data[12];
  vsh_volume_sampler sample;
  void *user;
} vsh_volume_map_volume;

typedef enum vsh_volume_map_status {
  VSH_VOLUME_MAP_OK = 0,
  VSH_VOLUME_MAP_EMPTY,  /* no volume with a box (none, invalid grids, singular matrices) */
  VSH_VOLUME_MAP_INSIDE, /* a point light inside a box, on it, or seeing them over 160 degrees */
  VSH_VOLUME_MAP_BAD_LIGHT /* a NaN or infinite light, or a zero direction */
} vsh_volume_map_status;

/* The light-space grid. A texel (i, j) covers (s, t) in
 * [lo + (i, j) * (hi - lo) / size, lo + (i + 1, j + 1) * (hi - lo) / size]:
 * (s, t) = (u, v) (world lengths) for a directional light, (u / w, v / w)
 * for a point light, where (u, v, w) = axes (p - eye). */
typedef struct vsh_volume_map_plan {
  int status;
  int size[2];
  int perspective;
  double eye[3];  /* the rays' origin plane (directional) or the light */
  double axes[9]; /* rows u, v, w; w the direction the light travels (axis) */
  double lo[2], hi[2];
} vsh_volume_map_plan;

/* A light as vsh_volume_opacity_map_plan takes it, from its homogeneous
 * world description (position, w) or (direction towards the light, 0):
 * a position becomes (position / w - origin, 1), a direction stays
 * (direction, 0), in the frame of world relative to `origin`. */
void vsh_volume_opacity_map_light(const double homogeneous[4], const double origin[3],
                                  double out[4]);

/* Plans the grid of `size` x `size` texels (size >= 2) over the boxes of
 * the `count` volumes for light `light`: (position, 1) or (direction
 * towards the light, 0) in the caller's frame. The window has a texel of
 * margin on every side, so the rim texels miss the boxes and the map fades
 * to 1 at its edge. Returns the status (also in out->status). */
int vsh_volume_opacity_map_plan(const vsh_volume_map_volume *volumes, int count,
                                const double light[4], int size, vsh_volume_map_plan *out);

/* Fills rows [row0, row1) of the map planned by `plan`: 4 floats per texel,
 * x fastest, row 0 at the lowest t (T, entry, exit, 0). `cutoff`: the
 * transmittance under which a ray counts as blocked (T = 0). Rows may be
 * filled in any order, in parallel (samplers that only read). Returns the
 * number of opacity samples taken. */
long long vsh_volume_opacity_map_fill(const vsh_volume_map_plan *plan,
                                      const vsh_volume_map_volume *volumes, int count,
                                      double cutoff, int row0, int row1, float *texels);

/* The ray of texel (i, j) of an OK plan, in the caller's frame: origin o
 * (on the plane upstream of the boxes for a directional light, the light
 * for a point light) and unit direction d. The fill marches these; the
 * volumes' receiver map (vtkShadowVolumeReceiver) traces them through the
 * opaque casters. */
void vsh_volume_opacity_map_texel_ray(const vsh_volume_map_plan *plan, int i, int j, double o[3],
                                      double d[3]);

/* The light a receiver at light distance d keeps under a texel (T, entry,
 * exit): 1 before the entry, T past the exit, T^((d - entry) / (exit -
 * entry)) in between. The GPU stage computes the same. */
double vsh_volume_opacity_map_kept(const float texel[4], double d);

/* The map's frame for a view position: out (row major 4x4) takes view
 * coordinates (camera at 0, `view_rotation` the world -> view rotation,
 * row major 4x4 without translation) to (u, v, w) relative to plan->eye,
 * where `eye` is the camera's position in the caller's frame. Returns 0
 * (out the identity) for a plan that is not OK. */
int vsh_volume_opacity_map_view_matrix(const vsh_volume_map_plan *plan,
                                       const double view_rotation[16], const double eye[3],
                                       double out[16]);

#ifdef __cplusplus
}
#endif

#endif
