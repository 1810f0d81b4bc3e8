/* vsh_ply_header.c - parse and check a PLY header for the PLY checker.
 *
 * Mirrors what VTK 9.1's vtkPLY accepts (it reads header lines through a
 * 4096-byte buffer, rewrites "vertex_index" to "vertex_indices" and reads the
 * properties vtkPLYReader knows as scalars or lists) and refuses what it would
 * misread: unknown types, list counts of a floating type, element counts over
 * the limits, a coordinate declared as a list. */
#include "vsh_ply_internal.h"

#include <inttypes.h>
#include <stdlib.h>
#include <string.h>

#define PLY_MAX_HEADER_LINES 10000

static ply_type type_named(const vsh__span *w) {
  static const struct {
    const char *name;
    ply_type type;
  } types[] = {{"char", {1, 1, 1}},   {"uchar", {1, 1, 0}},  {"int8", {1, 1, 1}},
               {"uint8", {1, 1, 0}},  {"short", {2, 1, 1}},  {"ushort", {2, 1, 0}},
               {"int16", {2, 1, 1}},  {"uint16", {2, 1, 0}}, {"int", {4, 1, 1}},
               {"uint", {4, 1, 0}},   {"int32", {4, 1, 1}},  {"uint32", {4, 1, 0}},
               {"float", {4, 0, 1}},  {"float32", {4, 0, 1}}, {"double", {8, 0, 1}},
               {"float64", {8, 0, 1}}};
  ply_type none = {0, 0, 0};
  size_t i;
  for (i = 0; i < sizeof types / sizeof types[0]; ++i)
    if (vsh__span_is(w, types[i].name)) return types[i].type;
  return none;
}

/* Properties vtkPLYReader reads as scalars, as index lists, as texture lists. */
static int role_of(const char *name, int *must_be_list) {
  static const char *const scalars[] = {"x", "y", "z", "nx", "ny", "nz", "red", "green", "blue",
                                        "alpha", "u", "v", "s", "t", "texture_u", "texture_v",
                                        "intensity", "diffuse_red", "diffuse_green",
                                        "diffuse_blue"};
  size_t i;
  *must_be_list = -1; /* no rule */
  /* vtkPLY rewrites "vertex_index" (anywhere in a line) to "vertex_indices" */
  if (strcmp(name, "vertex_indices") == 0 || strncmp(name, "vertex_index", 12) == 0) {
    *must_be_list = 1;
    return PLY_ROLE_INDICES;
  }
  if (strcmp(name, "texcoord") == 0) {
    *must_be_list = 1;
    return PLY_ROLE_TEXCOORD;
  }
  for (i = 0; i < sizeof scalars / sizeof scalars[0]; ++i)
    if (strcmp(name, scalars[i]) == 0) {
      *must_be_list = 0;
      return i < 3 ? PLY_ROLE_COORD : PLY_ROLE_OTHER;
    }
  return PLY_ROLE_OTHER;
}

static void copy_name(char *dst, const vsh__span *w) {
  size_t n = (size_t)(w->end - w->p);
  if (n >= PLY_MAX_NAME) n = PLY_MAX_NAME - 1;
  memcpy(dst, w->p, n);
  dst[n] = '\0';
}

static int element_line(ply_header *h, vsh__span *rest, size_t line, char *err, size_t n) {
  vsh__span name, count;
  int64_t c;
  ply_element *e;
  if (h->element_count == PLY_MAX_ELEMENTS)
    return vsh__mc_fail(err, n, "line %zu: more than %d elements in the PLY header", line,
                        PLY_MAX_ELEMENTS);
  if (!vsh__span_word(rest, &name) || !vsh__span_word(rest, &count) ||
      !vsh__span_int64(&count, &c) || c < 0)
    return vsh__mc_fail(err, n, "line %zu: PLY element line is not \"element NAME COUNT\"", line);
  e = &h->elements[h->element_count++];
  memset(e, 0, sizeof *e);
  copy_name(e->name, &name);
  e->count = (uint64_t)c;
  e->is_vertex = strcmp(e->name, "vertex") == 0;
  e->is_face = strcmp(e->name, "face") == 0;
  if (e->count > (e->is_face ? VSH_MESH_MAX_TRIANGLES : VSH_MESH_MAX_POINTS))
    return vsh__mc_fail(err, n, "line %zu: PLY element \"%s\" has %" PRIu64 " entries, over the "
                        "limit of %u", line, e->name, e->count,
                        e->is_face ? VSH_MESH_MAX_TRIANGLES : VSH_MESH_MAX_POINTS);
  if (e->is_vertex) h->vertex_count = e->count;
  return 0;
}

