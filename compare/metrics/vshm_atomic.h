/* vshm_atomic.h - replace a file atomically: write "<path>.tmp<pid>", then
 * rename() it over <path>.
 *
 * Why: the harness runs many tools in parallel and may be interrupted. A
 * reader (or a rerun that skips existing outputs) must never see a half
 * written PNG or JSON file: rename() within one directory is atomic on
 * POSIX, so <path> is either the old file, absent, or complete. The pid in
 * the temporary name keeps two processes writing the same path apart.
 *
 * Errors go to err (may be NULL) as "<path>: <problem>"; nothing is printed.
 */
#ifndef VSHM_ATOMIC_H
#define VSHM_ATOMIC_H

#include <stddef.h>
#include <stdio.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Enough for any path the tools take plus ".tmp" and a pid. */
#define VSHM_ATOMIC_TMP_MAX 4096

typedef struct vshm_atomic_file {
  FILE *fp;                      /* write the content here */
  const char *path;              /* final destination (not copied) */
  char tmp[VSHM_ATOMIC_TMP_MAX];  /* the temporary file */
} vshm_atomic_file;

/* Creates the temporary file. Returns 0, or -1 with err set (nothing is
 * left on disk). */
int vshm_atomic_open(vshm_atomic_file *af, const char *path, char *err, size_t errlen);

/* Flushes, syncs and closes the temporary file, then renames it to the
 * final path. Returns 0, or -1 with err set; on failure the temporary file
 * is removed and the final path is untouched. */
int vshm_atomic_commit(vshm_atomic_file *af, char *err, size_t errlen);

/* Closes and removes the temporary file (after a failed write). */
void vshm_atomic_abort(vshm_atomic_file *af);

/* Whole-buffer convenience: writes len bytes of data to path atomically. */
int vshm_write_file_atomic(const char *path, const void *data, size_t len, char *err,
                           size_t errlen);

#ifdef __cplusplus
}
#endif

#endif
