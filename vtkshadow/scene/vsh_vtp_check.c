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

/* Compressed data starts with a header of unsigned words (UInt32 or UInt64,
 * in the file's byte order): block count, block size, last block size, then
 * one compressed size per block. VTK 9.1 sizes a vector from the block count
 * before checking it against the data (a count of 2^32-1 fills 16 GB), so the
 * header must fit in what follows it and the blocks must be of sane size. */
typedef struct vtp_words {
  int word;       /* 4 or 8 */
  int big_endian;
} vtp_words;

static uint64_t word_at(const unsigned char *p, vtp_words w) {
  uint64_t v = 0;
  int i;
  for (i = 0; i < w.word; ++i) v |= (uint64_t)p[w.big_endian ? w.word - 1 - i : i] << (8 * i);
  return v;
}

#define VTP_MAX_BLOCK (1u << 30)
static int check_compression_header(const unsigned char *p, size_t available, vtp_words w,
                                    size_t index, char *err, size_t err_size) {
  uint64_t blocks, block, last;
  if (available < 3u * (size_t)w.word)
    return vsh__mc_fail(err, err_size, "DataArray %zu: compressed data header is cut off", index);
  blocks = word_at(p, w);
  block = word_at(p + w.word, w);
  last = word_at(p + 2 * w.word, w);
  if (blocks > (available / (size_t)w.word) - 3 || block > VTP_MAX_BLOCK || last > block)
    return vsh__mc_fail(err, err_size, "DataArray %zu: compressed data header is inconsistent "
                        "(%" PRIu64 " blocks of %" PRIu64 " bytes, last %" PRIu64 ", in %zu bytes)",
                        index, blocks, block, last, available);
  return 0;
}

static int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  return c == '+' ? 62 : c == '/' ? 63 : -1;
}

/* Decodes up to `max` bytes of base64 text [p, end) (whitespace skipped). */
static size_t base64_decode(const char *p, const char *end, unsigned char *out, size_t max) {
  size_t n = 0;
  unsigned bits = 0, acc = 0;
  for (; p < end && n < max; ++p) {
    int v = base64_value(*p);
    if (v < 0) {
      if (*p == '=' || *p == '<') break;
      continue;
    }
    acc = (acc << 6) | (unsigned)v;
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out[n++] = (unsigned char)(acc >> bits);
    }
  }
  return n;
}

typedef struct vtp_doc {
  const char *data, *end;    /* whole file */
  const char *appended;      /* first byte after '_' of raw appended data, or NULL */
  int appended_base64;
  vtp_words w;
} vtp_doc;

/* The compression header of DataArray `index`, whose tag is [tag, tag_end). */
static int check_compressed_array(const vtp_doc *d, const char *tag, const char *tag_end,
                                  size_t index, char *err, size_t err_size) {
  unsigned char head[4096];
  uint64_t offset = 0;
  const char *fmt_appended = find(tag, tag_end, "format=\"appended\"");
  if (fmt_appended) {
    if (attribute(tag, tag_end, "offset", &offset) <= 0)
      return vsh__mc_fail(err, err_size, "DataArray %zu: appended without an offset", index);
    if (!d->appended || offset >= (uint64_t)(d->end - d->appended))
      return vsh__mc_fail(err, err_size, "DataArray %zu: offset %" PRIu64 " is past the appended "
                          "data", index, offset);
    if (!d->appended_base64)
      return check_compression_header((const unsigned char *)d->appended + offset,
                                      (size_t)(d->end - d->appended - offset), d->w, index, err,
                                      err_size);
    {
      size_t n = base64_decode(d->appended + offset, d->end, head, sizeof head);
      size_t text = (size_t)(d->end - d->appended - offset);
      return check_compression_header(head, n < sizeof head ? n : text / 4 * 3, d->w, index, err,
                                      err_size);
    }
  }
  if (find(tag, tag_end, "format=\"binary\"")) {
    const char *close = find(tag_end, d->end, "</DataArray>");
    size_t n, text;
    if (!close) return vsh__mc_fail(err, err_size, "DataArray %zu: unterminated", index);
    text = (size_t)(close - tag_end - 1);
    n = base64_decode(tag_end + 1, close, head, sizeof head);
    return check_compression_header(head, n < sizeof head ? n : text / 4 * 3, d->w, index, err,
                                    err_size);
  }
  return 0;
}

static int check_compressed(const char *data, const char *end, const char *file,
                            const char *file_end, const char *xml_end, char *err,
                            size_t err_size) {
  vtp_doc d;
  const char *p = file, *raw;
  size_t index = 0;
  if (!find(file, file_end, "compressor=")) return 0;
  d.data = data;
  d.end = end;
  d.w.word = find(file, file_end, "header_type=\"UInt64\"") ? 8 : 4;
  d.w.big_endian = find(file, file_end, "byte_order=\"BigEndian\"") != NULL;
  d.appended = NULL;
  d.appended_base64 = 0;
  if (xml_end < end) { /* <AppendedData encoding="..."> then '_' */
    const char *tag_end = (const char *)memchr(xml_end, '>', (size_t)(end - xml_end));
    raw = tag_end ? (const char *)memchr(tag_end, '_', (size_t)(end - tag_end)) : NULL;
    d.appended = raw ? raw + 1 : NULL;
    d.appended_base64 = tag_end && find(xml_end, tag_end, "base64") != NULL;
  }
  while ((p = find(p, xml_end, "<DataArray")) != NULL) {
    const char *tag_end = (const char *)memchr(p, '>', (size_t)(xml_end - p));
    if (!tag_end) return vsh__mc_fail(err, err_size, "unterminated <DataArray> element");
    if (check_compressed_array(&d, p, tag_end, ++index, err, err_size)) return 1;
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
  if (check_arrays(file, end, err, err_size)) return 1;
  {
    const char *file_end = (const char *)memchr(file, '>', (size_t)(end - file));
    return check_compressed(data, data + size, file, file_end, end, err, err_size);
  }
}

int vsh_vtp_check(const char *path, char *err, size_t err_size) {
  return vsh__check_file(path, vsh_vtp_check_buffer, err, err_size);
}
