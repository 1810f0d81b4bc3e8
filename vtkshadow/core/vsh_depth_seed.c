#include "vsh_depth_seed.h"

#include <math.h>

/* Fitted at 800x600 on llvmpipe (2 cores) with the stage profile of
 * vtkshadow-render (--profile-frames, `volume` against
 * `volume:early_depth=0`, interleaved): the lit draw's stage gained 6 to 23
 * ms on the scenes saving 0.15 to 0.53 fragments a pixel (molecule,
 * arrow-glyphs, isosurface), nothing on those saving 0.09 to 0.10
 * (helix-tube, cone-glyphs) or none (elevation), and streamtubes, at 0.07,
 * lost 2.5 ms: the seed draw costs about as much as 0.1 hidden fragments a
 * pixel save. The threshold sits between the two groups. */
const double VSH_DEPTH_SEED_FRAGMENTS_PER_PIXEL = 0.12;

int vsh_depth_seed_pays(double unseeded_fragments, double seeded_fragments, double pixels)
{
  if (!isfinite(unseeded_fragments) || !isfinite(seeded_fragments) || !isfinite(pixels) ||
      unseeded_fragments < 0.0 || seeded_fragments < 0.0 || pixels <= 0.0) {
    return 0;
  }
  const double hidden = unseeded_fragments - seeded_fragments;
  return hidden > VSH_DEPTH_SEED_FRAGMENTS_PER_PIXEL * pixels;
}
