/* vtkshadow_metrics.c - vtkshadow-metrics: compare one visibility image
 * with its reference and print the metrics as JSON (usage: --help).
 *
 * Every input is read and checked before anything is written, so bad
 * input (exit 2) never leaves an output file behind. */
#include "metrics_cli_args.h"
#include "metrics_json.h"
#include "vshm_atomic.h"
#include "vshm_metrics.h"
#include "vshm_png.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_OK = 0, EXIT_FAIL = 1, EXIT_BAD_INPUT = 2, EXIT_EMPTY = 3 };

typedef struct image {
  const char *path;
  float *px; /* 1 float per pixel, 3 for colour images */
  int w, h;
} image;

static void complain(const char *msg) { fprintf(stderr, "vtkshadow-metrics: %s\n", msg); }

/* colour: an RGB(A) render (--reflection's --reference and --test). */
static int load_as(image *im, const char *path, int colour) {
  char err[1024];
  im->path = path;
  int rc = colour ? vshm_png_read_rgb(path, &im->px, &im->w, &im->h, NULL, err, sizeof err)
                  : vshm_png_read_gray(path, &im->px, &im->w, &im->h, NULL, err, sizeof err);
  if (rc != 0) {
    complain(err);
    return -1;
  }
  return 0;
}

static int load(image *im, const char *path) { return load_as(im, path, 0); }

/* Names both files and both sizes: "which one is wrong" is the question. */
static int same_size(const image *a, const image *ref) {
  if (a->w == ref->w && a->h == ref->h) return 0;
  fprintf(stderr, "vtkshadow-metrics: %s is %dx%d but %s is %dx%d\n", a->path, a->w, a->h,
          ref->path, ref->w, ref->h);
  return -1;
}

/* Writes json to --json and stdout; EXIT_OK or EXIT_FAIL. */
static int emit(const metrics_cli_args *args, const char *json) {
  char err[1024];
  if (args->json && vshm_write_file_atomic(args->json, json, strlen(json), err, sizeof err)) {
    complain(err);
    return EXIT_FAIL;
  }
  fputs(json, stdout);
  if (fflush(stdout) != 0) {
    complain("cannot write to stdout");
    return EXIT_FAIL;
  }
  return EXIT_OK;
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
  if (vshm_boundary_band(ref->px, valid, w, h, args->band, all_ex) != VSHM_METRICS_OK) goto oom;
  if (user_ex)
    for (size_t i = 0; i < n; ++i) all_ex[i] |= user_ex[i];

  vshm_metrics m;
  int rc = vshm_metrics_compute(test->px, ref->px, valid, all_ex, w, h, &m);
  if (rc < 0) goto oom;
  /* The band removes exactly the boundary edge_px measures, so edge_px
   * only honours --exclude. */
  if (rc == VSHM_METRICS_OK && args->band > 0 &&
      vshm_edge_px(test->px, ref->px, valid, user_ex, w, h, &m.edge_px) != VSHM_METRICS_OK)
    goto oom;

  char err[1024];
  if (args->heatmap) {
    if (!(rgb = malloc(3 * n))) goto oom;
    vshm_error_heatmap_rgb(test->px, ref->px, valid, w, h, rgb);
    if (vshm_png_write_rgb8(args->heatmap, rgb, w, h, err, sizeof err) != 0) {
      complain(err);
      goto done;
    }
  }
  vshm_penumbra pen;
  if (vshm_penumbra_compute(test->px, ref->px, valid, user_ex, w, h, &pen) < 0) goto oom;
  if (!(json = metrics_json_format(args, w, h, &m, &pen))) goto oom;
  if ((status = emit(args, json)) != EXIT_OK) goto done;
  if (rc == VSHM_METRICS_EMPTY) {
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

/* --reflection after the inputs are loaded and checked. */
static int run_reflection(const metrics_cli_args *args, const image *ref, const image *mask,
                          const image *test, const image *excl) {
  int w = ref->w, h = ref->h;
  size_t n = (size_t)w * (size_t)h;
  unsigned char *mirror = malloc(n), *ex = excl->px ? malloc(n) : NULL, *rgb = NULL;
  char *json = NULL, err[1024];
  int status = EXIT_FAIL;
  long mirror_px = 0, compared = 0;
  double mae = 0.0;
  if (!mirror || (excl->px && !ex)) goto oom;
  for (size_t i = 0; i < n; ++i) mirror_px += (mirror[i] = mask->px[i] > 0.0f);
  for (size_t i = 0; ex && i < n; ++i) ex[i] = excl->px[i] > 0.0f;
  int rc = vshm_reflection_mae(test->px, ref->px, mirror, ex, w, h, &mae, &compared);
  if (rc < 0) goto oom;
  if (args->heatmap) {
    if (!(rgb = malloc(3 * n))) goto oom;
    vshm_reflection_heatmap_rgb(test->px, ref->px, mirror, w, h, rgb);
    if (vshm_png_write_rgb8(args->heatmap, rgb, w, h, err, sizeof err) != 0) {
      complain(err);
      goto done;
    }
  }
  if (!(json = metrics_json_format_reflection(args, w, h, mirror_px, compared, mae))) goto oom;
  status = emit(args, json);
  if (status == EXIT_OK && rc == VSHM_METRICS_EMPTY) {
    /* 0 looks like a perfect mirror: make the caller notice */
    fprintf(stderr, "vtkshadow-metrics: no mirror pixel compared (%ld in %s, all excluded?)\n",
            mirror_px, mask->path);
    status = EXIT_EMPTY;
  }
  goto done;
oom:
  complain("out of memory");
done:
  free(mirror);
  free(ex);
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
  const int colour = args.reflection;
  if (load_as(&ref, args.reference, colour) == 0 && load(&mask, args.mask) == 0 &&
      load_as(&test, args.test, colour) == 0 &&
      (!args.exclude || load(&excl, args.exclude) == 0) && same_size(&mask, &ref) == 0 &&
      same_size(&test, &ref) == 0 && (!args.exclude || same_size(&excl, &ref) == 0)) {
    status = colour ? run_reflection(&args, &ref, &mask, &test, &excl)
                    : run(&args, &ref, &mask, &test, &excl);
  }
  free(ref.px);
  free(mask.px);
  free(test.px);
  free(excl.px);
  return status;
}
