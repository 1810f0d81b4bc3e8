/* core.depth_seed: the early-depth policy (vsh_depth_seed.h): seeding pays
 * only above the fitted share of hidden fragments, and never on counts that
 * are no evidence (degenerate inputs). */
#include "vsh_check.h"
#include "vsh_depth_seed.h"

#include <float.h>
#include <math.h>

static void test_threshold(void)
{
  const double pixels = 800.0 * 600.0;
  const double k = VSH_DEPTH_SEED_FRAGMENTS_PER_PIXEL;
  CHECK(k > 0.0 && k < 1.0);
  CHECK(VSH_DEPTH_SEED_MEASURE_EVERY >= 2);
  /* The measured scenes on either side of the fit: isosurface (0.53 hidden
   * a pixel) and molecule (0.15) pay, streamtubes (0.07) and elevation (0)
   * do not. */
  CHECK(vsh_depth_seed_pays(pixels * 1.53, pixels, pixels) == 1);
  CHECK(vsh_depth_seed_pays(pixels * 0.95, pixels * 0.80, pixels) == 1);
  CHECK(vsh_depth_seed_pays(pixels * 0.50, pixels * 0.43, pixels) == 0);
  CHECK(vsh_depth_seed_pays(pixels * 0.60, pixels * 0.60, pixels) == 0);
  /* Just above and at the threshold (strictly above pays). */
  CHECK(vsh_depth_seed_pays(k * pixels + 1.0, 0.0, pixels) == 1);
  CHECK(vsh_depth_seed_pays(k * pixels, 0.0, pixels) == 0);
  /* Scale-free: the same shares at another size decide the same. */
  CHECK(vsh_depth_seed_pays(1.53 * 64.0, 64.0, 64.0) == 1);
  CHECK(vsh_depth_seed_pays(0.5e8 * 1.07, 0.5e8, 1e8) == 0);
}

static void test_degenerate(void)
{
  const double pixels = 1000.0;
  /* A seeded frame with more fragments than the unseeded one (the view
   * changed between the two measuring frames): no evidence. */
  CHECK(vsh_depth_seed_pays(100.0, 900.0, pixels) == 0);
  /* No fragments at all, no pixels, negative or non-finite counts. */
  CHECK(vsh_depth_seed_pays(0.0, 0.0, pixels) == 0);
  CHECK(vsh_depth_seed_pays(5000.0, 0.0, 0.0) == 0);
  CHECK(vsh_depth_seed_pays(5000.0, 0.0, -1.0) == 0);
  CHECK(vsh_depth_seed_pays(-1.0, 0.0, pixels) == 0);
  CHECK(vsh_depth_seed_pays(5000.0, -1.0, pixels) == 0);
  CHECK(vsh_depth_seed_pays(NAN, 0.0, pixels) == 0);
  CHECK(vsh_depth_seed_pays(5000.0, NAN, pixels) == 0);
  CHECK(vsh_depth_seed_pays(5000.0, 0.0, NAN) == 0);
  CHECK(vsh_depth_seed_pays(INFINITY, 0.0, pixels) == 0);
  CHECK(vsh_depth_seed_pays(5000.0, 0.0, INFINITY) == 0);
  /* Huge finite counts still decide by their share. */
  CHECK(vsh_depth_seed_pays(DBL_MAX, DBL_MAX / 2.0, DBL_MAX / 4.0) == 1);
}

int main(void)
{
  test_threshold();
  test_degenerate();
  return vsh_check_report("core.depth_seed");
}
