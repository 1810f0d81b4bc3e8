/* vshm_metrics_size.h - the image sizes the metric functions accept
 * (private to the library). Bounded so that sizes, indices and the
 * doubled crack grid of the edge metric never overflow. */
#ifndef VSHM_METRICS_SIZE_H
#define VSHM_METRICS_SIZE_H

#define VSHM_METRICS_MAX_SIDE (1 << 20)
#define VSHM_METRICS_MAX_PIXELS (1L << 30)

static inline int vshm_metrics_size_ok(int width, int height) {
  return width > 0 && height > 0 && width <= VSHM_METRICS_MAX_SIDE &&
         height <= VSHM_METRICS_MAX_SIDE &&
         (double)width * (double)height <= (double)VSHM_METRICS_MAX_PIXELS;
}

#endif
