/* vsh_ply_check.c - scan a PLY body (ASCII or binary) before vtkPLYReader sees it.
 *
 * VTK 9.1's PLY code reads past the end of a truncated body, reads words that
 * an ASCII line does not have, and uses face indices unchecked: each is a
 * crash. So the whole body is walked here, element by element as the header
 * declares it: it must be long enough (binary) or have one line with enough
 * numbers per entry (ASCII, which vtkPLY reads one line per entry); vertex
 * coordinates must be finite floats (vtkPLYReader stores floats); every face
 * must have 3 to 255 corners (vtkPLYReader keeps the count in a byte), every
 * corner index a vertex that exists, and a texcoord list two numbers per
 * corner. */
#include "vsh_ply_internal.h"

#include <inttypes.h>
#include <math.h>
#include <string.h>

/* Where the walk is, for messages and for the per-entry checks. */
typedef struct ply_walk {
  const ply_header *h;
  const ply_element *e;
  uint64_t entry;         /* 0-based entry of e being read */
  int64_t corners, texcoords; /* list lengths seen in the current face (-1: none) */
  /* binary */
  const unsigned char *p, *end;
  /* ASCII */
  vsh__span line;
  size_t line_number;
} ply_walk;

static double decode(const unsigned char *p, ply_type t, int big_endian) {
  unsigned char b[8];
  int i;
  for (i = 0; i < t.size; ++i) b[i] = p[big_endian ? t.size - 1 - i : i];
  if (!t.integral) {
    if (t.size == 4) {
      float f;
      memcpy(&f, b, 4);
      return f;
    } else {
      double d;
      memcpy(&d, b, 8);
      return d;
    }
  } else {
    uint64_t u = 0;
    for (i = t.size - 1; i >= 0; --i) u = u << 8 | b[i];
    if (t.is_signed && (u >> (8 * t.size - 1)) & 1u) /* sign-extend */
      return (double)(int64_t)(u | (~(uint64_t)0 << (8 * t.size - 1)));
    return (double)u;
  }
}

/* The next value: binary bytes or an ASCII word. */
static int next_value(ply_walk *w, ply_type t, double *v, char *err, size_t n) {
  if (w->h->format == PLY_ASCII) {
    vsh__span word;
    if (!vsh__span_word(&w->line, &word))
      return vsh__mc_fail(err, n, "line %zu: %s %" PRIu64 " has too few values", w->line_number,
                          w->e->name, w->entry);
    if (!vsh__span_double(&word, v))
      return vsh__mc_fail(err, n, "line %zu: %s %" PRIu64 " has a value that is not a number "
                          "(got \"%.*s\")", w->line_number, w->e->name, w->entry,
                          (int)(word.end - word.p), word.p);
    return 0;
  }
  if ((size_t)(w->end - w->p) < (size_t)t.size)
    return vsh__mc_fail(err, n, "truncated PLY file: the body ends in %s %" PRIu64 " of %" PRIu64
                        " (the header promises more data than the file holds)", w->e->name,
                        w->entry, w->e->count);
  *v = decode(w->p, t, w->h->format == PLY_BINARY_BE);
  w->p += t.size;
  return 0;
}

static int check_list(ply_walk *w, const ply_property *p, char *err, size_t n) {
  double count, v;
  int64_t k;
  if (next_value(w, p->count, &count, err, n)) return 1;
  if (!(count >= 0 && count <= 1e9 && count == floor(count)))
    return vsh__mc_fail(err, n, "%s %" PRIu64 ": list \"%s\" has a bad length (got %g)",
                        w->e->name, w->entry, p->name, count);
  if (w->e->is_face && p->role == PLY_ROLE_INDICES) {
    if (count < 3 || count > 255)
      return vsh__mc_fail(err, n, "face %" PRIu64 " has %g vertices (3 to 255 are supported)",
                          w->entry, count);
    w->corners = (int64_t)count;
  }
  if (w->e->is_face && p->role == PLY_ROLE_TEXCOORD) w->texcoords = (int64_t)count;
  for (k = 0; k < (int64_t)count; ++k) {
    if (next_value(w, p->type, &v, err, n)) return 1;
    if (w->e->is_face && p->role == PLY_ROLE_INDICES &&
        !(v >= 0 && v < (double)w->h->vertex_count && v == floor(v)))
      return vsh__mc_fail(err, n, "face %" PRIu64 " refers to vertex %.17g but the file has %"
                          PRIu64, w->entry, v, w->h->vertex_count);
  }
  return 0;
}

