/* vsh_stl_check.c - scan an STL file before vtkSTLReader sees it.
 *
 * Binary: VTK 9.1 sizes its arrays from the triangle count in the header, so
 * a header claiming 2^31 triangles aborts the process with std::bad_alloc.
 * The count must fit in the file (84 + 50 bytes per triangle) and under the
 * limit. ASCII: the solid/facet/loop/vertex structure, and vertex coordinates
 * that are finite floats (the reader stores floats).
 *
 * Which of the two a file is must be decided exactly like VTK 9.1 does
 * (vtksys::SystemTools::DetectFileType: of the first 256 bytes, 5% or more
 * outside printable ASCII, tab, CR and LF means binary), or a file we
 * checked as one kind would be read as the other. */
#include "vsh_mesh_check_internal.h"

#include <ctype.h>
#include <inttypes.h>
#include <math.h>
#include <string.h>

#define STL_HEADER 84
#define STL_RECORD 50

/* 1 for binary, 0 for ASCII, -1 when bytes whose class we are not sure VTK
 * agrees on (DEL, vertical tab, form feed) decide it. */
static int stl_is_binary(const char *data, size_t size) {
  size_t n = size < 256 ? size : 256, i, text = 0, unsure = 0;
  int strict, loose;
  if (n == 0) return 1; /* VTK: unknown type, "attempting binary" */
  for (i = 0; i < n; ++i) {
    const unsigned char c = (unsigned char)data[i];
    if ((c >= 0x20 && c < 0x7F) || c == '\n' || c == '\r' || c == '\t')
      ++text;
    else if (c == 0x7F || c == '\v' || c == '\f')
      ++unsure;
  }
  strict = (double)(n - text) / (double)n >= 0.05;
  loose = (double)(n - text - unsure) / (double)n >= 0.05;
  return strict == loose ? strict : -1;
}

