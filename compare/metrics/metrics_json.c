/* metrics_json.c - see metrics_json.h. A tiny growing string buffer is
 * enough: the object is flat and small. */
#include "metrics_json.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct sbuf {
  char *s;
  size_t len, cap;
  int oom;
} sbuf;

static void sb_printf(sbuf *b, const char *fmt, ...) {
  if (b->oom) return;
  for (;;) {
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(b->s + b->len, b->cap - b->len, fmt, ap);
    va_end(ap);
    if (n < 0) {
      b->oom = 1;
      return;
    }
    if ((size_t)n < b->cap - b->len) {
      b->len += (size_t)n;
      return;
    }
    size_t cap = 2 * b->cap + (size_t)n + 1;
    char *s = realloc(b->s, cap);
    if (!s) {
      b->oom = 1;
      return;
    }
    b->s = s;
    b->cap = cap;
  }
}

/* File names are arbitrary bytes: escape what JSON forbids in strings. */
static void sb_string(sbuf *b, const char *key, const char *value) {
  sb_printf(b, "  \"%s\": ", key);
  if (!value) {
    sb_printf(b, "null,\n");
    return;
  }
  sb_printf(b, "\"");
  for (const unsigned char *p = (const unsigned char *)value; *p; ++p) {
    if (*p == '"' || *p == '\\')
      sb_printf(b, "\\%c", *p);
    else if (*p < 0x20)
      sb_printf(b, "\\u%04x", *p);
    else
      sb_printf(b, "%c", *p);
  }
  sb_printf(b, "\",\n");
}

/* The file names common to both objects. */
static void sb_files(sbuf *b, const metrics_cli_args *a) {
  sb_printf(b, "{\n");
  sb_string(b, "reference", a->reference);
  sb_string(b, "mask", a->mask);
  sb_string(b, "test", a->test);
  sb_string(b, "exclude", a->exclude);
  sb_string(b, "heatmap", a->heatmap);
}

static char *sb_finish(sbuf *b) {
  if (b->oom) {
    free(b->s);
    return NULL;
  }
  return b->s;
}

char *metrics_json_format_reflection(const metrics_cli_args *a, int width, int height,
                                     long mirror_pixels, long compared, double mae) {
  sbuf b = {malloc(512), 0, 512, 0};
  if (!b.s) return NULL;
  b.s[0] = '\0';
  sb_files(&b, a);
  sb_printf(&b, "  \"metric\": \"reflection\",\n");
  sb_printf(&b, "  \"width\": %d,\n  \"height\": %d,\n", width, height);
  sb_printf(&b, "  \"mirror_pixels\": %ld,\n", mirror_pixels);
  sb_printf(&b, "  \"compared_pixels\": %ld,\n", compared);
  sb_printf(&b, "  \"reflection_mae\": %.9g\n", mae);
  sb_printf(&b, "}\n");
  return sb_finish(&b);
}

char *metrics_json_format(const metrics_cli_args *a, int width, int height,
                          const vshm_metrics *m, const vshm_penumbra *pen) {
  sbuf b = {malloc(512), 0, 512, 0};
  if (!b.s) return NULL;
  b.s[0] = '\0';
  sb_files(&b, a);
  sb_printf(&b, "  \"band\": %d,\n", a->band);
  sb_printf(&b, "  \"width\": %d,\n  \"height\": %d,\n", width, height);
  sb_printf(&b, "  \"valid_pixels\": %ld,\n", m->valid_pixels);
  sb_printf(&b, "  \"compared_pixels\": %ld,\n", m->compared_pixels);
  /* %.9g: enough digits to compare runs, short enough to read */
  sb_printf(&b, "  \"vis_mae\": %.9g,\n", m->vis_mae);
  sb_printf(&b, "  \"wrong_pct\": %.9g,\n", m->wrong_pct);
  sb_printf(&b, "  \"edge_px\": %.9g,\n", m->edge_px);
  sb_printf(&b, "  \"false_shadow_pct\": %.9g,\n", m->false_shadow_pct);
  sb_printf(&b, "  \"false_light_pct\": %.9g,\n", m->false_light_pct);
  sb_printf(&b, "  \"ref_shadow_pixels\": %ld,\n", m->ref_shadow_pixels);
  sb_printf(&b, "  \"test_shadow_pixels\": %ld,\n", m->test_shadow_pixels);
  sb_printf(&b, "  \"wrong_of_shadow_pct\": %.9g,\n", m->wrong_of_shadow_pct);
  sb_printf(&b, "  \"wrong_of_test_shadow_pct\": %.9g,\n", m->wrong_of_test_shadow_pct);
  /* Penumbra figures (issue 15): over the reference's penumbra, which the
   * boundary band would remove, so they honour --exclude only. */
  sb_printf(&b, "  \"pen_pixels\": %ld,\n", pen->penumbra_pixels);
  sb_printf(&b, "  \"pen_mae\": %.9g,\n", pen->pen_mae);
  sb_printf(&b, "  \"pen_bias\": %.9g,\n", pen->pen_bias);
  sb_printf(&b, "  \"pen_leak_pct\": %.9g,\n", pen->leak_pct);
  sb_printf(&b, "  \"pen_false_shadow_pct\": %.9g,\n", pen->false_shadow_pct);
  sb_printf(&b, "  \"pen_width_ratio\": %.9g\n", pen->width_ratio);
  sb_printf(&b, "}\n");
  return sb_finish(&b);
}
