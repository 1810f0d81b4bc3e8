/* test_scene_parse.c - the scene parser: values and defaults of good scenes,
 * one bad file per validation rule (message names file, field and value),
 * and parsing from memory. Usage: test_scene_parse DATA_DIR */
#include "vsh_check.h"
#include "vsh_scene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *data_dir = ".";

static const char *data(const char *rel) {
  static char buf[4][1024];
  static int slot = 0;
  char *b = buf[slot++ % 4];
  snprintf(b, sizeof buf[0], "%s/%s", data_dir, rel);
  return b;
}

static void check_vec(const double *v, double x, double y, double z) {
  CHECK_NEAR(v[0], x, 1e-12);
  CHECK_NEAR(v[1], y, 1e-12);
  CHECK_NEAR(v[2], z, 1e-12);
}

static void test_full(void) {
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene *s = NULL;
  const char *path = data("good/full.json");
  int rc = vsh_scene_load(path, &s, err, sizeof err);
  CHECK(rc == 0);
  if (rc) {
    fprintf(stderr, "unexpected error: %s\n", err);
    return;
  }
  CHECK(strcmp(s->path, path) == 0);
  CHECK(s->description && strcmp(s->description, "Unit sphere over a floor, one sun") == 0);
  CHECK(s->width == 800 && s->height == 600);
  check_vec(s->camera.position, 0, -8, 5);
  check_vec(s->camera.focal_point, 0, 0, 0.5);
  check_vec(s->camera.view_up, 0, 0, 1);
  CHECK_NEAR(s->camera.view_angle, 30, 0);
  check_vec(s->background, 0, 0, 0);

  CHECK(s->light_count == 3);
  if (s->light_count == 3) {
    CHECK(s->lights[0].type == VSH_LIGHT_DIRECTIONAL);
    check_vec(s->lights[0].direction, -3.0 / 7, -2.0 / 7, -6.0 / 7); /* |(-3,-2,-6)| = 7 */
    check_vec(s->lights[0].color, 1, 1, 1);
    CHECK_NEAR(s->lights[0].intensity, 1, 0);
    CHECK(s->lights[1].type == VSH_LIGHT_POINT);
    check_vec(s->lights[1].position, 3, 2, 6);
    CHECK(s->lights[2].type == VSH_LIGHT_SPOT);
    check_vec(s->lights[2].focal_point, 0, 0, 0);
    CHECK_NEAR(s->lights[2].cone_angle, 30, 0);
  }

  CHECK(s->object_count == 5);
  if (s->object_count == 5) {
    const vsh_object *o = s->objects;
    CHECK(o[0].kind == VSH_OBJECT_SPHERE);
    check_vec(o[0].center, 0, 0, 1.2);
    CHECK_NEAR(o[0].radius, 0.5, 0);
    CHECK(o[0].resolution == 128);
    CHECK(o[0].casts == 1 && o[0].receiver == 0 && o[0].name == NULL);
    CHECK(o[1].kind == VSH_OBJECT_PLANE && o[1].receiver == 1);
    check_vec(o[1].origin, -5, -5, 0);
    check_vec(o[1].point1, 5, -5, 0);
    check_vec(o[1].point2, -5, 5, 0);
    CHECK(o[2].kind == VSH_OBJECT_BOX && o[2].casts == 0);
    check_vec(o[2].min, -1, -1, 0);
    check_vec(o[2].max, 1, 1, 2);
    check_vec(o[2].color, 0.8, 0.2, 0.2);
    CHECK(o[2].name && strcmp(o[2].name, "crate") == 0);
    CHECK(o[3].kind == VSH_OBJECT_CYLINDER && o[3].resolution == 64);
    check_vec(o[3].base, 0, 0, 0);
    check_vec(o[3].top, 0, 0, 1);
    CHECK_NEAR(o[3].radius, 0.3, 0);
    CHECK(o[4].kind == VSH_OBJECT_MESH && o[4].has_transform == 1);
    CHECK(o[4].mesh_path && strcmp(o[4].mesh_path, "meshes/part.ply") == 0);
    CHECK(o[4].mesh_resolved_path &&
          strcmp(o[4].mesh_resolved_path, data("good/meshes/part.ply")) == 0);
  }
  vsh_scene_free(s);
}

