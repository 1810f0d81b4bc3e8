/* vsh_obj_check.c - scan a Wavefront OBJ file before vtkOBJReader sees it.
 *
 * VTK 9.1's OBJ reader uses face indices without checking them, so a face
 * naming vertex 0, a vertex past the end, or a relative (negative) index
 * reaching before the first vertex crashes it. Here every index of every
 * f/l/p element is resolved like the OBJ specification says (positive:
 * 1-based; negative: relative to the vertices read so far) and checked
 * against the v/vt/vn counts; vertex coordinates must be finite in float
 * precision (the reader stores floats); counts must stay under the limits. */
#include "vsh_mesh_check_internal.h"

#include <inttypes.h>
#include <string.h>

/* VTK 9.1's OBJ reader splits longer lines; polygons with a few hundred
 * v/vt/vn corners still fit. */
#define OBJ_MAX_LINE 65536

enum { OBJ_V, OBJ_VT, OBJ_VN };
static const char *const kind_names[] = {"vertex", "texture coordinate", "normal"};

typedef struct obj_scan {
  uint64_t count[3];    /* v, vt, vn read so far */
  uint64_t elements;    /* f, l, p lines so far (the "face" number in messages) */
  uint64_t triangles;   /* what the faces become after fan triangulation */
  int64_t max_ref[3];   /* largest positive index, checked at the end (forward references) */
  uint64_t max_ref_element[3];
  size_t max_ref_line[3];
  const char *max_ref_name[3]; /* "face", "line" or "point" */
  const char *element;  /* "face", "line", "point" for the current f/l/p line */
} obj_scan;

/* One index of a corner ("12", "-3"): zero or before the first element fails now,
 * a positive one is remembered to be checked against the final count. */
static int check_index(obj_scan *s, int kind, const vsh__span *digits, size_t line, char *err,
                       size_t err_size) {
  int64_t i;
  if (!vsh__span_int64(digits, &i))
    return vsh__mc_fail(err, err_size, "line %zu: %s %" PRIu64 " has a %s index that is not an "
                        "integer (got \"%.*s\")", line, s->element, s->elements, kind_names[kind],
                        (int)(digits->end - digits->p), digits->p);
  if (i == 0)
    return vsh__mc_fail(err, err_size, "line %zu: %s %" PRIu64 " refers to %s 0 (OBJ indices "
                        "start at 1)", line, s->element, s->elements, kind_names[kind]);
  if (i < 0 && (uint64_t)(-(i + 1)) >= s->count[kind])
    return vsh__mc_fail(err, err_size, "line %zu: %s %" PRIu64 " refers to %s %" PRId64
                        ", before the first one (only %" PRIu64 " precede it)", line, s->element,
                        s->elements, kind_names[kind], i, s->count[kind]);
  if (i > s->max_ref[kind]) {
    s->max_ref[kind] = i;
    s->max_ref_element[kind] = s->elements;
    s->max_ref_line[kind] = line;
    s->max_ref_name[kind] = s->element;
  }
  return 0;
}

/* One corner "v", "v/vt", "v//vn" or "v/vt/vn". */
static int check_corner(obj_scan *s, const vsh__span *word, size_t line, char *err,
                        size_t err_size) {
  vsh__span part = {word->p, word->p};
  int kind = OBJ_V;
  for (;;) {
    while (part.end < word->end && *part.end != '/') ++part.end;
    if (kind > OBJ_VN)
      return vsh__mc_fail(err, err_size, "line %zu: %s %" PRIu64 " has a corner with more than "
                          "three indices (got \"%.*s\")", line, s->element, s->elements,
                          (int)(word->end - word->p), word->p);
    if (part.end > part.p || kind == OBJ_V) { /* only the vt slot may be empty ("v//vn") */
      if (check_index(s, kind, &part, line, err, err_size)) return 1;
    }
    if (part.end >= word->end) return 0;
    part.p = part.end = part.end + 1;
    ++kind;
  }
}

