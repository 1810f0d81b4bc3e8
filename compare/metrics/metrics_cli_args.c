/* metrics_cli_args.c - see metrics_cli_args.h. */
#include "metrics_cli_args.h"

#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

const char metrics_cli_usage[] =
    "Usage: vtkshadow-metrics --reference R.png --mask M.png --test T.png\n"
    "                         [--exclude E.png] [--band N] [--heatmap H.png]\n"
    "                         [--json OUT.json]\n"
    "       vtkshadow-metrics --reflection --reference R.png --mask MIRROR.png\n"
    "                         --test T.png [--exclude E.png] [--heatmap H.png]\n"
    "                         [--json OUT.json]\n"
    "\n"
    "Compares the visibility image T (16- or 8-bit grayscale PNG, 65535 = lit)\n"
    "with the reference R over the pixels valid in M (non-zero = valid) and\n"
    "prints the shadow error metrics as one JSON object on stdout.\n"
    "\n"
    "  --reference R.png  reference visibility (ray traced)\n"
    "  --mask M.png       valid pixels of the reference\n"
    "  --test T.png       visibility of the renderer under test\n"
    "  --exclude E.png    leave out pixels that are non-zero in E (all metrics)\n"
    "  --band N           also leave out pixels within N pixels (Chebyshev) of\n"
    "                     R's shadow boundary; N = 1 is the one-pixel band on\n"
    "                     each side. Does not apply to edge_px, which measures\n"
    "                     that boundary. Default 0\n"
    "  --heatmap H.png    write the signed error map (blue: too dark, red: too\n"
    "                     bright, white: exact, grey: invalid)\n"
    "  --json OUT.json    also write the JSON object to OUT.json\n"
    "  --reflection       colour mode for planar mirrors: R and T are colour\n"
    "                     renders (RGB or RGBA PNG, linear values), M the\n"
    "                     mirror's pixels; prints reflection_mae, the mean\n"
    "                     absolute colour error over them (no --band)\n"
    "  --help             show this text\n"
    "\n"
    "All images must have the same size. Outputs are written atomically.\n"
    "Exit status: 0 ok; 2 bad input (nothing written); 3 no pixel compared\n"
    "(metrics printed as 0); 1 other failure (output not writable, memory).\n"
    "Definitions: docs/metrics.md.\n";

typedef struct opt_slot {
  const char *name;
  const char **value;
} opt_slot;

static int parse_band(const char *s, int *out) {
  /* strtol alone accepts " 3", "+3" and "3x" as 3; ask for plain digits */
  if (!*s) return -1;
  for (const char *p = s; *p; ++p)
    if (*p < '0' || *p > '9') return -1;
  errno = 0;
  long n = strtol(s, NULL, 10);
  if (errno != 0 || n > INT_MAX) return -1;
  *out = (int)n;
  return 0;
}

int metrics_cli_parse(int argc, char **argv, metrics_cli_args *a, char *err,
                      size_t errlen) {
  memset(a, 0, sizeof *a);
  const char *band = NULL;
  opt_slot slots[] = {
      {"--reference", &a->reference}, {"--mask", &a->mask},       {"--test", &a->test},
      {"--exclude", &a->exclude},     {"--heatmap", &a->heatmap}, {"--json", &a->json},
      {"--band", &band},
  };
  const size_t nslots = sizeof slots / sizeof slots[0];

  for (int i = 1; i < argc; ++i) {
    const char *arg = argv[i];
    if (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0) {
      a->help = 1;
      return 0;
    }
    if (strcmp(arg, "--reflection") == 0) { /* a switch: takes no value */
      if (a->reflection) {
        snprintf(err, errlen, "--reflection given twice");
        return -1;
      }
      a->reflection = 1;
      continue;
    }
    size_t k = 0;
    while (k < nslots && strcmp(arg, slots[k].name) != 0) ++k;
    if (k == nslots) {
      snprintf(err, errlen, "%s '%s'", arg[0] == '-' ? "unknown option" : "unexpected argument",
               arg);
      return -1;
    }
    if (i + 1 >= argc) {
      snprintf(err, errlen, "%s: missing value", arg);
      return -1;
    }
    if (*slots[k].value) {
      /* last-one-wins would silently compare the wrong file */
      snprintf(err, errlen, "%s given twice ('%s' and '%s')", arg, *slots[k].value,
               argv[i + 1]);
      return -1;
    }
    const char *val = argv[++i];
    if (!*val) {
      snprintf(err, errlen, "%s: empty value", arg);
      return -1;
    }
    *slots[k].value = val;
  }
  if (band && parse_band(band, &a->band) != 0) {
    snprintf(err, errlen, "--band: expected a whole number >= 0, got '%s'", band);
    return -1;
  }
  if (band && a->reflection) {
    /* a band along a shadow boundary means nothing for colours */
    snprintf(err, errlen, "--band '%s': not with --reflection", band);
    return -1;
  }
  const char *required[][2] = {
      {"--reference", a->reference}, {"--mask", a->mask}, {"--test", a->test}};
  for (size_t r = 0; r < 3; ++r) {
    if (!required[r][1]) {
      snprintf(err, errlen, "missing required option %s", required[r][0]);
      return -1;
    }
  }
  return 0;
}