static void test_defaults(void) {
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene *s = NULL;
  int i, rc = vsh_scene_load(data("good/minimal.json"), &s, err, sizeof err);
  CHECK(rc == 0);
  if (rc) {
    fprintf(stderr, "unexpected error: %s\n", err);
    return;
  }
  CHECK(s->description == NULL);
  check_vec(s->background, 0, 0, 0);
  check_vec(s->lights[0].direction, 0, 0, -1); /* normalized from (0,0,-2) */
  check_vec(s->lights[0].color, 1, 1, 1);
  CHECK_NEAR(s->lights[0].intensity, 1, 0);
  CHECK(s->objects[0].resolution == 64);
  CHECK(s->objects[0].casts == 1);
  CHECK(s->objects[0].receiver == 0);
  CHECK(s->objects[0].has_transform == 0);
  CHECK(s->objects[0].name == NULL && s->objects[0].mesh_path == NULL);
  check_vec(s->objects[0].color, 1, 1, 1);
  for (i = 0; i < 16; ++i) CHECK(s->objects[0].transform[i] == ((i % 5 == 0) ? 1.0 : 0.0));
  vsh_scene_free(s);
}

/* Light sizes: given values kept exactly, 0 when absent (hard lights). */
static void test_light_sizes(void) {
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene *s = NULL;
  size_t i;
  int rc = vsh_scene_load(data("good/soft.json"), &s, err, sizeof err);
  CHECK(rc == 0);
  if (rc) {
    fprintf(stderr, "unexpected error: %s\n", err);
    return;
  }
  CHECK(s->light_count == 5);
  if (s->light_count == 5) {
    CHECK(s->lights[0].angle == 11.4 && s->lights[0].radius == 0.0);
    CHECK(s->lights[1].radius == 0.5 && s->lights[1].angle == 0.0);
    CHECK(s->lights[2].radius == 0.25 && s->lights[2].angle == 0.0);
    CHECK(s->lights[3].radius == 0.0);
    CHECK(s->lights[4].angle == 179.5);
  }
  vsh_scene_free(s);
  s = NULL;
  rc = vsh_scene_load(data("good/full.json"), &s, err, sizeof err);
  CHECK(rc == 0);
  for (i = 0; rc == 0 && i < s->light_count; ++i)
    CHECK(s->lights[i].radius == 0.0 && s->lights[i].angle == 0.0);
  vsh_scene_free(s);
}

static void test_meshes(void) {
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene *s = NULL;
  int rc = vsh_scene_load(data("good/meshes.json"), &s, err, sizeof err);
  CHECK(rc == 0);
  if (rc) {
    fprintf(stderr, "unexpected error: %s\n", err);
    return;
  }
  CHECK(s->object_count == 6);
  check_vec(s->background, 0.1, 0.2, 0.3);
  check_vec(s->lights[0].color, 2.5, 2, 1.5); /* light colours may exceed 1 */
  CHECK_NEAR(s->lights[0].intensity, 0.5, 0);
  CHECK_NEAR(s->lights[1].cone_angle, 90, 0);
  CHECK(strcmp(s->objects[1].mesh_path, "meshes/tri.STL") == 0); /* extension case-insensitive */
  CHECK(s->objects[2].has_transform && s->objects[2].transform[3] == 1 &&
        s->objects[2].transform[7] == 2 && s->objects[2].transform[11] == 3);
  CHECK(s->objects[4].transform[0] == -1); /* mirrors are allowed */
  CHECK(s->objects[5].receiver == 0);
  vsh_scene_free(s);
}

/* "opacity" and "filter": a translucent sphere and a red filter slab. */
static void test_translucent(void) {
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene *s = NULL;
  int rc = vsh_scene_load(data("good/translucent.json"), &s, err, sizeof err);
  CHECK(rc == 0);
  if (rc) {
    fprintf(stderr, "unexpected error: %s\n", err);
    return;
  }
  CHECK(s->object_count == 3);
  if (s->object_count == 3) {
    CHECK(s->objects[0].opacity == 1 && s->objects[0].filter == 0); /* defaults */
    CHECK(s->objects[1].opacity == 0.5 && s->objects[1].filter == 0);
    CHECK(s->objects[2].opacity == 0.4 && s->objects[2].filter == 1);
  }
  vsh_scene_free(s);
}

