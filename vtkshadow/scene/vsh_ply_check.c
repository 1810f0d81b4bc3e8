#include "vsh_ply_check.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PLY_MAX_LINE 1024
#define PLY_MAX_HEADER_LINES 10000

/* Bytes of one PLY scalar type, 0 for an unknown name. */
static int ply_type_size(const char *name)
{
  static const struct { const char *name; int size; } types[] = {
    {"char", 1}, {"uchar", 1}, {"int8", 1}, {"uint8", 1},
    {"short", 2}, {"ushort", 2}, {"int16", 2}, {"uint16", 2},
    {"int", 4}, {"uint", 4}, {"int32", 4}, {"uint32", 4}, {"float", 4}, {"float32", 4},
    {"double", 8}, {"float64", 8}};
  for (size_t i = 0; i < sizeof types / sizeof types[0]; ++i)
    if (strcmp(name, types[i].name) == 0)
      return types[i].size;
  return 0;
}

static int fail(char *err, size_t err_size, const char *message)
{
  if (err && err_size)
    snprintf(err, err_size, "%s", message);
  return 1;
}

int vsh_ply_check(const char *path, char *err, size_t err_size)
{
  FILE *f = fopen(path, "rb");
  if (!f) {
    char msg[256];
    snprintf(msg, sizeof msg, "cannot open (%s)", strerror(errno));
    return fail(err, err_size, msg);
  }
  char line[PLY_MAX_LINE];
  int ascii = -1, saw_end = 0;
  /* Minimum body size: bytes for binary files, lines for ASCII ones. */
  double min_bytes = 0.0, min_lines = 0.0, element_count = 0.0, element_bytes = 0.0;
  int in_element = 0;
  if (!fgets(line, sizeof line, f) || strncmp(line, "ply", 3) != 0) {
    fclose(f);
    return fail(err, err_size, "not a PLY file (no \"ply\" magic line)");
  }
  for (int n = 0; n < PLY_MAX_HEADER_LINES && fgets(line, sizeof line, f); ++n) {
    char word[64] = "", a[64] = "", b[64] = "", c[64] = "";
    const int fields = sscanf(line, "%63s %63s %63s %63s", word, a, b, c);
    if (fields < 1)
      continue;
    if (strcmp(word, "end_header") == 0) {
      saw_end = 1;
      break;
    }
    if (strcmp(word, "format") == 0) {
      ascii = strcmp(a, "ascii") == 0 ? 1
            : (strcmp(a, "binary_little_endian") == 0 || strcmp(a, "binary_big_endian") == 0) ? 0
                                                                                                : -2;
    } else if (strcmp(word, "element") == 0) {
      if (in_element)
        min_bytes += element_count * element_bytes;
      char *end = NULL;
      element_count = strtod(b, &end);
      if (fields < 3 || end == b || *end != '\0' || element_count < 0 || element_count > 1e10) {
        fclose(f);
        return fail(err, err_size, "PLY header has a bad element count");
      }
      min_lines += element_count;
      element_bytes = 0.0;
      in_element = 1;
    } else if (strcmp(word, "property") == 0) {
      /* "property list COUNT_TYPE ITEM_TYPE NAME": at least the count. */
      const int size = ply_type_size(strcmp(a, "list") == 0 ? b : a);
      if (!in_element || size == 0) {
        fclose(f);
        return fail(err, err_size, "PLY header has a bad property line");
      }
      element_bytes += size;
    }
  }
  if (in_element)
    min_bytes += element_count * element_bytes;
  if (!saw_end || ascii < 0) {
    fclose(f);
    return fail(err, err_size, saw_end ? "PLY header has no known format line"
                                       : "PLY header has no end_header line");
  }
  int truncated = 0;
  if (ascii) {
    double lines = 0.0;
    int c, blank = 1;
    while ((c = fgetc(f)) != EOF) {
      if (c == '\n') {
        lines += blank ? 0 : 1;
        blank = 1;
      } else if (c != ' ' && c != '\t' && c != '\r') {
        blank = 0;
      }
    }
    lines += blank ? 0 : 1;
    truncated = lines < min_lines;
  } else {
    const long start = ftell(f);
    if (start < 0 || fseek(f, 0, SEEK_END) != 0) {
      fclose(f);
      return fail(err, err_size, "cannot measure the file");
    }
    const long end = ftell(f);
    truncated = end < 0 || (double)(end - start) < min_bytes;
  }
  fclose(f);
  if (truncated)
    return fail(err, err_size, "truncated PLY file: the body is shorter than its header says");
  return 0;
}
