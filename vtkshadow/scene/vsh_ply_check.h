/* vsh_ply_check.h - refuse PLY files that VTK 9.1's PLY reader would crash on.
 *
 * VTK 9.1's vtkPLYReader reads past the end of a truncated file (it segfaults
 * or corrupts the heap: seen on ASCII and binary files whose header promises
 * more elements than the body holds). Before a PLY file reaches it, we check
 * that the body is at least as long as the header says: for binary files the
 * byte count, for ASCII files the line count. */
#ifndef VSH_PLY_CHECK_H
#define VSH_PLY_CHECK_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Returns 0 when `path` is a PLY file whose body is long enough for its
 * header; otherwise non-zero with a reason in err (no file name in it). */
int vsh_ply_check(const char *path, char *err, size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