/* "mirror": R on planes; absent means no mirror (R = 0), 0 and 1 are valid. */
static void test_mirror(void) {
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene *s = NULL;
  int rc = vsh_scene_load(data("good/mirror.json"), &s, err, sizeof err);
  CHECK(rc == 0);
  if (rc) {
    fprintf(stderr, "unexpected error: %s\n", err);
    return;
  }
  CHECK(s->object_count == 4);
  if (s->object_count == 4) {
    CHECK(s->objects[0].has_mirror == 0 && s->objects[0].mirror == 0);
    CHECK(s->objects[1].has_mirror == 1 && s->objects[1].mirror == 0.75);
    CHECK(s->objects[1].receiver == 1);
    CHECK(s->objects[2].has_mirror == 1 && s->objects[2].mirror == 0);
    CHECK(s->objects[3].has_mirror == 1 && s->objects[3].mirror == 1);
  }
  vsh_scene_free(s);
}

/* Points and polylines get the world radius of VTK's impostor at each
 * position (pixels / 2 at its depth, at the scene's size); a volume keeps
 * its fields. */
static void test_primitives(void) {
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene *s = NULL;
  int rc = vsh_scene_load(data("good/primitives.json"), &s, err, sizeof err);
  CHECK(rc == 0);
  if (rc) {
    fprintf(stderr, "unexpected error: %s\n", err);
    return;
  }
  CHECK(s->object_count == 4);
  if (s->object_count == 4) {
    const vsh_object *p = &s->objects[0], *l = &s->objects[1], *v = &s->objects[2];
    /* one pixel at depth d is 2 d tan(45) / 100 = d / 50 wide */
    CHECK(p->kind == VSH_OBJECT_POINTS && p->position_count == 2 && p->pixels == 20);
    CHECK(fabs(p->radii[0] - 10.0 * 10.0 / 50.0) < 1e-12); /* depth 10: 10 px of d/50 */
    CHECK(fabs(p->radii[1] - 10.0 * 5.0 / 50.0) < 1e-12);  /* depth 5 */
    CHECK(p->positions[3] == 3 && p->positions[4] == 1 && p->positions[5] == 5);
    CHECK(p->resolution == 32); /* default */
    CHECK(l->kind == VSH_OBJECT_POLYLINE && l->position_count == 3 && l->resolution == 16);
    CHECK(fabs(l->radii[0] - 5.0 * 10.0 / 50.0) < 1e-12);
    CHECK(fabs(l->radii[2] - 5.0 * 5.0 / 50.0) < 1e-12);
    CHECK(v->kind == VSH_OBJECT_VOLUME && v->radius == 1.5 && v->density == 2);
    CHECK(v->samples == 64 && v->center[2] == 2);
    CHECK(strcmp(vsh_object_kind_name(v->kind), "volume") == 0);
  }
  vsh_scene_free(s);
}

/* One file per rule: the message must start with the file name and contain
 * the field path, the problem and the offending value. */
typedef struct bad_case {
  const char *file;
  const char *expect1;
  const char *expect2; /* may be NULL */
} bad_case;

