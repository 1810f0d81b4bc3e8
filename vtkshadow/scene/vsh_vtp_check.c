/* vsh_vtp_check.c - the part of a VTP file we can check before
 * vtkXMLPolyDataReader runs: it is a PolyData VTKFile and the counts its
 * Piece elements declare (which the reader allocates from) are well-formed
 * and under the limits. The decoded cell arrays are checked after reading
 * (vsh_cells_check): inline, appended, base64 and compressed data all end up
 * in the same arrays, so one check there covers every encoding. */
#include "vsh_mesh_check_internal.h"

#include <inttypes.h>
#include <string.h>

static const char *find(const char *p, const char *end, const char *s) {
  size_t n = strlen(s);
  for (; p && (size_t)(end - p) >= n; ++p) {
    p = (const char *)memchr(p, s[0], (size_t)(end - p) - n + 1);
    if (!p) return NULL;
    if (memcmp(p, s, n) == 0) return p;
  }
  return NULL;
}

static int is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

/* Value of attribute `name` in the tag [p, end) as an unsigned integer.
 * Returns 1 found and valid, 0 absent, -1 present but not a count. */
static int attribute(const char *p, const char *end, const char *name, uint64_t *value) {
  const size_t n = strlen(name);
  const char *a = p;
  while ((a = find(a, end, name)) != NULL) {
    const char *q = a + n;
    char quote;
    if (a == p || !is_blank(a[-1])) {
      a = q;
      continue;
    }
    while (q < end && is_blank(*q)) ++q;
    if (q >= end || *q != '=') {
      a = q;
      continue;
    }
    ++q;
    while (q < end && is_blank(*q)) ++q;
    if (q >= end || (*q != '"' && *q != '\'')) return -1;
    quote = *q++;
    *value = 0;
    if (q >= end || *q < '0' || *q > '9') return -1;
    for (; q < end && *q >= '0' && *q <= '9'; ++q) {
      if (*value > UINT64_MAX / 20) return -1; /* absurdly long: refuse rather than wrap */
      *value = *value * 10 + (uint64_t)(*q - '0');
    }
    return q < end && *q == quote ? 1 : -1;
  }
  return 0;
}

/* Every DataArray's NumberOfComponents and NumberOfTuples: VTK 9.1 sizes a
 * vector from them before reading any data (NumberOfComponents="-1" throws
 * std::length_error out of the reader). */
#define VTP_MAX_COMPONENTS 1024
static int check_arrays(const char *p, const char *end, char *err, size_t err_size) {
  size_t index = 0;
  while ((p = find(p, end, "<DataArray")) != NULL) {
    const char *tag_end = (const char *)memchr(p, '>', (size_t)(end - p));
    uint64_t v = 0;
    int rc;
    if (!tag_end) return vsh__mc_fail(err, err_size, "unterminated <DataArray> element");
    ++index;
    rc = attribute(p, tag_end, "NumberOfComponents", &v);
    if (rc < 0 || (rc > 0 && (v == 0 || v > VTP_MAX_COMPONENTS)))
      return vsh__mc_fail(err, err_size, "DataArray %zu: NumberOfComponents is not a count from 1 "
                          "to %d", index, VTP_MAX_COMPONENTS);
    rc = attribute(p, tag_end, "NumberOfTuples", &v);
    if (rc < 0 || v > 4ull * VSH_MESH_MAX_TRIANGLES)
      return vsh__mc_fail(err, err_size, "DataArray %zu: NumberOfTuples is not a count under %llu",
                          index, 4ull * VSH_MESH_MAX_TRIANGLES);
    p = tag_end;
  }
  return 0;
}

int vsh_vtp_check_buffer(const char *data, size_t size, char *err, size_t err_size) {
  static const char *const counts[] = {"NumberOfPoints", "NumberOfVerts", "NumberOfLines",
                                       "NumberOfStrips", "NumberOfPolys"};
  const char *end = data + size, *appended, *file, *piece, *tag_end;
  uint64_t total[5] = {0, 0, 0, 0, 0};
  size_t k, pieces = 0;
  /* Raw appended data may contain any bytes, "<Piece" included: stop there. */
  appended = find(data, end, "<AppendedData");
  if (appended) end = appended;
  file = find(data, end, "<VTKFile");
  if (!file || !(tag_end = (const char *)memchr(file, '>', (size_t)(end - file))))
    return vsh__mc_fail(err, err_size, "not a VTK XML file (no <VTKFile> element)");
  if (!find(file, tag_end, "type=\"PolyData\""))
    return vsh__mc_fail(err, err_size, "VTK XML file is not of type PolyData");
  for (piece = find(tag_end, end, "<Piece"); piece; piece = find(tag_end, end, "<Piece")) {
    tag_end = (const char *)memchr(piece, '>', (size_t)(end - piece));
    if (!tag_end) return vsh__mc_fail(err, err_size, "unterminated <Piece> element");
    ++pieces;
    for (k = 0; k < 5; ++k) {
      uint64_t v = 0;
      int rc = attribute(piece, tag_end, counts[k], &v);
      if (rc < 0)
        return vsh__mc_fail(err, err_size, "Piece %zu: %s is not a count", pieces, counts[k]);
      total[k] += v;
      if (total[k] > (k == 0 ? VSH_MESH_MAX_POINTS : VSH_MESH_MAX_TRIANGLES))
        return vsh__mc_fail(err, err_size, "%s adds up to %" PRIu64 ", over the limit of %u",
                            counts[k], total[k],
                            k == 0 ? VSH_MESH_MAX_POINTS : VSH_MESH_MAX_TRIANGLES);
    }
  }
  if (pieces == 0) return vsh__mc_fail(err, err_size, "VTP file has no <Piece> element");
  return check_arrays(file, end, err, err_size);
}

int vsh_vtp_check(const char *path, char *err, size_t err_size) {
  return vsh__check_file(path, vsh_vtp_check_buffer, err, err_size);
}
