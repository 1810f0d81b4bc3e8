/* vtkshadow_metrics.c - vtkshadow-metrics: compare one visibility image
 * with its reference and print the metrics as JSON (usage: --help).
 *
 * Every input is read and checked before anything is written, so bad
 * input (exit 2) never leaves an output file behind. */
#include "metrics_cli_args.h"
#include "metrics_json.h"
#include "vsh_atomic.h"
#include "vsh_metrics.h"
#include "vsh_png.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_OK = 0, EXIT_FAIL = 1, EXIT_BAD_INPUT = 2, EXIT_EMPTY = 3 };

typedef struct image {
  const char *path;
  float *px;
  int w, h;
} image;

static void complain(const char *msg) { fprintf(stderr, "vtkshadow-metrics: %s\n", msg); }

static int load(image *im, const char *path) {
  char err[1024];
  im->path = path;
  if (vsh_png_read_gray(path, &im->px, &im->w, &im->h, NULL, err, sizeof err) != 0) {
    complain(err);
    return -1;
  }
  return 0;
}

/* Names both files and both sizes: "which one is wrong" is the question. */
static int same_size(const image *a, const image *ref) {
  if (a->w == ref->w && a->h == ref->h) return 0;
  fprintf(stderr, "vtkshadow-metrics: %s is %dx%d but %s is %dx%d\n", a->path, a->w, a->h,
          ref->path, ref->w, ref->h);
  return -1;
}

/* Everything after the inputs are loaded and checked. */
static int run(const metrics_cli_args *args, const image *ref, const image *mask,
               const image *test, const image *excl) {
  int w = ref->w, h = ref->h;
  size_t n = (size_t)w * (size_t)h;
  unsigned char *valid = malloc(n), *user_ex = NULL, *all_ex = malloc(n);
  unsigned char *rgb = NULL;
  char *json = NULL;
  int status = EXIT_FAIL;
  if (!valid || !all_ex) goto oom;
  for (size_t i = 0; i < n; ++i) valid[i] = mask->px[i] > 0.0f;
  if (excl->px) {
    if (!(user_ex = malloc(n))) goto oom;
    for (size_t i = 0; i < n; ++i) user_ex[i] = excl->px[i] > 0.0f;
  }
  if (vsh_boundary_band(ref->px, valid, w, h, args->band, all_ex) != VSH_METRICS_OK) goto oom;
  if (user_ex)
    for (size_t i = 0; i < n; ++i) all_ex[i] |= user_ex[i];

  vsh_metrics m;
  int rc = vsh_metrics_compute(test->px, ref->px, valid, all_ex, w, h, &m);
  if (rc < 0) goto oom;
  /* The band removes exactly the boundary edge_px measures, so edge_px
   * only honours --exclude. */
  if (rc == VSH_METRICS_OK && args->band > 0 &&
      vsh_edge_px(test->px, ref->px, valid, user_ex, w, h, &m.edge_px) != VSH_METRICS_OK)
    goto oom;

  char err[1024];
  if (args->heatmap) {
    if (!(rgb = malloc(3 * n))) goto oom;
    vsh_error_heatmap_rgb(test->px, ref->px, valid, w, h, rgb);
    if (vsh_png_write_rgb8(args->heatmap, rgb, w, h, err, sizeof err) != 0) {
      complain(err);
      goto done;
    }
  }
  if (!(json = metrics_json_format(args, w, h, &m))) goto oom;
  if (args->json && vsh_write_file_atomic(args->json, json, strlen(json), err, sizeof err)) {
    complain(err);
    goto done;
  }
  fputs(json, stdout);
  if (fflush(stdout) != 0) {
    complain("cannot write to stdout");
    goto done;
  }
  status = EXIT_OK;
  if (rc == VSH_METRICS_EMPTY) {
    /* all-zero metrics look like a perfect score: make the caller notice */
    fprintf(stderr, "vtkshadow-metrics: no pixel compared (%ld valid in %s, all excluded?)\n",
            m.valid_pixels, mask->path);
    status = EXIT_EMPTY;
  }
  goto done;
oom:
  complain("out of memory");
done:
  free(valid);
  free(user_ex);
  free(all_ex);
  free(rgb);
  free(json);
  return status;
}

int main(int argc, char **argv) {
  metrics_cli_args args;
  char err[1024];
  if (metrics_cli_parse(argc, argv, &args, err, sizeof err) != 0) {
    complain(err);
    fputs("Try 'vtkshadow-metrics --help'.\n", stderr);
    return EXIT_BAD_INPUT;
  }
  if (args.help) {
    fputs(metrics_cli_usage, stdout);
    return EXIT_OK;
  }
  image ref = {0}, mask = {0}, test = {0}, excl = {0};
  int status = EXIT_BAD_INPUT;
  if (load(&ref, args.reference) == 0 && load(&mask, args.mask) == 0 &&
      load(&test, args.test) == 0 && (!args.exclude || load(&excl, args.exclude) == 0) &&
      same_size(&mask, &ref) == 0 && same_size(&test, &ref) == 0 &&
      (!args.exclude || same_size(&excl, &ref) == 0)) {
    status = run(&args, &ref, &mask, &test, &excl);
  }
  free(ref.px);
  free(mask.px);
  free(test.px);
  free(excl.px);
  return status;
}