static const bad_case bad_cases[] = {
    {"unknown_top_field", ": unknown field \"sizes\" at the top level", "did you mean \"size\"?"},
    {"unknown_object_field", ": objects[1]: unknown field \"recever\"", "did you mean \"receiver\"?"},
    {"missing_view_angle", ": camera.view_angle: missing required field", NULL},
    {"missing_lights", ": lights: missing required field", NULL},
    {"size_string", ": size[0]: expected an integer (got \"800\")", NULL},
    {"size_zero", ": size[1]: must be in 1..16384 (got 0)", NULL},
    {"size_too_big", ": size[0]: must be in 1..16384 (got 16385)", NULL},
    {"size_length", ": size: expected [width, height] (got [800])", NULL},
    {"size_fraction", ": size[0]: expected an integer (got 800.5)", NULL},
    {"sphere_radius_negative", ": objects[0].sphere.radius: must be > 0 (got -0.5)", NULL},
    {"sphere_missing_center", ": objects[0].sphere.center: missing required field", NULL},
    {"resolution_too_small", ": objects[0].sphere.resolution: must be in 3..4096 (got 2)", NULL},
    {"resolution_fraction", ": objects[0].cylinder.resolution: expected an integer (got 64.5)",
     NULL},
    {"direction_zero", ": lights[0].direction: zero length (got [0, 0, 0])", NULL},
    {"view_up_parallel", ": camera.view_up: parallel to the view direction (got [0, 0, 1])", NULL},
    {"view_up_zero", ": camera.view_up: zero length (got [0, 0, 0])", NULL},
    {"camera_same_point", ": camera.focal_point: equal to camera.position (got [1, 2, 3])", NULL},
    {"view_angle_range", ": camera.view_angle: must be in (0, 180) degrees (got 180)", NULL},
    {"view_angle_string", ": camera.view_angle: expected a number (got \"30\")", NULL},
    {"position_length", ": camera.position: expected an array of 3 numbers (got [0, -8])", NULL},
    {"position_element", ": camera.position[1]: expected a number (got \"a\")", NULL},
    {"camera_not_object", ": camera: expected an object (got [0, 0, 0])", NULL},
    {"cone_angle_range", ": lights[0].cone_angle: must be in (0, 90] degrees", "(got 95)"},
    {"cone_angle_zero", ": lights[0].cone_angle: must be in (0, 90] degrees", "(got 0)"},
    {"cone_angle_missing", ": lights[0].cone_angle: missing required field", NULL},
    {"spot_same_point", ": lights[0].focal_point: equal to lights[0].position (got [0, 0, 5])",
     NULL},
    {"light_type_unknown", ": lights[0].type: expected \"directional\", \"point\" or \"spot\"",
     "(got \"area\")"},
    {"light_type_missing", ": lights[0].type: missing required field", NULL},
    {"light_field_for_other_type", ": lights[0]: unknown field \"direction\" for a point light",
     NULL},
    {"light_intensity_negative", ": lights[0].intensity: must be >= 0 (got -1)", NULL},
    {"light_color_negative", ": lights[0].color[1]: must be >= 0 (got -0.5)", NULL},
    {"light_radius_negative", ": lights[0].radius: must be >= 0", "(got -0.25)"},
    {"light_radius_string", ": lights[0].radius: expected a number (got \"0.5\")", NULL},
    {"light_angle_range", ": lights[0].angle: must be in [0, 180) degrees", "(got 180)"},
    {"light_angle_negative", ": lights[0].angle: must be in [0, 180) degrees", "(got -1)"},
    {"light_radius_on_directional",
     ": lights[0]: unknown field \"radius\" for a directional light", NULL},
    {"light_angle_on_point", ": lights[0]: unknown field \"angle\" for a point light", NULL},
    {"lights_empty", ": lights: needs at least one entry (got [])", NULL},
    {"lights_not_array", ": lights: expected an array (got {\"type\": \"point\"})", NULL},
    {"objects_empty", ": objects: needs at least one entry (got [])", NULL},
    {"object_not_object", ": objects[0]: expected an object (got \"sphere\")", NULL},
    {"two_shapes", ": objects[0]: more than one shape (\"sphere\" and \"box\")", NULL},
    {"no_shape", ": objects[0]: missing shape", NULL},
    {"receiver_on_sphere", ": objects[0].receiver: only flat objects (plane) can be receivers",
     "(got true)"},
    {"receiver_not_bool", ": objects[0].receiver: expected true or false (got 1)", NULL},
    {"mirror_range", ": objects[0].mirror: must be in [0, 1] (got 1.5)", NULL},
    {"mirror_negative", ": objects[0].mirror: must be in [0, 1] (got -0.25)", NULL},
    {"mirror_string", ": objects[0].mirror: expected a number (got \"0.5\")", NULL},
    {"mirror_bool", ": objects[0].mirror: expected a number (got true)", NULL},
    {"mirror_infinite", ": objects[0].mirror: must be a finite number (got inf)", NULL},
    {"mirror_on_sphere", ": objects[0].mirror: only a plane can be a mirror, and a sphere is not",
     "(got 0.5)"},
    {"opacity_range", ": objects[0].opacity: must be in [0, 1] (got 1.5)", NULL},
    {"opacity_string", ": objects[0].opacity: expected a number (got \"0.4\")", NULL},
    {"filter_negative", ": objects[0].filter: must be in [0, 1] (got -0.1)", NULL},
    {"mirror_translucent", ": objects[0].opacity: a mirror must be opaque (opacity 1)",
     "(got 0.5)"},
    {"casts_string", ": objects[0].casts: expected true or false (got \"yes\")", NULL},
    {"name_number", ": objects[0].name: expected a string (got 5)", NULL},
    {"color_range", ": objects[0].color[0]: must be in [0, 1] (got 1.5)", NULL},
    {"background_range", ": background[2]: must be in [0, 1] (got 2)", NULL},
    {"description_number", ": description: expected a string (got 1)", NULL},
    {"box_flat", ": objects[0].box.max[2]: must be greater than min[2] = 1 (got 1)", NULL},
    {"box_unknown_field", ": objects[0].box: unknown field \"center\"", NULL},
    {"cylinder_same_points", ": objects[0].cylinder.top: equal to base (got [0, 0, 1])", NULL},
    {"cylinder_radius_zero", ": objects[0].cylinder.radius: must be > 0 (got 0)", NULL},
    {"plane_parallel", ": objects[0].plane: zero area", "\"point2\": [2, 2, 0]"},
    {"plane_zero_edge", ": objects[0].plane: zero area", "\"point1\": [0, 0, 0]"},
    {"transform_not_affine", ": objects[0].transform: must be affine", "(got [0, 0, 1, 1])"},
    {"transform_singular", ": objects[0].transform: linear part is singular", "(got [1, 0, 0"},
    {"transform_length", ": objects[0].transform: expected an array of 16 numbers", NULL},
    {"mesh_missing", ": objects[0].mesh: unreadable: No such file or directory",
     "(got \"meshes/nope.ply\", looked for \""},
    {"mesh_directory", ": objects[0].mesh: unreadable: Is a directory",
     "(got \"meshes/folder.ply\""},
    {"mesh_extension", ": objects[0].mesh: unsupported file type", "(got \"meshes/part.3ds\")"},
    {"mesh_empty_path", ": objects[0].mesh: empty path (got \"\")", NULL},
    {"mesh_not_string", ": objects[0].mesh: expected a string", NULL},
    {"top_array", ": expected a JSON object at the top level (got [1, 2])", NULL},
    {"empty", ": empty file", NULL},
    {"whitespace_only", ": empty file", NULL},
    {"invalid_json", ": line 4 column 24: invalid JSON", NULL},
    {"trailing_text", ": line 2 column 1: invalid JSON (text after the end)", NULL},
    {"infinite_number", ": objects[0].sphere.radius: must be a finite number (got inf)", NULL},
    {"duplicate_field", ": objects[0].sphere.radius: duplicate field", NULL},
    {"points_size_zero", ": objects[0].points.point_size: must be in (0, 4096] pixels (got 0)",
     NULL},
    {"points_behind_camera", ": objects[0].points.positions[1]: not in front of the camera",
     "(got [0, -9, 2])"},
    {"points_empty", ": objects[0].points.positions: needs at least 1 positions (got [])", NULL},
    {"points_position_length",
     ": objects[0].points.positions[0]: expected an array of 3 numbers (got [0, 0])", NULL},
    {"points_transform", ": objects[0].transform: not supported for a points", NULL},
    {"polyline_one_point", ": objects[0].polyline.points: needs at least 2 positions", NULL},
    {"polyline_repeated", ": objects[0].polyline.points[2]: equal to the point before it",
     "(got [1, 0, 1])"},
    {"polyline_width_missing", ": objects[0].polyline.line_width: missing required field", NULL},
    {"volume_density_zero", ": objects[0].volume.density: must be > 0 with density * radius <= 50",
     "(got 0)"},
    {"volume_too_dense", ": objects[0].volume.density: must be > 0 with density * radius <= 50",
     "(got 30)"},
    {"volume_samples", ": objects[0].volume.samples: must be in 8..512 (got 4)", NULL},
    {"volume_opacity", ": objects[0].opacity: not supported for a volume", "(got 0.5)"},
};