static uint32_t le32(const unsigned char *p) {
  return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static float le_float(const unsigned char *p) {
  uint32_t u = le32(p);
  float f;
  memcpy(&f, &u, sizeof f);
  return f;
}

static int check_binary(const unsigned char *data, size_t size, char *err, size_t err_size) {
  uint64_t claimed, held, t;
  if (size < STL_HEADER)
    return vsh__mc_fail(err, err_size, "binary STL file of %zu bytes is shorter than the 84-byte "
                        "header", size);
  claimed = le32(data + 80);
  held = (size - STL_HEADER) / STL_RECORD;
  if (claimed > held)
    return vsh__mc_fail(err, err_size, "binary STL header says %" PRIu64 " triangles but the "
                        "file holds only %" PRIu64 " (%zu bytes; %" PRIu64 " triangles need %"
                        PRIu64 ")", claimed, held, size, claimed,
                        (uint64_t)STL_HEADER + claimed * STL_RECORD);
  if ((size - STL_HEADER) % STL_RECORD != 0)
    return vsh__mc_fail(err, err_size, "binary STL body is not a whole number of 50-byte "
                        "triangles (%zu bytes after the header)", size - STL_HEADER);
  if (held > VSH_MESH_MAX_TRIANGLES)
    return vsh__mc_fail(err, err_size, "binary STL has %" PRIu64 " triangles, over the limit of "
                        "%u", held, VSH_MESH_MAX_TRIANGLES);
  for (t = 0; t < held; ++t) {
    const unsigned char *corner = data + STL_HEADER + t * STL_RECORD + 12; /* after the normal */
    int k;
    for (k = 0; k < 9; ++k)
      if (!isfinite(le_float(corner + 4 * k)))
        return vsh__mc_fail(err, err_size, "triangle %" PRIu64 " has a vertex coordinate that "
                            "is not finite (got %g)", t + 1, (double)le_float(corner + 4 * k));
  }
  return 0;
}

/* Words of an ASCII STL across lines. */
typedef struct stl_words {
  vsh__text text;
  vsh__span line, word;
} stl_words;

static int next_word(stl_words *w) {
  while (!vsh__span_word(&w->line, &w->word))
    if (!vsh__text_line(&w->text, &w->line)) return 0;
  return 1;
}

static int word_is(const stl_words *w, const char *s) {
  size_t n = strlen(s), i;
  if ((size_t)(w->word.end - w->word.p) != n) return 0;
  for (i = 0; i < n; ++i)
    if (tolower((unsigned char)w->word.p[i]) != s[i]) return 0;
  return 1;
}

static int expect(stl_words *w, const char *s, char *err, size_t err_size) {
  if (next_word(w) && word_is(w, s)) return 0;
  return vsh__mc_fail(err, err_size, "line %zu: expected \"%s\" in ASCII STL", w->text.line, s);
}

/* "facet normal nx ny nz outer loop vertex x y z (x3) endloop endfacet" after "facet". */
static int check_facet(stl_words *w, uint64_t facet, char *err, size_t err_size) {
  int k, c;
  double v;
  if (expect(w, "normal", err, err_size)) return 1;
  for (k = 0; k < 3; ++k)
    if (!next_word(w) || !vsh__span_double(&w->word, &v))
      return vsh__mc_fail(err, err_size, "line %zu: facet %" PRIu64 " normal is not 3 numbers",
                          w->text.line, facet);
  if (expect(w, "outer", err, err_size) || expect(w, "loop", err, err_size)) return 1;
  for (c = 0; c < 3; ++c) {
    if (expect(w, "vertex", err, err_size)) return 1;
    for (k = 0; k < 3; ++k) {
      if (!next_word(w) || !vsh__span_double(&w->word, &v))
        return vsh__mc_fail(err, err_size, "line %zu: facet %" PRIu64 " vertex is not 3 numbers",
                            w->text.line, facet);
      if (!vsh__float_ok(v))
        return vsh__mc_fail(err, err_size, "line %zu: facet %" PRIu64 " has a vertex coordinate "
                            "that is not a finite float (got \"%.*s\")", w->text.line, facet,
                            (int)(w->word.end - w->word.p), w->word.p);
    }
  }
  if (expect(w, "endloop", err, err_size) || expect(w, "endfacet", err, err_size)) return 1;
  return 0;
}

static int check_ascii(const char *data, size_t size, char *err, size_t err_size) {
  stl_words w;
  uint64_t facets = 0;
  memset(&w, 0, sizeof w);
  w.text.p = data;
  w.text.end = data + size;
  if (memchr(data, '\0', size))
    return vsh__mc_fail(err, err_size, "ASCII STL contains NUL bytes");
  while (vsh__text_line(&w.text, &w.line)) { /* line lengths first: VTK reads by lines */
    if ((size_t)(w.line.end - w.line.p) > VSH_MESH_MAX_LINE)
      return vsh__mc_fail(err, err_size, "line %zu is longer than %d characters", w.text.line,
                          VSH_MESH_MAX_LINE);
  }
  w.text.p = data;
  w.text.line = 0;
  w.line.p = w.line.end = data;
  if (expect(&w, "solid", err, err_size)) return 1;
  w.line.p = w.line.end; /* the solid's name: rest of the line */
  while (next_word(&w)) {
    if (word_is(&w, "facet")) {
      if (check_facet(&w, ++facets, err, err_size)) return 1;
      if (facets > VSH_MESH_MAX_TRIANGLES)
        return vsh__mc_fail(err, err_size, "more than %u facets (the limit)",
                            VSH_MESH_MAX_TRIANGLES);
    } else if (word_is(&w, "endsolid") || word_is(&w, "solid")) {
      w.line.p = w.line.end; /* name */
    } else {
      return vsh__mc_fail(err, err_size, "line %zu: expected \"facet\" or \"endsolid\" in ASCII "
                          "STL (got \"%.*s\")", w.text.line, (int)(w.word.end - w.word.p),
                          w.word.p);
    }
  }
  return 0;
}

int vsh_stl_check_buffer(const char *data, size_t size, char *err, size_t err_size) {
  switch (stl_is_binary(data, size)) {
  case 1:
    return check_binary((const unsigned char *)data, size, err, err_size);
  case 0:
    return check_ascii(data, size, err, err_size);
  default:
    return vsh__mc_fail(err, err_size, "cannot tell whether this STL file is ASCII or binary "
                        "(DEL, vertical-tab or form-feed bytes in its first 256)");
  }
}

int vsh_stl_check(const char *path, char *err, size_t err_size) {
  return vsh__check_file(path, vsh_stl_check_buffer, err, err_size);
}
