/* vsh_volume_march.h - the light a shadow ray keeps through a volume
 * (a vtkVolume: a scalar field on a regular grid, made translucent by a
 * scalar opacity transfer function), for ray-traced shadows
 * (docs/raytraced-shadows.md, "Volumes").
 *
 * The rule is VTK's own opacity correction: the transfer function gives an
 * opacity a per sample at the "unit distance" u
 * (vtkVolumeProperty::GetScalarOpacityUnitDistance); a step of length ds
 * keeps (1 - a)^(ds / u) of the light. Steps multiply, so a ray keeps
 * T = exp(-sum_i -ln(1 - a_i) ds_i / u): a constant a over a crossing of
 * length L keeps exactly (1 - a)^(L / u), whatever the step.
 *
 * The march samples the ray inside the grid's box at the midpoints of equal
 * steps no longer than the step asked for (half the smallest spacing, by
 * vsh_volume_grid_step), so the steps sum to the crossing's length exactly
 * and a sample never falls outside the box. The samples come from a
 * callback (the VTK layer: the scalar interpolated trilinearly, then looked
 * up in the transfer function's table, the order VTK's mappers use).
 *
 * Pure functions on plain data (no allocation). */
#ifndef VSH_VOLUME_MARCH_H
#define VSH_VOLUME_MARCH_H

#ifdef __cplusplus
extern "C" {
#endif

/* A regular grid of point samples in its data coordinates: point (i, j, k)
 * is at origin + (i, j, k) * spacing; dims are point counts per axis. */
typedef struct vsh_volume_grid {
  double origin[3];
  double spacing[3];
  int dims[3];
} vsh_volume_grid;

/* 1 when the grid has a box to march: finite origin, finite spacing > 0
 * and at least 2 points on every axis; 0 otherwise (zero, negative or NaN
 * spacing, a flat or empty grid). */
int vsh_volume_grid_valid(const vsh_volume_grid *g);

/* The grid's box, [lo, hi] per axis (data coordinates). */
void vsh_volume_grid_box(const vsh_volume_grid *g, double lo[3], double hi[3]);

/* The march's step in data coordinates: half the smallest spacing (a
 * sample at least twice per cell on every axis, as the trilinear field
 * varies per cell). 0 for an invalid grid. */
double vsh_volume_grid_step(const vsh_volume_grid *g);

/* Clips the ray origin + t dir, t in [*t0, *t1], to the box [lo, hi] (slab
 * method; dir need not be unit, a zero component means parallel to that
 * slab pair). Returns 1 and narrows [*t0, *t1] when the ray crosses the box
 * for a positive length; 0 when it misses, only touches it, or any input
 * is NaN. *t1 may be +infinity (a directional light). */
int vsh_volume_clip_ray(const double lo[3], const double hi[3], const double origin[3],
                        const double dir[3], double *t0, double *t1);

/* The field `values` (dims[0] x dims[1] x dims[2], x fastest, as VTK
 * orders point data) interpolated trilinearly at data point p; p is
 * clamped to the grid's box. NaN for an invalid grid or a non-finite p. */
double vsh_volume_trilinear(const vsh_volume_grid *g, const float *values, const double p[3]);

/* A transfer function tabulated at n >= 1 evenly spaced scalars over
 * [lo, hi], linearly interpolated at scalar s. Outside [lo, hi]: the end
 * value with `clamp`, 0 without (vtkPiecewiseFunction's Clamping). NaN s
 * gives 0. */
double vsh_volume_table(const float *table, int n, double lo, double hi, int clamp, double s);

/* The fraction of light a step of length `length` keeps through opacity
 * `alpha` defined at unit distance `unit`: (1 - alpha)^(length / unit).
 * alpha is clamped to [0, 1] (NaN counts as opaque, as vsh_transmit does);
 * a unit that is not finite and > 0 counts as 1; a length that is not
 * finite and >= 0 keeps everything. */
double vsh_volume_kept(double alpha, double length, double unit);

/* The opacity at data point p (inside the grid's box) of one volume. */
typedef double (*vsh_volume_sampler)(void *user, const double p[3]);

/* A shadow ray in the volume's data coordinates: origin + t direction for
 * t in [t_min, t_max], t measured in world length along the ray (the
 * direction is the world unit direction taken into data coordinates, so
 * it is not unit under a scaling matrix); t_max may be +infinity. */
typedef struct vsh_volume_ray {
  double origin[3];
  double direction[3];
  double t_min, t_max;
} vsh_volume_ray;

/* The march's settings: the grid, the opacity unit distance (world
 * length), and the transmittance under which the ray counts as blocked
 * (the march stops and returns 0: below what an 8-bit mask holds, 1/1024
 * in the tracer). */
typedef struct vsh_volume_march_input {
  const vsh_volume_grid *grid;
  double unit;
  double cutoff;
} vsh_volume_march_input;

/* The transmittance in [0, 1] of ray r through the volume: 1 when it
 * misses the box, or the grid is invalid, or any of the ray's values is
 * NaN (nothing to march); else the product of vsh_volume_kept over equal
 * steps of at most vsh_volume_grid_step (in data coordinates) across the
 * box, sampled at their midpoints; 0 once under in->cutoff. *samples (when
 * not null) gets the number of sampler calls. */
double vsh_volume_march(const vsh_volume_march_input *in, const vsh_volume_ray *r,
                        vsh_volume_sampler sample, void *user, int *samples);

#ifdef __cplusplus
}
#endif

#endif
