/* vsh_mesh_check_internal.h - helpers shared by the mesh file checkers:
 * messages, a bounded text cursor (the buffers are not NUL-terminated) and
 * number parsing that never reads past the end. */
#ifndef VSH_MESH_CHECK_INTERNAL_H
#define VSH_MESH_CHECK_INTERNAL_H

#include "vsh_mesh_check.h"

#include <stddef.h>
#include <stdint.h>

/* Formats a message into err; always returns 1 (the checkers' "bad file"). */
int vsh__mc_fail(char *err, size_t err_size, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* A line-by-line, word-by-word reader over [p, end). Lines end at '\n'; a
 * '\r' before it is whitespace. */
typedef struct vsh__text {
  const char *p, *end;
  size_t line; /* 1-based number of the line last returned by vsh__text_line */
} vsh__text;

typedef struct vsh__span {
  const char *p, *end;
} vsh__span;

/* Next line into *line (without its '\n'); 0 at the end of the text. */
int vsh__text_line(vsh__text *t, vsh__span *line);
/* Next whitespace-separated word of *line into *word (and consumes it); 0 when
 * the line has no more words. */
int vsh__span_word(vsh__span *line, vsh__span *word);
int vsh__span_is(const vsh__span *word, const char *s);
/* The whole word as a number; 0 if it is not one (or is absurdly long). */
int vsh__span_double(const vsh__span *word, double *value);
int vsh__span_int64(const vsh__span *word, int64_t *value);
/* finite and representable as a float (VTK stores OBJ/PLY/STL points as float) */
int vsh__float_ok(double v);

/* The whole file in memory (mapped where the system allows it). */
typedef struct vsh__file {
  const char *data;
  size_t size;
  void *handle; /* what to release */
  int mapped;
} vsh__file;
int vsh__file_open(const char *path, vsh__file *f, char *err, size_t err_size);
void vsh__file_close(vsh__file *f);

/* Runs a buffer checker on a file. */
int vsh__check_file(const char *path, int (*check)(const char *, size_t, char *, size_t),
                    char *err, size_t err_size);
#endif