static int property_line(ply_header *h, vsh__span *rest, size_t line, char *err, size_t n) {
  vsh__span w[4];
  int words = 0, must_be_list;
  ply_element *e = h->element_count ? &h->elements[h->element_count - 1] : NULL;
  ply_property *p;
  while (words < 4 && vsh__span_word(rest, &w[words])) ++words;
  if (!e) return vsh__mc_fail(err, n, "line %zu: PLY property before any element", line);
  if (e->property_count == PLY_MAX_PROPERTIES)
    return vsh__mc_fail(err, n, "line %zu: more than %d properties in PLY element \"%s\"", line,
                        PLY_MAX_PROPERTIES, e->name);
  p = &e->properties[e->property_count++];
  memset(p, 0, sizeof *p);
  p->is_list = words >= 1 && vsh__span_is(&w[0], "list");
  if (words < (p->is_list ? 4 : 2))
    return vsh__mc_fail(err, n, "line %zu: PLY property line is not \"property TYPE NAME\" or "
                        "\"property list COUNT_TYPE TYPE NAME\"", line);
  if (p->is_list) {
    p->count = type_named(&w[1]);
    p->type = type_named(&w[2]);
    copy_name(p->name, &w[3]);
    if (p->count.size == 0 || !p->count.integral)
      return vsh__mc_fail(err, n, "line %zu: PLY list \"%s\" has a count type that is not an "
                          "integer type", line, p->name);
  } else {
    p->type = type_named(&w[0]);
    copy_name(p->name, &w[1]);
  }
  if (p->type.size == 0)
    return vsh__mc_fail(err, n, "line %zu: PLY property \"%s\" has an unknown type", line,
                        p->name);
  p->role = role_of(p->name, &must_be_list);
  if (must_be_list >= 0 && must_be_list != p->is_list)
    return vsh__mc_fail(err, n, "line %zu: PLY property \"%s\" must %sbe a list", line, p->name,
                        must_be_list ? "" : "not ");
  if (p->role == PLY_ROLE_INDICES && !p->type.integral)
    return vsh__mc_fail(err, n, "line %zu: PLY vertex indices must have an integer type", line);
  return 0;
}

static int format_line(ply_header *h, vsh__span *rest, size_t line, char *err, size_t n) {
  vsh__span w;
  if (!vsh__span_word(rest, &w))
    return vsh__mc_fail(err, n, "line %zu: PLY format line names no format", line);
  h->format = vsh__span_is(&w, "ascii")                  ? PLY_ASCII
              : vsh__span_is(&w, "binary_little_endian") ? PLY_BINARY_LE
              : vsh__span_is(&w, "binary_big_endian")    ? PLY_BINARY_BE
                                                         : -1;
  if (h->format < 0)
    return vsh__mc_fail(err, n, "line %zu: unknown PLY format \"%.*s\"", line,
                        (int)(w.end - w.p), w.p);
  return 0;
}

static int has_property(const ply_element *e, const char *name) {
  int i;
  for (i = 0; i < e->property_count; ++i)
    if (strcmp(e->properties[i].name, name) == 0) return 1;
  return 0;
}

/* vtkPLYReader needs vertex x, y, z (without them it frees its file and then
 * reads it: a crash) and, for faces, vertex_indices. */
static int check_geometry(const ply_header *h, char *err, size_t n) {
  int i, vertex = 0;
  for (i = 0; i < h->element_count; ++i) {
    const ply_element *e = &h->elements[i];
    if (e->is_vertex) {
      vertex = 1;
      if (!has_property(e, "x") || !has_property(e, "y") || !has_property(e, "z"))
        return vsh__mc_fail(err, n, "PLY element \"vertex\" lacks one of the properties x, y, z");
    }
    if (e->is_face && !has_property(e, "vertex_indices") && !has_property(e, "vertex_index"))
      return vsh__mc_fail(err, n, "PLY element \"face\" has no vertex_indices list");
  }
  return vertex ? 0 : vsh__mc_fail(err, n, "PLY header declares no \"vertex\" element");
}

int vsh__ply_header(const char *data, size_t size, ply_header *h, char *err, size_t n) {
  vsh__text text = {data, data + size, 0};
  vsh__span line, word;
  memset(h, 0, sizeof *h);
  h->format = -1;
  if (!vsh__text_line(&text, &line) || !vsh__span_word(&line, &word) || !vsh__span_is(&word, "ply"))
    return vsh__mc_fail(err, n, "not a PLY file (no \"ply\" magic line)");
  while (vsh__text_line(&text, &line)) {
    int rc = 0;
    if (text.line > PLY_MAX_HEADER_LINES || (size_t)(line.end - line.p) > VSH_MESH_MAX_LINE)
      return vsh__mc_fail(err, n, "line %zu: PLY header too long or line too long", text.line);
    if (memchr(line.p, '\0', (size_t)(line.end - line.p)))
      return vsh__mc_fail(err, n, "line %zu: NUL byte in the PLY header", text.line);
    if (!vsh__span_word(&line, &word)) /* vtkPLY fails on it, then crashes */
      return vsh__mc_fail(err, n, "line %zu: blank line in the PLY header", text.line);
    if (vsh__span_is(&word, "end_header")) {
      if (h->format < 0) return vsh__mc_fail(err, n, "PLY header has no format line");
      h->body = (size_t)(text.p - data);
      h->lines = text.line;
      return check_geometry(h, err, n);
    }
    if (vsh__span_is(&word, "format")) rc = format_line(h, &line, text.line, err, n);
    else if (vsh__span_is(&word, "element")) rc = element_line(h, &line, text.line, err, n);
    else if (vsh__span_is(&word, "property")) rc = property_line(h, &line, text.line, err, n);
    else if (!vsh__span_is(&word, "comment") && !vsh__span_is(&word, "obj_info"))
      rc = vsh__mc_fail(err, n, "line %zu: unknown PLY header keyword \"%.*s\"", text.line,
                        (int)(word.end - word.p), word.p);
    if (rc) return rc;
  }
  return vsh__mc_fail(err, n, "PLY header has no end_header line");
}