static void test_bad_files(void) {
  size_t i;
  for (i = 0; i < sizeof bad_cases / sizeof bad_cases[0]; ++i) {
    char err[VSH_SCENE_ERROR_MAX], rel[256], expect[1200];
    const char *path;
    vsh_scene *s = (vsh_scene *)&s; /* must be reset to NULL */
    int rc;
    snprintf(rel, sizeof rel, "bad/%s.json", bad_cases[i].file);
    path = data(rel);
    rc = vsh_scene_load(path, &s, err, sizeof err);
    CHECK(rc != 0);
    CHECK(s == NULL);
    if (rc == 0) {
      fprintf(stderr, "  %s parsed but should not\n", path);
      vsh_scene_free(s);
      continue;
    }
    /* "FILE: FIELD: ..." - the file name comes first. */
    snprintf(expect, sizeof expect, "%s%s", path, bad_cases[i].expect1);
    CHECK_STR_CONTAINS(err, expect);
    if (bad_cases[i].expect2) CHECK_STR_CONTAINS(err, bad_cases[i].expect2);
    CHECK(strchr(err, '\n') == NULL); /* one line */
  }
}

static void test_load_errors(void) {
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene *s = NULL;
  const char *missing = data("bad/does_not_exist.json");
  CHECK(vsh_scene_load(missing, &s, err, sizeof err) != 0 && s == NULL);
  CHECK_STR_CONTAINS(err, missing);
  CHECK_STR_CONTAINS(err, "cannot open: No such file or directory");
  CHECK(vsh_scene_load(data("bad"), &s, err, sizeof err) != 0 && s == NULL);
  CHECK_STR_CONTAINS(err, "cannot read: Is a directory");
  CHECK(vsh_scene_load(NULL, &s, err, sizeof err) != 0 && s == NULL);
  CHECK_STR_CONTAINS(err, "no scene file given");
}

