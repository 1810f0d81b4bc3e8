/* vsh_scene_fields.c - typed readers for JSON values, each with its own message.
 *
 * The scene walk (vsh_scene_parse.c) only says which field it wants and what
 * kind of value; the type checks, the finiteness check (cJSON turns 1e999 into
 * inf) and the wording of the messages live here so they are uniform.
 */
#include "vsh_scene_internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

char *vsh__strdup(const char *s) {
  size_t n = strlen(s) + 1;
  char *copy = (char *)malloc(n);
  if (copy) memcpy(copy, s, n);
  return copy;
}

void vsh__field(char *buf, const char *parent, const char *key) {
  if (parent && parent[0])
    snprintf(buf, VSH_FIELD_MAX, "%s.%s", parent, key);
  else
    snprintf(buf, VSH_FIELD_MAX, "%s", key);
}

void vsh__field_index(char *buf, const char *parent, size_t index) {
  snprintf(buf, VSH_FIELD_MAX, "%s[%zu]", parent, index);
}

/* Edit distance, capped: only used to suggest "did you mean" for short keys. */
static int edit_distance(const char *a, const char *b) {
  int prev[33], cur[33];
  size_t la = strlen(a), lb = strlen(b), i, j;
  if (la > 32 || lb > 32) return 99;
  for (j = 0; j <= lb; ++j) prev[j] = (int)j;
  for (i = 1; i <= la; ++i) {
    cur[0] = (int)i;
    for (j = 1; j <= lb; ++j) {
      int sub = prev[j - 1] + (a[i - 1] != b[j - 1]);
      int del = prev[j] + 1, ins = cur[j - 1] + 1;
      cur[j] = sub < del ? (sub < ins ? sub : ins) : (del < ins ? del : ins);
    }
    memcpy(prev, cur, sizeof(int) * (lb + 1));
  }
  return prev[lb];
}

int vsh__check_keys(const vsh_ctx *ctx, const cJSON *object, const char *field,
                    const char *const *allowed, const char *what) {
  const cJSON *child, *other;
  for (child = object->child; child; child = child->next) {
    const char *key = child->string ? child->string : "";
    const char *const *a;
    int known = 0;
    for (a = allowed; *a; ++a)
      if (strcmp(*a, key) == 0) known = 1;
    if (!known) {
      char quoted[VSH_GOT_MAX], hint[VSH_GOT_MAX + 32] = "";
      cJSON tmp;
      const char *best = NULL;
      int best_d = 3;
      memset(&tmp, 0, sizeof tmp);
      tmp.type = cJSON_String;
      tmp.valuestring = (char *)key;
      vsh__fmt_json(&tmp, quoted, sizeof quoted);
      /* A typo is the usual cause, so point at the nearest valid key. */
      for (a = allowed; *a; ++a) {
        int d = edit_distance(key, *a);
        if (d < best_d) {
          best_d = d;
          best = *a;
        }
      }
      if (best) snprintf(hint, sizeof hint, " (did you mean \"%s\"?)", best);
      if (field && field[0])
        return vsh__fail(ctx, field, NULL, "unknown field %s%s%s%s", quoted,
                         what ? " " : "", what ? what : "", hint);
      return vsh__fail(ctx, NULL, NULL, "unknown field %s at the top level%s", quoted, hint);
    }
    /* cJSON keeps duplicate keys and lookups return the first one, so a
     * second "radius" would be silently ignored: reject it. */
    for (other = object->child; other != child; other = other->next) {
      if (other->string && strcmp(other->string, key) == 0) {
        char sub[VSH_FIELD_MAX];
        vsh__field(sub, field, key);
        return vsh__fail(ctx, sub, NULL, "duplicate field");
      }
    }
  }
  return 0;
}

int vsh__require(const vsh_ctx *ctx, const cJSON *item, const char *field) {
  if (!item) return vsh__fail(ctx, field, NULL, "missing required field");
  return 0;
}

int vsh__object(const vsh_ctx *ctx, const cJSON *item, const char *field) {
  char got[VSH_GOT_MAX];
  if (cJSON_IsObject(item)) return 0;
  vsh__fmt_json(item, got, sizeof got);
  return vsh__fail(ctx, field, got, "expected an object");
}

int vsh__number(const vsh_ctx *ctx, const cJSON *item, const char *field, double *out) {
  char got[VSH_GOT_MAX];
  vsh__fmt_json(item, got, sizeof got);
  if (!cJSON_IsNumber(item)) return vsh__fail(ctx, field, got, "expected a number");
  if (!isfinite(item->valuedouble)) return vsh__fail(ctx, field, got, "must be a finite number");
  *out = item->valuedouble;
  return 0;
}

int vsh__integer(const vsh_ctx *ctx, const cJSON *item, const char *field, int lo, int hi,
                 int *out) {
  char got[VSH_GOT_MAX];
  double v;
  vsh__fmt_json(item, got, sizeof got);
  if (!cJSON_IsNumber(item) || !isfinite(item->valuedouble) ||
      item->valuedouble != floor(item->valuedouble))
    return vsh__fail(ctx, field, got, "expected an integer");
  v = item->valuedouble;
  if (v < lo || v > hi) return vsh__fail(ctx, field, got, "must be in %d..%d", lo, hi);
  *out = (int)v;
  return 0;
}

int vsh__boolean(const vsh_ctx *ctx, const cJSON *item, const char *field, int *out) {
  char got[VSH_GOT_MAX];
  if (!cJSON_IsBool(item)) {
    vsh__fmt_json(item, got, sizeof got);
    return vsh__fail(ctx, field, got, "expected true or false");
  }
  *out = cJSON_IsTrue(item) ? 1 : 0;
  return 0;
}

int vsh__string(const vsh_ctx *ctx, const cJSON *item, const char *field, char **out) {
  char got[VSH_GOT_MAX];
  *out = NULL;
  if (!cJSON_IsString(item) || !item->valuestring) {
    vsh__fmt_json(item, got, sizeof got);
    return vsh__fail(ctx, field, got, "expected a string");
  }
  *out = vsh__strdup(item->valuestring);
  if (!*out) return vsh__fail(ctx, field, NULL, "out of memory");
  return 0;
}

int vsh__vector(const vsh_ctx *ctx, const cJSON *item, const char *field, int n, double *out) {
  char got[VSH_GOT_MAX], sub[VSH_FIELD_MAX];
  const cJSON *e;
  int i = 0;
  if (!cJSON_IsArray(item) || cJSON_GetArraySize(item) != n) {
    vsh__fmt_json(item, got, sizeof got);
    return vsh__fail(ctx, field, got, "expected an array of %d numbers", n);
  }
  for (e = item->child; e; e = e->next, ++i) {
    vsh__field_index(sub, field, (size_t)i);
    if (vsh__number(ctx, e, sub, &out[i])) return -1;
  }
  return 0;
}

int vsh__color01(const vsh_ctx *ctx, const cJSON *item, const char *field, double out[3]) {
  char got[VSH_GOT_MAX], sub[VSH_FIELD_MAX];
  int i;
  if (vsh__vector(ctx, item, field, 3, out)) return -1;
  for (i = 0; i < 3; ++i) {
    if (out[i] < 0.0 || out[i] > 1.0) {
      vsh__field_index(sub, field, (size_t)i);
      vsh__fmt_number(out[i], got, sizeof got);
      return vsh__fail(ctx, sub, got, "must be in [0, 1]");
    }
  }
  return 0;
}