static int check_entry(ply_walk *w, char *err, size_t n) {
  int i;
  double v;
  w->corners = w->texcoords = -1;
  for (i = 0; i < w->e->property_count; ++i) {
    const ply_property *p = &w->e->properties[i];
    if (p->is_list) {
      if (check_list(w, p, err, n)) return 1;
      continue;
    }
    if (next_value(w, p->type, &v, err, n)) return 1;
    if (w->e->is_vertex && p->role == PLY_ROLE_COORD && !vsh__float_ok(v))
      return vsh__mc_fail(err, n, "vertex %" PRIu64 " has a coordinate %s that is not a finite "
                          "float (got %g)", w->entry, p->name, v);
  }
  if (w->texcoords >= 0 && w->corners >= 0 && w->texcoords != 2 * w->corners)
    return vsh__mc_fail(err, n, "face %" PRIu64 " has %" PRId64 " corners but %" PRId64
                        " texcoord values (2 per corner expected)", w->entry, w->corners,
                        w->texcoords);
  return 0;
}

/* ASCII: vtkPLY reads each entry from its own line, skipping nothing. */
static int ascii_entry(ply_walk *w, vsh__text *text, char *err, size_t n) {
  if (!vsh__text_line(text, &w->line))
    return vsh__mc_fail(err, n, "truncated PLY file: the body ends before %s %" PRIu64 " of %"
                        PRIu64, w->e->name, w->entry, w->e->count);
  w->line_number = w->h->lines + text->line;
  if ((size_t)(w->line.end - w->line.p) > VSH_MESH_MAX_LINE)
    return vsh__mc_fail(err, n, "line %zu is longer than %d characters", w->line_number,
                        VSH_MESH_MAX_LINE);
  if (w->line.end == text->end) /* vtkPLY fails on it, then frees twice: a crash */
    return vsh__mc_fail(err, n, "line %zu: %s %" PRIu64 " is not ended by a newline",
                        w->line_number, w->e->name, w->entry);
  if (memchr(w->line.p, '\0', (size_t)(w->line.end - w->line.p)))
    return vsh__mc_fail(err, n, "line %zu: NUL byte in an ASCII PLY body", w->line_number);
  return check_entry(w, err, n);
}

int vsh_ply_check_buffer(const char *data, size_t size, char *err, size_t n) {
  ply_header h;
  ply_walk w;
  vsh__text text;
  int i;
  uint64_t triangles = 0;
  if (vsh__ply_header(data, size, &h, err, n)) return 1;
  memset(&w, 0, sizeof w);
  w.h = &h;
  w.p = (const unsigned char *)data + h.body;
  w.end = (const unsigned char *)data + size;
  text.p = data + h.body;
  text.end = data + size;
  text.line = 0;
  for (i = 0; i < h.element_count; ++i) {
    w.e = &h.elements[i];
    for (w.entry = 0; w.entry < w.e->count; ++w.entry) {
      if (h.format == PLY_ASCII ? ascii_entry(&w, &text, err, n) : check_entry(&w, err, n))
        return 1;
      if (w.corners > 0 && (triangles += (uint64_t)w.corners - 2) > VSH_MESH_MAX_TRIANGLES)
        return vsh__mc_fail(err, n, "more than %u triangles (the limit)", VSH_MESH_MAX_TRIANGLES);
    }
  }
  return 0;
}

int vsh_ply_check(const char *path, char *err, size_t err_size) {
  return vsh__check_file(path, vsh_ply_check_buffer, err, err_size);
}