static const char minimal[] =
    "{\"size\": [8, 8], \"camera\": {\"position\": [0, 0, 5], \"focal_point\": [0, 0, 0],"
    " \"view_up\": [0, 1, 0], \"view_angle\": 30},"
    " \"lights\": [{\"type\": \"point\", \"position\": [1, 1, 1]}],"
    " \"objects\": [{\"box\": {\"min\": [0, 0, 0], \"max\": [1, 1, 1]}}]}";

static void test_memory(void) {
  char err[VSH_SCENE_ERROR_MAX], small[16], text[2048];
  vsh_scene *s = NULL;
  size_t n = strlen(minimal);

  /* No path: messages say "(memory)", the scene has no path. */
  CHECK(vsh_scene_parse(minimal, n, NULL, &s, err, sizeof err) == 0);
  CHECK(s && s->path == NULL && s->width == 8);
  vsh_scene_free(s);
  CHECK(vsh_scene_parse("[]", 2, NULL, &s, err, sizeof err) != 0 && s == NULL);
  CHECK_STR_CONTAINS(err, "(memory): expected a JSON object at the top level (got [])");

  /* `length` is honoured: text after it, even unterminated garbage, is ignored. */
  memcpy(text, minimal, n);
  memcpy(text + n, "}}}garbage", 10);
  CHECK(vsh_scene_parse(text, n, "mem.json", &s, err, sizeof err) == 0);
  CHECK(s && strcmp(s->path, "mem.json") == 0);
  vsh_scene_free(s);
  /* ... and a length one short is a truncated document. */
  CHECK(vsh_scene_parse(text, n - 1, "mem.json", &s, err, sizeof err) != 0);
  CHECK_STR_CONTAINS(err, "mem.json: line 1 column");
  /* An embedded NUL is not the end of the document. */
  memcpy(text, minimal, n);
  text[n] = '\0';
  text[n + 1] = '1';
  CHECK(vsh_scene_parse(text, n + 2, "nul.json", &s, err, sizeof err) != 0);
  CHECK_STR_CONTAINS(err, "nul.json: line 1 column");

  /* Small or absent error buffers are safe. */
  CHECK(vsh_scene_parse("[]", 2, "a-rather-long-file-name.json", &s, small, sizeof small) != 0);
  CHECK(strlen(small) == sizeof small - 1);
  CHECK(vsh_scene_parse("[]", 2, "x.json", &s, NULL, 0) != 0);
  CHECK(vsh_scene_parse(NULL, 0, "x.json", &s, err, sizeof err) != 0);
  CHECK_STR_CONTAINS(err, "x.json: empty file");

  /* Mesh paths resolve against the directory of the given path ... */
  snprintf(text, sizeof text,
           "{\"size\": [8, 8], \"camera\": {\"position\": [0, 0, 5], \"focal_point\": [0, 0, 0],"
           " \"view_up\": [0, 1, 0], \"view_angle\": 30},"
           " \"lights\": [{\"type\": \"point\", \"position\": [1, 1, 1]}],"
           " \"objects\": [{\"mesh\": \"meshes/tri.obj\"}, {\"mesh\": \"%s\"}]}",
           data("good/meshes/part.ply"));
  CHECK(vsh_scene_parse(text, strlen(text), data("good/not-on-disk.json"), &s, err, sizeof err) ==
        0);
  if (s) {
    CHECK(strcmp(s->objects[0].mesh_resolved_path, data("good/meshes/tri.obj")) == 0);
    /* ... unless absolute (the data dir is absolute in the ctest run). */
    if (data_dir[0] == '/')
      CHECK(strcmp(s->objects[1].mesh_resolved_path, s->objects[1].mesh_path) == 0);
    vsh_scene_free(s);
  } else {
    fprintf(stderr, "unexpected error: %s\n", err);
  }
  /* Without a directory in the path they resolve against the working directory. */
  CHECK(vsh_scene_parse(text, strlen(text), "scene.json", &s, err, sizeof err) != 0);
  CHECK_STR_CONTAINS(err, "scene.json: objects[0].mesh: unreadable");
  CHECK_STR_CONTAINS(err, "(got \"meshes/tri.obj\")"); /* resolved == written: said once */

  /* Huge numbers: finite but differences overflow. */
  {
    const char *huge =
        "{\"size\": [8, 8], \"camera\": {\"position\": [-1e308, 0, 0], \"focal_point\": [1e308, 0, 0],"
        " \"view_up\": [0, 1, 0], \"view_angle\": 30},"
        " \"lights\": [{\"type\": \"directional\", \"direction\": [1e-320, 0, 0]}],"
        " \"objects\": [{\"sphere\": {\"center\": [0, 0, 0], \"radius\": 1}}]}";
    CHECK(vsh_scene_parse(huge, strlen(huge), "huge.json", &s, err, sizeof err) != 0);
    CHECK_STR_CONTAINS(err, "huge.json: camera.focal_point: too far from camera.position");
  }
  /* Tiny but non-zero vectors are fine and normalize exactly. */
  {
    const char *tiny =
        "{\"size\": [8, 8], \"camera\": {\"position\": [0, 0, 1e-300], \"focal_point\": [0, 0, 0],"
        " \"view_up\": [0, 1e-300, 0], \"view_angle\": 30},"
        " \"lights\": [{\"type\": \"directional\", \"direction\": [1e-320, 0, 0]}],"
        " \"objects\": [{\"sphere\": {\"center\": [0, 0, 0], \"radius\": 1e-300}}]}";
    CHECK(vsh_scene_parse(tiny, strlen(tiny), "tiny.json", &s, err, sizeof err) == 0);
    if (s) {
      check_vec(s->lights[0].direction, 1, 0, 0);
      vsh_scene_free(s);
    } else {
      fprintf(stderr, "unexpected error: %s\n", err);
    }
  }
}

static void test_names(void) {
  CHECK(strcmp(vsh_light_type_name(VSH_LIGHT_SPOT), "spot") == 0);
  CHECK(strcmp(vsh_light_type_name(VSH_LIGHT_DIRECTIONAL), "directional") == 0);
  CHECK(strcmp(vsh_object_kind_name(VSH_OBJECT_CYLINDER), "cylinder") == 0);
  CHECK(strcmp(vsh_object_kind_name(VSH_OBJECT_MESH), "mesh") == 0);
  vsh_scene_free(NULL);
}

int main(int argc, char **argv) {
  if (argc > 1) data_dir = argv[1];
  test_full();
  test_defaults();
  test_meshes();
  test_mirror();
  test_translucent();
  test_primitives();
  test_bad_files();
  test_light_sizes();
  test_load_errors();
  test_memory();
  test_names();
  return vsh_check_report("scene.parse");
}
