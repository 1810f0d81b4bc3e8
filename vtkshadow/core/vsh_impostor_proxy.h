/* vsh_impostor_proxy.h - closed triangle meshes standing in for the spheres
 * and tubes VTK draws as screen-space impostors (RenderPointsAsSpheres,
 * RenderLinesAsTubes), for the techniques that cast triangles (csm, planar,
 * volume): raytrace casts true spheres and round curves instead
 * (vsh_rt_impostor_radius gives the radius both use).
 *
 * A sphere is the icosahedron subdivided once (42 vertices, 80 triangles);
 * a segment is a truncated cone of VSH_PROXY_TUBE_SIDES sides with flat caps
 * (joints and ends get a sphere each, as Embree's round curves have). Every
 * mesh is closed and wound counter-clockwise seen from outside, so shadow
 * volumes and silhouette fans can count it.
 *
 * The proxy's size: a polyhedron inside the true sphere casts too small a
 * shadow, one around it too large. By Cauchy's formula the mean projected
 * area of a convex body is a quarter of its surface area, so scaling the
 * unit icosphere (circumradius 1) by sqrt(4 pi / area) gives it the sphere's
 * silhouette area on average over directions: its vertices then lie at 1.0379
 * radii and its faces at 0.9696 (-3.0 % .. +3.8 %). Likewise the tube's
 * polygon is scaled to the circle's mean width (its perimeter / pi):
 * vertices at 1.0115 radii, edges at 0.9770 (12 sides). */
#ifndef VSH_IMPOSTOR_PROXY_H
#define VSH_IMPOSTOR_PROXY_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define VSH_PROXY_SPHERE_VERTICES 42
#define VSH_PROXY_SPHERE_TRIANGLES 80
#define VSH_PROXY_TUBE_SIDES 12
#define VSH_PROXY_TUBE_VERTICES (2 * VSH_PROXY_TUBE_SIDES)
/* The side's two triangles per side and each cap's fan of sides - 2. */
#define VSH_PROXY_TUBE_TRIANGLES (2 * VSH_PROXY_TUBE_SIDES + 2 * (VSH_PROXY_TUBE_SIDES - 2))

/* The unit shapes, computed once by vsh_proxy_shapes_init. */
typedef struct vsh_proxy_shapes {
  double sphere[3 * VSH_PROXY_SPHERE_VERTICES]; /* already scaled (see above) */
  uint32_t sphere_triangles[3 * VSH_PROXY_SPHERE_TRIANGLES];
  double ring[2 * VSH_PROXY_TUBE_SIDES]; /* cos, sin of each side, scaled */
  double sphere_scale;                    /* sqrt(4 pi / icosphere area) */
  double tube_scale;                      /* pi / (n sin(pi / n)) */
} vsh_proxy_shapes;

void vsh_proxy_shapes_init(vsh_proxy_shapes *shapes);

/* A sphere proxy of `radius` about `centre`: VSH_PROXY_SPHERE_VERTICES
 * positions (x y z) into `vertices` and VSH_PROXY_SPHERE_TRIANGLES
 * triangles (3 indices each, `base` added: the first vertex's index in the
 * caller's buffer) into `triangles`. */
void vsh_proxy_sphere(const vsh_proxy_shapes *shapes, const double centre[3], double radius,
                      double *vertices, uint32_t *triangles, uint32_t base);

/* A truncated cone from `a` (radius ra) to `b` (radius rb):
 * VSH_PROXY_TUBE_VERTICES positions and VSH_PROXY_TUBE_TRIANGLES
 * triangles as above. `turn` odd turns the ring by half a side, so that
 * the rings of two collinear segments meeting at a joint never coincide
 * (a welded ring would join four triangles at an edge: not closed any
 * more). Returns 0 and writes nothing when a == b or the input is not
 * finite: the spheres at the ends cover such a segment. */
int vsh_proxy_tube(const vsh_proxy_shapes *shapes, const double a[3], double ra, const double b[3],
                   double rb, int turn, double *vertices, uint32_t *triangles, uint32_t base);

/* The flat shapes VTK draws for plain points and lines (without
 * RenderPointsAsSpheres / RenderLinesAsTubes), as world quads: a point of
 * size s is a square sprite s pixels wide parallel to the image plane, a
 * line of width s a band s pixels wide across its direction on screen. Both
 * casters and what raytrace's primary rays land on are these quads, not a
 * solid: VTK draws nothing behind them. `view` is world -> eye (rigid), `projection` eye ->
 * clip, both row major; the half-widths are vsh_rt_impostor_radius's at
 * each point. The 4 corners (x y z each) run counter-clockwise seen from
 * the camera.
 *
 * The square of half side `half` about `centre`: 0 (nothing written) when
 * `half` is not positive and finite or the view is degenerate. */
int vsh_flat_square(const double view[16], const double centre[3], double half,
                    double corners[12]);

/* The band from `a` (half-width ra) to `b` (rb), across the segment's
 * direction on screen (a straight segment stays straight in projection, so
 * one direction serves both ends): 0 (nothing written) when the segment is
 * seen end-on (no direction on screen; VTK draws at most a dot), a width is
 * not positive and finite, or the input is not finite. */
int vsh_flat_band(const double projection[16], const double view[16], const double a[3], double ra,
                  const double b[3], double rb, double corners[12]);

#ifdef __cplusplus
}
#endif

#endif
