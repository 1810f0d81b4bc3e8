/* metrics_cli_args.h - command line of vtkshadow-metrics (parsing only). */
#ifndef METRICS_CLI_ARGS_H
#define METRICS_CLI_ARGS_H

#include <stddef.h>

typedef struct metrics_cli_args {
  const char *reference; /* --reference: v_ref, grayscale PNG */
  const char *mask;      /* --mask: valid pixels, non-zero = valid */
  const char *test;      /* --test: v of the renderer under test */
  const char *exclude;   /* --exclude (optional): non-zero = leave out */
  const char *heatmap;   /* --heatmap (optional): RGB error map to write */
  const char *json;      /* --json (optional): copy of stdout to write */
  int band;              /* --band N, default 0 (no band) */
  int reflection;        /* --reflection: colour images, reflection_mae */
  int help;              /* --help given: print usage, nothing else */
} metrics_cli_args;

/* Fills a from argv (argv[0] is skipped); options take their value in the
 * next argument ("--band 1"). Returns 0, or -1 with a one-line message in
 * err naming the option and the offending value. */
int metrics_cli_parse(int argc, char **argv, metrics_cli_args *a, char *err,
                      size_t errlen);

/* The --help text. */
extern const char metrics_cli_usage[];

#endif
