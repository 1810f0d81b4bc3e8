/* vsh_scene_errors.c - formatting of validation messages.
 *
 * Every message has the shape "FILE: FIELD: problem (got VALUE)" so a user can
 * find the offending spot without a debugger, and tests can match on the field
 * path and the quoted value. Values are printed in the shortest form that
 * reads back exactly, so "must be > 0 (got 1e-320)" is never shown as "0".
 */
#include "vsh_scene_internal.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int vsh__fail(const vsh_ctx *ctx, const char *field, const char *got, const char *fmt, ...) {
  char problem[VSH_SCENE_ERROR_MAX];
  va_list ap;
  if (!ctx->err || ctx->err_size == 0) return -1;
  va_start(ap, fmt);
  vsnprintf(problem, sizeof problem, fmt, ap);
  va_end(ap);
  /* snprintf truncates safely when the caller's buffer is small. */
  if (field && field[0]) {
    if (got)
      snprintf(ctx->err, ctx->err_size, "%s: %s: %s (got %s)", ctx->file, field, problem, got);
    else
      snprintf(ctx->err, ctx->err_size, "%s: %s: %s", ctx->file, field, problem);
  } else {
    if (got)
      snprintf(ctx->err, ctx->err_size, "%s: %s (got %s)", ctx->file, problem, got);
    else
      snprintf(ctx->err, ctx->err_size, "%s: %s", ctx->file, problem);
  }
  return -1;
}

void vsh__fmt_number(double v, char *buf, size_t size) {
  int precision;
  if (size == 0) return;
  if (isnan(v)) {
    snprintf(buf, size, "nan");
    return;
  }
  if (isinf(v)) {
    snprintf(buf, size, v > 0 ? "inf" : "-inf");
    return;
  }
  /* The shortest %g precision that round-trips: "0.1" rather than
   * "0.10000000000000001", yet distinct values never print the same. */
  for (precision = 6; precision <= 17; ++precision) {
    char tmp[64];
    snprintf(tmp, sizeof tmp, "%.*g", precision, v);
    if (strtod(tmp, NULL) == v || precision == 17) {
      snprintf(buf, size, "%s", tmp);
      return;
    }
  }
}

void vsh__fmt_vec(const double *v, int n, char *buf, size_t size) {
  size_t used = 0;
  int i;
  if (size == 0) return;
  buf[0] = '\0';
  used += (size_t)snprintf(buf, size, "[");
  for (i = 0; i < n && used < size; ++i) {
    char num[64];
    vsh__fmt_number(v[i], num, sizeof num);
    used += (size_t)snprintf(buf + used, size - used, "%s%s", i ? ", " : "", num);
  }
  if (used < size) snprintf(buf + used, size - used, "]");
}

/* A tiny bounded writer: appends until the buffer is full, then marks the
 * output as truncated. Quoting the whole of a 10 MB array back would help nobody. */
typedef struct vsh_out {
  char *buf;
  size_t size, used;
  int full;
} vsh_out;

static void out_str(vsh_out *o, const char *s) {
  while (*s && !o->full) {
    if (o->used + 4 >= o->size) { /* keep room for "..." and the terminator */
      memcpy(o->buf + o->used, "...", 3);
      o->used += 3;
      o->full = 1;
      break;
    }
    o->buf[o->used++] = *s++;
  }
  o->buf[o->used] = '\0';
}

static void out_json(vsh_out *o, const cJSON *item, int depth) {
  char tmp[64];
  const cJSON *child;
  if (o->full) return;
  if (!item) {
    out_str(o, "nothing");
  } else if (cJSON_IsNumber(item)) {
    vsh__fmt_number(item->valuedouble, tmp, sizeof tmp);
    out_str(o, tmp);
  } else if (cJSON_IsString(item)) {
    const unsigned char *s = (const unsigned char *)item->valuestring;
    out_str(o, "\"");
    for (; s && *s && !o->full; ++s) {
      if (*s == '"' || *s == '\\') {
        tmp[0] = '\\';
        tmp[1] = (char)*s;
        tmp[2] = '\0';
      } else if (*s < 0x20 || *s == 0x7f) {
        snprintf(tmp, sizeof tmp, "\\u%04x", *s); /* keep messages on one line */
      } else {
        tmp[0] = (char)*s;
        tmp[1] = '\0';
      }
      out_str(o, tmp);
    }
    out_str(o, "\"");
  } else if (cJSON_IsTrue(item)) {
    out_str(o, "true");
  } else if (cJSON_IsFalse(item)) {
    out_str(o, "false");
  } else if (cJSON_IsNull(item)) {
    out_str(o, "null");
  } else if (cJSON_IsArray(item) || cJSON_IsObject(item)) {
    int is_array = cJSON_IsArray(item);
    out_str(o, is_array ? "[" : "{");
    if (depth >= 3 && item->child) {
      out_str(o, "...");
    } else {
      for (child = item->child; child && !o->full; child = child->next) {
        if (child != item->child) out_str(o, ", ");
        if (!is_array) {
          cJSON key;
          memset(&key, 0, sizeof key);
          key.type = cJSON_String;
          key.valuestring = child->string;
          out_json(o, &key, depth + 1);
          out_str(o, ": ");
        }
        out_json(o, child, depth + 1);
      }
    }
    out_str(o, is_array ? "]" : "}");
  } else {
    out_str(o, "?");
  }
}

void vsh__fmt_json(const cJSON *item, char *buf, size_t size) {
  vsh_out o;
  if (size < 8) {
    if (size) buf[0] = '\0';
    return;
  }
  o.buf = buf;
  o.size = size;
  o.used = 0;
  o.full = 0;
  buf[0] = '\0';
  out_json(&o, item, 0);
}
