/* vshm_atomic.c - see vshm_atomic.h. */
/* fsync, fileno and getpid are POSIX, not C11. */
#define _POSIX_C_SOURCE 200809L

#include "vshm_atomic.h"

#include <errno.h>
#include <stdarg.h>
#include <string.h>
#include <unistd.h>

static void set_err(char *err, size_t errlen, const char *fmt, ...) {
  if (!err || errlen == 0) return;
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(err, errlen, fmt, ap);
  va_end(ap);
}

int vshm_atomic_open(vshm_atomic_file *af, const char *path, char *err, size_t errlen) {
  af->fp = NULL;
  af->path = path;
  af->tmp[0] = '\0';
  if (!path || !*path) {
    set_err(err, errlen, "(empty path): cannot write");
    return -1;
  }
  int n = snprintf(af->tmp, sizeof af->tmp, "%s.tmp%ld", path, (long)getpid());
  if (n < 0 || (size_t)n >= sizeof af->tmp) {
    set_err(err, errlen, "%s: path too long", path);
    af->tmp[0] = '\0';
    return -1;
  }
  af->fp = fopen(af->tmp, "wb");
  if (!af->fp) {
    set_err(err, errlen, "%s: cannot create temporary file %s (%s)", path, af->tmp,
            strerror(errno));
    af->tmp[0] = '\0';
    return -1;
  }
  return 0;
}

void vshm_atomic_abort(vshm_atomic_file *af) {
  if (af->fp) fclose(af->fp);
  af->fp = NULL;
  if (af->tmp[0]) remove(af->tmp);
  af->tmp[0] = '\0';
}

int vshm_atomic_commit(vshm_atomic_file *af, char *err, size_t errlen) {
  /* Every step can report a late write error (full disk, quota): check
   * them all, otherwise a truncated file would be renamed into place. */
  if (fflush(af->fp) != 0 || ferror(af->fp)) {
    set_err(err, errlen, "%s: write failed (%s)", af->path, strerror(errno));
    vshm_atomic_abort(af);
    return -1;
  }
  /* Without fsync a crash soon after rename() can leave an empty file
   * under the final name on some file systems. */
  if (fsync(fileno(af->fp)) != 0 && errno != EINVAL) {
    set_err(err, errlen, "%s: fsync failed (%s)", af->path, strerror(errno));
    vshm_atomic_abort(af);
    return -1;
  }
  int rc = fclose(af->fp);
  af->fp = NULL;
  if (rc != 0) {
    set_err(err, errlen, "%s: close failed (%s)", af->path, strerror(errno));
    vshm_atomic_abort(af);
    return -1;
  }
  if (rename(af->tmp, af->path) != 0) {
    set_err(err, errlen, "%s: cannot rename %s into place (%s)", af->path, af->tmp,
            strerror(errno));
    vshm_atomic_abort(af);
    return -1;
  }
  af->tmp[0] = '\0';
  return 0;
}

int vshm_write_file_atomic(const char *path, const void *data, size_t len, char *err,
                           size_t errlen) {
  vshm_atomic_file af;
  if (vshm_atomic_open(&af, path, err, errlen) != 0) return -1;
  if (len > 0 && fwrite(data, 1, len, af.fp) != len) {
    set_err(err, errlen, "%s: write failed (%s)", path, strerror(errno));
    vshm_atomic_abort(&af);
    return -1;
  }
  return vshm_atomic_commit(&af, err, errlen);
}
