/* vshm_boundary.h - where the 0.5-level boundary of a visibility image lies.
 *
 * A valid pixel is "lit" when v >= 0.5 and "shadowed" otherwise; invalid
 * pixels have no state. The boundary is made of "cracks": the shared edge
 * between two 4-adjacent valid pixels of different state.
 *
 * Why cracks and not boundary pixels: marking the pixels on both sides of
 * the edge makes a straight edge moved by k pixels measure k - 0.5 (half the
 * marked pixels are one pixel closer), and marking only one side is not
 * symmetric between lit and shadow. A crack sits exactly half way between
 * its two pixels, so a straight edge moved by k pixels measures exactly k.
 *
 * Cracks live on a doubled grid of (2w-1) x (2h-1) cells: pixel (x,y) is
 * cell (2x,2y), the crack between (x,y) and (x+1,y) is cell (2x+1,2y), the
 * crack between (x,y) and (x,y+1) is cell (2x,2y+1). Distances on that grid
 * are twice the distances in pixels.
 */
#ifndef VSHM_BOUNDARY_H
#define VSHM_BOUNDARY_H

#ifdef __cplusplus
extern "C" {
#endif

/* The thresholded state: non-zero for lit. */
static inline int vshm_is_lit(float v) { return v >= 0.5f; }

/* Clears the (2w-1) x (2h-1) grid `cracks`, then sets the cells of the
 * boundary cracks of v to 1. valid != 0 marks valid pixels. Returns the
 * number of cracks. */
long vshm_boundary_cracks(const float *v, const unsigned char *valid, int width,
                          int height, unsigned char *cracks);

/* The two pixels (row-major indices) on either side of crack cell (cx,cy). */
void vshm_crack_pixels(int cx, int cy, int width, long *a, long *b);

#ifdef __cplusplus
}
#endif

#endif
