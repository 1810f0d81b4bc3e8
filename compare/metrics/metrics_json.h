/* metrics_json.h - the JSON object vtkshadow-metrics prints. */
#ifndef METRICS_JSON_H
#define METRICS_JSON_H

#include "metrics_cli_args.h"
#include "vsh_metrics.h"

/* Returns a malloc()ed, NUL-terminated JSON object (ending in a newline)
 * with the input file names, the options and every metric; NULL when out
 * of memory. */
char *metrics_json_format(const metrics_cli_args *a, int width, int height,
                          const vsh_metrics *m);

/* The same for --reflection: file names, size, mirror_pixels (non-zero in
 * the mask), compared_pixels and reflection_mae. */
char *metrics_json_format_reflection(const metrics_cli_args *a, int width, int height,
                                     long mirror_pixels, long compared, double mae);

#endif
