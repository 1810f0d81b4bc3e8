/* vshm_edt.h - exact squared Euclidean distance transform of a binary grid.
 *
 * Felzenszwalb & Huttenlocher, "Distance Transforms of Sampled Functions"
 * (Theory of Computing 8, 2012): the 2D squared distance separates into a
 * 1D transform along every column followed by one along every row, and
 * each 1D transform is the lower envelope of parabolas, O(n). Exact (not
 * the 3x3 chamfer approximation) so that edge_px means pixels.
 */
#ifndef VSHM_EDT_H
#define VSHM_EDT_H

#ifdef __cplusplus
extern "C" {
#endif

/* d2[i] = squared Euclidean distance (in cells) from cell i to the nearest
 * cell with feature[i] != 0; grids are width * height, row major. With no
 * feature cell at all, every d2 is +INFINITY.
 * Returns the number of feature cells (>= 0), or -1 on bad arguments or
 * when out of memory. */
long vshm_edt_sq(const unsigned char *feature, int width, int height, double *d2);

#ifdef __cplusplus
}
#endif

#endif
