/* vsh_scene.h - the vtkshadow scene file: parse, validate, tessellate.
 *
 * One loader for every renderer: the scene file is parsed and validated here
 * (C11, cJSON), primitives are tessellated here, so VTK, POV-Ray and Cycles
 * all receive exactly the same triangles. Mesh files (PLY, OBJ, STL, VTP) are
 * read by VTK's readers in the C++ layer; this layer only resolves and checks
 * their paths. See docs/scene-format.md for the format.
 */
#ifndef VSH_SCENE_H
#define VSH_SCENE_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Longest error message the loader produces (including the terminator). */
#define VSH_SCENE_ERROR_MAX 1024

typedef enum vsh_light_type {
  VSH_LIGHT_DIRECTIONAL = 0,
  VSH_LIGHT_POINT = 1,
  VSH_LIGHT_SPOT = 2
} vsh_light_type;

typedef struct vsh_light {
  vsh_light_type type;
  double direction[3];   /* directional: where the light travels, unit length */
  double position[3];    /* point and spot */
  double focal_point[3]; /* spot: the cone axis points from position to here */
  double cone_angle;     /* spot: VTK's half-angle in degrees, (0, 90] */
  double color[3];       /* linear RGB, default 1 1 1 */
  double intensity;      /* default 1 */
  /* The light's size; 0 (the default) is today's hard point / parallel light.
   * point, spot: radius of a disk centred on `position` and facing the shaded
   * point (Cycles 3.4's point and spot lights), >= 0, world units.
   * directional: angular diameter in degrees, [0, 180): shadow rays leave in
   * directions normalize(-direction + tan(angle/2) * d), d on the unit disk
   * perpendicular to `direction` (Cycles 3.4's sun). */
  double radius; /* point, spot */
  double angle;  /* directional */
} vsh_light;

typedef enum vsh_object_kind {
  VSH_OBJECT_SPHERE = 0,
  VSH_OBJECT_PLANE = 1,
  VSH_OBJECT_BOX = 2,
  VSH_OBJECT_CYLINDER = 3,
  VSH_OBJECT_MESH = 4,
  /* What VTK draws as screen-space solids (docs/scene-format.md, "points",
   * "polyline") and a volume-rendered blob ("volume"). */
  VSH_OBJECT_POINTS = 5,
  VSH_OBJECT_POLYLINE = 6,
  VSH_OBJECT_VOLUME = 7
} vsh_object_kind;

typedef struct vsh_object {
  vsh_object_kind kind;
  /* sphere */
  double center[3];
  double radius;    /* sphere, cylinder */
  int resolution;   /* sphere, cylinder: segments around the axis */
  /* plane: the parallelogram origin + s (point1 - origin) + t (point2 - origin) */
  double origin[3], point1[3], point2[3];
  /* box: axis-aligned before the transform */
  double min[3], max[3];
  /* cylinder: capped, from base centre to top centre */
  double base[3], top[3];
  /* points (drawn as spheres) and polyline (drawn as a tube): world positions,
   * and the world radius VTK's impostor has at each, pixels / 2 of the
   * scene's image at that depth (vsh_impostor_world_radius); pixels is
   * "point_size" or "line_width" at the scene's "size". */
  double *positions; /* 3 * position_count */
  double *radii;     /* position_count */
  size_t position_count;
  double pixels;
  /* volume: extinction density * max(0, 1 - |p - center| / radius) per world
   * unit (center, radius above), sampled on `samples`^3 grid points. */
  double density;
  int samples;
  /* mesh: path as written in the file, and resolved against the scene's folder */
  char *mesh_path;
  char *mesh_resolved_path;
  /* every object */
  double transform[16]; /* row-major 4x4, affine, identity by default */
  int has_transform;
  int receiver;         /* planar shadows fall on it (flat objects only) */
  int casts;            /* default 1 */
  int has_mirror;       /* plane only: "mirror" given, the plane reflects */
  double mirror;        /* reflectance in [0, 1]; 0 when absent */
  double color[3];      /* default 1 1 1 */
  /* Translucency (docs/translucency.md): each crossing of the surface lets
   * (1 - opacity) of the light through; of that, the fraction `filter` is
   * tinted by the colour (POV-Ray's filter), the rest passes unchanged
   * (POV-Ray's transmit). opacity default 1 (opaque), filter default 0. */
  double opacity;
  double filter;
  char *name;           /* optional; NULL when absent */
} vsh_object;

typedef struct vsh_camera {
  double position[3];
  double focal_point[3];
  double view_up[3];
  double view_angle; /* VTK's vertical angle in degrees, (0, 180) */
} vsh_camera;

typedef struct vsh_scene {
  char *path;        /* the file as given */
  char *description; /* optional one-line description; NULL when absent */
  int width, height; /* "size" */
  vsh_camera camera;
  double background[3];
  vsh_light *lights;
  size_t light_count;
  vsh_object *objects;
  size_t object_count;
} vsh_scene;

/* Parse and validate a scene file. Returns 0 and sets *out on success.
 * On failure returns non-zero, sets *out to NULL and writes into err a message
 * of the form "FILE: FIELD: problem (got VALUE)", e.g.
 * "scenes/a.json: objects[1].sphere.radius: must be > 0 (got -0.5)". */
int vsh_scene_load(const char *path, vsh_scene **out, char *err, size_t err_size);
/* Same, from text in memory; `path` is used for messages and to resolve mesh paths. */
int vsh_scene_parse(const char *text, size_t length, const char *path, vsh_scene **out,
                    char *err, size_t err_size);
void vsh_scene_free(vsh_scene *scene);

/* A triangle mesh in world coordinates, double precision, per-vertex normals. */
typedef struct vsh_mesh {
  double *points;      /* 3 * point_count */
  double *normals;     /* 3 * point_count, unit length */
  uint32_t *triangles; /* 3 * triangle_count, counter-clockwise seen from outside */
  size_t point_count;
  size_t triangle_count;
} vsh_mesh;

/* The world radius of VTK's sphere or tube impostor of `pixels` pixels
 * across at world point p, seen by the scene's camera at the scene's size:
 * pixels * d * tan(view_angle / 2) / height, d the distance of p along the
 * view direction (VTK draws the impostor `pixels` wide on screen, so it is
 * as wide in world units as `pixels` pixels are at its depth). 0 when p is
 * not in front of the camera. */
double vsh_impostor_world_radius(const vsh_scene *scene, double pixels, const double p[3]);

/* Tessellate a primitive object (not VSH_OBJECT_MESH or VSH_OBJECT_VOLUME:
 * a volume has no surface) with its transform applied. points: a sphere of
 * its radius at every position; polyline: a sphere at every vertex and a
 * cone frustum along every segment (the solid VTK's tube impostor shows).
 * Returns 0 on success, non-zero on allocation failure or a mesh object. */
int vsh_object_tessellate(const vsh_object *object, vsh_mesh *out);
/* Apply a row-major affine transform to points (and inverse-transpose to normals). */
void vsh_mesh_transform(vsh_mesh *mesh, const double transform[16]);
void vsh_mesh_free(vsh_mesh *mesh);

const char *vsh_light_type_name(vsh_light_type type);
const char *vsh_object_kind_name(vsh_object_kind kind);

#ifdef __cplusplus
}
#endif
#endif
