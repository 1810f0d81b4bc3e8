/* vsh_mesh_check.h - validate mesh files before (or right after) VTK reads them.
 *
 * VTK 9.1's readers trust their input: an OBJ face naming a vertex that does
 * not exist, a PLY face index past the vertex count or a truncated PLY body,
 * a binary STL header claiming 2^31 triangles, a VTP connectivity entry past
 * its points all crash or abort the process. These checkers scan the bytes
 * first (OBJ, PLY, STL; the XML header of VTP) and, for VTP, the cell arrays
 * right after vtkXMLPolyDataReader has decoded them, so that a bad file
 * becomes an error message instead of a crash.
 *
 * Every checker returns 0 for an acceptable file, otherwise non-zero with one
 * line in err saying what is wrong (without the file name: the caller names the
 * scene file and the field), e.g. "face 17 refers to vertex 1200 but the file
 * has 1000 vertices".
 *
 * Limits (docs/scene-format.md, "Mesh validation and limits"): at most
 * VSH_MESH_MAX_TRIANGLES triangles (polygons count as n-2 triangles) and
 * VSH_MESH_MAX_POINTS points per mesh file; coordinates must be finite and,
 * for formats VTK stores in single precision (OBJ, PLY, STL), within float
 * range. */
#ifndef VSH_MESH_CHECK_H
#define VSH_MESH_CHECK_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define VSH_MESH_MAX_TRIANGLES 50000000u
#define VSH_MESH_MAX_POINTS 50000000u
/* Longest text line accepted in OBJ / ASCII PLY / ASCII STL files: VTK 9.1's
 * PLY reader reads lines through a 4096-byte buffer and splits longer ones,
 * which would desynchronise it from our scan. */
#define VSH_MESH_MAX_LINE 4000

/* Byte-buffer checkers (what the fuzz targets call). `data` need not be
 * NUL-terminated; nothing past data[size-1] is read. */
int vsh_obj_check_buffer(const char *data, size_t size, char *err, size_t err_size);
int vsh_ply_check_buffer(const char *data, size_t size, char *err, size_t err_size);
int vsh_stl_check_buffer(const char *data, size_t size, char *err, size_t err_size);
/* VTP before reading: the XML must hold one PolyData Piece whose declared
 * counts are under the limits. */
int vsh_vtp_check_buffer(const char *data, size_t size, char *err, size_t err_size);

/* File checkers: map the file and run the buffer checker for its format. */
int vsh_obj_check(const char *path, char *err, size_t err_size);
int vsh_ply_check(const char *path, char *err, size_t err_size);
int vsh_stl_check(const char *path, char *err, size_t err_size);
int vsh_vtp_check(const char *path, char *err, size_t err_size);

/* One cell array as VTK 9.1's vtkCellArray stores it: offsets (count+1
 * entries, starting at 0) and connectivity, both 32- or 64-bit. `what` names
 * the array in messages ("polygon", "strip", ...). Checks that offsets start at
 * 0, never decrease and end at the connectivity size, and that every id is a
 * point that exists. Adds the triangles the cells will become to *triangles. */
typedef struct vsh_cell_arrays {
  const void *offsets;
  const void *connectivity;
  int is_64bit;
  size_t offset_count;       /* number of entries in offsets (cells + 1), 0 if empty */
  size_t connectivity_count; /* number of entries in connectivity */
} vsh_cell_arrays;
int vsh_cells_check(const vsh_cell_arrays *cells, const char *what, size_t point_count,
                    uint64_t *triangles, char *err, size_t err_size);

/* Point coordinates after reading (x0 y0 z0 x1 ...): all finite. */
int vsh_points_check_double(const double *xyz, size_t point_count, char *err, size_t err_size);
int vsh_points_check_float(const float *xyz, size_t point_count, char *err, size_t err_size);

#ifdef __cplusplus
}
#endif
#endif
