/* metrics_json.h - the JSON object vtkshadow-metrics prints. */
#ifndef METRICS_JSON_H
#define METRICS_JSON_H

#include "metrics_cli_args.h"
#include "vshm_metrics.h"
#include "vshm_penumbra.h"

/* Returns a malloc()ed, NUL-terminated JSON object (ending in a newline)
 * with the input file names, the options, every metric and the penumbra
 * figures (pen_*: pen_pixels 0 and pen_mae 0 when the reference has no
 * penumbra); NULL when out of memory. */
char *metrics_json_format(const metrics_cli_args *a, int width, int height,
                          const vshm_metrics *m, const vshm_penumbra *pen);

/* The same for --reflection: file names, size, mirror_pixels (non-zero in
 * the mask), compared_pixels and reflection_mae. */
char *metrics_json_format_reflection(const metrics_cli_args *a, int width, int height,
                                     long mirror_pixels, long compared, double mae);

#endif