static int check_element(obj_scan *s, vsh__span *rest, size_t line, char *err, size_t err_size) {
  vsh__span word;
  uint64_t corners = 0;
  ++s->elements;
  while (vsh__span_word(rest, &word)) {
    if (check_corner(s, &word, line, err, err_size)) return 1;
    ++corners;
  }
  if (strcmp(s->element, "face") != 0) return 0;
  if (corners < 3)
    return vsh__mc_fail(err, err_size, "line %zu: face %" PRIu64 " has %" PRIu64 " vertices (a "
                        "face needs at least 3)", line, s->elements, corners);
  s->triangles += corners - 2;
  if (s->triangles > VSH_MESH_MAX_TRIANGLES)
    return vsh__mc_fail(err, err_size, "line %zu: more than %u triangles (the limit)", line,
                        VSH_MESH_MAX_TRIANGLES);
  return 0;
}

/* "v x y z [w | r g b]", "vt u [v [w]]", "vn x y z": the coordinates the
 * reader parses must be numbers; vertex positions must be finite floats. */
static int check_vector(obj_scan *s, int kind, vsh__span *rest, size_t line, char *err,
                        size_t err_size) {
  static const int needed[] = {3, 2, 3};
  vsh__span word;
  int k;
  for (k = 0; k < needed[kind]; ++k) {
    double v;
    if (!vsh__span_word(rest, &word) || !vsh__span_double(&word, &v))
      return vsh__mc_fail(err, err_size, "line %zu: %s %" PRIu64 " has fewer than %d numbers",
                          line, kind_names[kind], s->count[kind] + 1, needed[kind]);
    if (kind == OBJ_V && !vsh__float_ok(v))
      return vsh__mc_fail(err, err_size, "line %zu: vertex %" PRIu64 " has a coordinate that is "
                          "not a finite float (got \"%.*s\")", line, s->count[kind] + 1,
                          (int)(word.end - word.p), word.p);
  }
  if (++s->count[kind] > VSH_MESH_MAX_POINTS)
    return vsh__mc_fail(err, err_size, "line %zu: more than %u %ss (the limit)", line,
                        VSH_MESH_MAX_POINTS, kind_names[kind]);
  return 0;
}

static int check_line(obj_scan *s, vsh__span *line, size_t number, char *err, size_t err_size) {
  vsh__span command;
  if ((size_t)(line->end - line->p) > OBJ_MAX_LINE)
    return vsh__mc_fail(err, err_size, "line %zu is longer than %d characters", number,
                        OBJ_MAX_LINE);
  if (!vsh__span_word(line, &command)) return 0;
  if (vsh__span_is(&command, "v")) return check_vector(s, OBJ_V, line, number, err, err_size);
  if (vsh__span_is(&command, "vt")) return check_vector(s, OBJ_VT, line, number, err, err_size);
  if (vsh__span_is(&command, "vn")) return check_vector(s, OBJ_VN, line, number, err, err_size);
  s->element = vsh__span_is(&command, "f") ? "face"
               : vsh__span_is(&command, "l") ? "line"
               : vsh__span_is(&command, "p") ? "point"
                                             : NULL;
  return s->element ? check_element(s, line, number, err, err_size) : 0; /* others: ignored */
}

int vsh_obj_check_buffer(const char *data, size_t size, char *err, size_t err_size) {
  obj_scan s;
  vsh__text text = {data, data + size, 0};
  vsh__span line;
  int kind;
  memset(&s, 0, sizeof s);
  if (size && memchr(data, '\0', size))
    return vsh__mc_fail(err, err_size, "not a text file (it contains NUL bytes)");
  while (vsh__text_line(&text, &line))
    if (check_line(&s, &line, text.line, err, err_size)) return 1;
  /* Positive indices may point forward; now that all counts are known: */
  for (kind = OBJ_V; kind <= OBJ_VN; ++kind)
    if ((uint64_t)s.max_ref[kind] > s.count[kind])
      return vsh__mc_fail(err, err_size, "line %zu: %s %" PRIu64 " refers to %s %" PRId64
                          " but the file has %" PRIu64, s.max_ref_line[kind],
                          s.max_ref_name[kind], s.max_ref_element[kind], kind_names[kind],
                          s.max_ref[kind], s.count[kind]);
  return 0;
}

int vsh_obj_check(const char *path, char *err, size_t err_size) {
  return vsh__check_file(path, vsh_obj_check_buffer, err, err_size);
}
