/* vsh_mesh_check_util.c - messages, bounded text scanning and file mapping for
 * the mesh checkers. The file is mapped rather than read so that checking a
 * multi-gigabyte mesh costs address space, not memory. */
#define _POSIX_C_SOURCE 200809L
#include "vsh_mesh_check_internal.h"

#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__unix__) || defined(__APPLE__)
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#define VSH_HAVE_MMAP 1
#endif

int vsh__mc_fail(char *err, size_t err_size, const char *fmt, ...) {
  if (err && err_size) {
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err, err_size, fmt, ap);
    va_end(ap);
  }
  return 1;
}

int vsh__text_line(vsh__text *t, vsh__span *line) {
  const char *nl;
  if (t->p >= t->end) return 0;
  nl = (const char *)memchr(t->p, '\n', (size_t)(t->end - t->p));
  line->p = t->p;
  line->end = nl ? nl : t->end;
  t->p = nl ? nl + 1 : t->end;
  ++t->line;
  return 1;
}

static int is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f' || c == '\n';
}

int vsh__span_word(vsh__span *line, vsh__span *word) {
  const char *p = line->p;
  while (p < line->end && is_space(*p)) ++p;
  if (p >= line->end) {
    line->p = line->end;
    return 0;
  }
  word->p = p;
  while (p < line->end && !is_space(*p)) ++p;
  word->end = p;
  line->p = p;
  return 1;
}

int vsh__span_is(const vsh__span *word, const char *s) {
  size_t n = strlen(s);
  return (size_t)(word->end - word->p) == n && memcmp(word->p, s, n) == 0;
}

/* Copies a word into a NUL-terminated buffer for strtod/strtoll. */
static int word_copy(const vsh__span *word, char *buf, size_t size) {
  size_t n = (size_t)(word->end - word->p);
  if (n == 0 || n >= size) return 0;
  memcpy(buf, word->p, n);
  buf[n] = '\0';
  return 1;
}

int vsh__span_double(const vsh__span *word, double *value) {
  char buf[256], *end = NULL;
  if (!word_copy(word, buf, sizeof buf)) return 0;
  errno = 0;
  *value = strtod(buf, &end);
  return end != buf && *end == '\0';
}

int vsh__span_int64(const vsh__span *word, int64_t *value) {
  char buf[64], *end = NULL;
  long long v;
  if (!word_copy(word, buf, sizeof buf)) return 0;
  errno = 0;
  v = strtoll(buf, &end, 10);
  if (end == buf || *end != '\0' || errno == ERANGE) return 0;
  *value = (int64_t)v;
  return 1;
}

int vsh__float_ok(double v) { return isfinite(v) && fabs(v) <= FLT_MAX; }

int vsh__file_open(const char *path, vsh__file *f, char *err, size_t err_size) {
  memset(f, 0, sizeof *f);
  f->data = "";
#ifdef VSH_HAVE_MMAP
  {
    struct stat st;
    int fd = open(path, O_RDONLY);
    if (fd < 0) return vsh__mc_fail(err, err_size, "cannot open (%s)", strerror(errno));
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
      close(fd);
      return vsh__mc_fail(err, err_size, "not a regular file");
    }
    if (st.st_size > 0) {
      void *p = mmap(NULL, (size_t)st.st_size, PROT_READ, MAP_PRIVATE, fd, 0);
      if (p == MAP_FAILED) {
        close(fd);
        return vsh__mc_fail(err, err_size, "cannot map (%s)", strerror(errno));
      }
      f->data = (const char *)p;
      f->size = (size_t)st.st_size;
      f->handle = p;
      f->mapped = 1;
    }
    close(fd);
    return 0;
  }
#else
  {
    FILE *fp = fopen(path, "rb");
    long size;
    char *buf;
    if (!fp) return vsh__mc_fail(err, err_size, "cannot open (%s)", strerror(errno));
    if (fseek(fp, 0, SEEK_END) != 0 || (size = ftell(fp)) < 0 || fseek(fp, 0, SEEK_SET) != 0) {
      fclose(fp);
      return vsh__mc_fail(err, err_size, "cannot measure the file");
    }
    buf = (char *)malloc((size_t)size + 1);
    if (!buf || fread(buf, 1, (size_t)size, fp) != (size_t)size) {
      free(buf);
      fclose(fp);
      return vsh__mc_fail(err, err_size, "cannot read the file");
    }
    fclose(fp);
    f->data = buf;
    f->size = (size_t)size;
    f->handle = buf;
    return 0;
  }
#endif
}

void vsh__file_close(vsh__file *f) {
  if (!f->handle) return;
#ifdef VSH_HAVE_MMAP
  if (f->mapped) munmap(f->handle, f->size);
#else
  free(f->handle);
#endif
  memset(f, 0, sizeof *f);
}

int vsh__check_file(const char *path, int (*check)(const char *, size_t, char *, size_t),
                    char *err, size_t err_size) {
  vsh__file f;
  int rc;
  if (vsh__file_open(path, &f, err, err_size) != 0) return 1;
  rc = check(f.data, f.size, err, err_size);
  vsh__file_close(&f);
  return rc;
}
