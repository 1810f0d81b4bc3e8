/* core.volume_cost: the shadow-volume cost model in milliseconds and its
 * predicted error (vsh_volume_cost.h), with degenerate inputs. */
#include "vsh_auto_general.h"
#include "vsh_check.h"
#include "vsh_volume_cost.h"

#include <float.h>
#include <math.h>

static double cost4(double pixels, double triangles, double edges, double fill)
{
  const vsh_volume_ms_input in = {pixels, triangles, edges, fill, 0.0};
  return vsh_volume_cost_ms(&in);
}

static double cost(double pixels, double edges, double fill)
{
  const vsh_volume_ms_input in = {pixels, 0.0, edges, fill, 0.0};
  return vsh_volume_cost_ms(&in);
}

static void test_terms(void)
{
  /* The coefficients are what a measurement gives: positive and finite. */
  CHECK(VSH_VOLUME_MS_PER_PIXEL > 0.0 && isfinite(VSH_VOLUME_MS_PER_PIXEL));
  CHECK(VSH_VOLUME_MS_PER_TRIANGLE > 0.0 && isfinite(VSH_VOLUME_MS_PER_TRIANGLE));
  CHECK(VSH_VOLUME_MS_PER_EDGE > 0.0 && isfinite(VSH_VOLUME_MS_PER_EDGE));
  CHECK(VSH_VOLUME_MS_PER_FILL_PX > 0.0 && isfinite(VSH_VOLUME_MS_PER_FILL_PX));
  /* Each term on its own, then their sum: the model is linear. */
  CHECK_NEAR(cost(640.0 * 480.0, 0.0, 0.0), VSH_VOLUME_MS_PER_PIXEL * 640.0 * 480.0, 1e-12);
  CHECK_NEAR(cost(0.0, 1000.0, 0.0), VSH_VOLUME_MS_PER_EDGE * 1000.0, 1e-12);
  CHECK_NEAR(cost(0.0, 0.0, 5e4), VSH_VOLUME_MS_PER_FILL_PX * 5e4, 1e-12);
  CHECK_NEAR(cost(640.0 * 480.0, 1000.0, 5e4),
             cost(640.0 * 480.0, 0.0, 0.0) + cost(0.0, 1000.0, 0.0) + cost(0.0, 0.0, 5e4), 1e-12);
  CHECK_NEAR(cost4(0.0, 1e5, 0.0, 0.0), VSH_VOLUME_MS_PER_TRIANGLE * 1e5, 1e-12);
  CHECK_NEAR(cost4(3e5, 1e5, 1000.0, 5e4), cost(3e5, 1000.0, 5e4) + cost4(0.0, 1e5, 0.0, 0.0),
             1e-12);
  CHECK(cost4(0.0, -1.0, 0.0, 0.0) == INFINITY && cost4(0.0, NAN, 0.0, 0.0) == INFINITY);
  CHECK(cost4(0.0, INFINITY, 0.0, 0.0) == INFINITY);
  /* Caps of volumes counted z-fail: drawn like the pre-pass's triangles. */
  {
    const vsh_volume_ms_input capped = {0.0, 0.0, 0.0, 0.0, 28322.0};
    const vsh_volume_ms_input bad = {0.0, 0.0, 0.0, 0.0, -1.0};
    const vsh_volume_ms_input nan_caps = {0.0, 0.0, 0.0, 0.0, NAN};
    CHECK_NEAR(vsh_volume_cost_ms(&capped), VSH_VOLUME_MS_PER_TRIANGLE * 28322.0, 1e-12);
    CHECK(vsh_volume_cost_ms(&bad) == INFINITY && vsh_volume_cost_ms(&nan_caps) == INFINITY);
  }
  /* Nothing at all costs nothing; 0 edges and 0 fill leave the screen term. */
  CHECK(cost(0.0, 0.0, 0.0) == 0.0);
  CHECK(cost(100.0, 0.0, 0.0) > 0.0);
  /* More edges or more fill never cost less. */
  CHECK(cost(1e5, 2000.0, 1e4) > cost(1e5, 1000.0, 1e4));
  CHECK(cost(1e5, 1000.0, 2e4) > cost(1e5, 1000.0, 1e4));
}

static void test_degenerate(void)
{
  /* Bad input is never cheap: +inf. */
  CHECK(vsh_volume_cost_ms(NULL) == INFINITY);
  CHECK(cost(NAN, 0.0, 0.0) == INFINITY);
  CHECK(cost(0.0, NAN, 0.0) == INFINITY);
  CHECK(cost(0.0, 0.0, NAN) == INFINITY);
  CHECK(cost(-1.0, 0.0, 0.0) == INFINITY);
  CHECK(cost(0.0, -1.0, 0.0) == INFINITY);
  CHECK(cost(0.0, 0.0, -1e-300) == INFINITY);
  /* Huge values: finite while the sum is, +inf when it overflows. */
  const double huge = cost(1e12, 1e12, 1e12);
  CHECK(isfinite(huge) && huge > cost(1e6, 1e6, 1e6));
  CHECK(!isnan(cost(DBL_MAX, DBL_MAX, DBL_MAX)) && cost(DBL_MAX, DBL_MAX, DBL_MAX) > huge);
  CHECK(cost(INFINITY, 0.0, 0.0) == INFINITY);
  CHECK(cost(0.0, 0.0, INFINITY) == INFINITY);
}

static void test_error_and_choice(void)
{
  CHECK(vsh_volume_predicted_error(0, 0) == 0.0);
  CHECK(vsh_volume_predicted_error(-3, 0) == 0.0);
  CHECK(vsh_volume_predicted_error(1, 0) == INFINITY);
  CHECK(vsh_volume_predicted_error(0, 1) == INFINITY);
  /* In auto's pick: exact and cheap wins over a map that misses a thin
   * caster; a huge fill loses to the map, and to rays. */
  const double pixels = 640.0 * 480.0;
  vsh_auto_candidate c[VSH_AUTO_GENERAL_COUNT] = {
      {1, 0.0, 11.5 * pixels / (800.0 * 600.0)}, {1, 0.0, cost(pixels, 200.0, 2e4)},
      {1, 0.0, 400.0}};
  int met = 0;
  c[VSH_AUTO_GENERAL_CSM].predicted_error_pct = 2.0; /* a thin caster's lost shadow */
  CHECK(vsh_auto_pick_cheapest(c, VSH_AUTO_GENERAL_COUNT, 0.5, &met) == VSH_AUTO_GENERAL_VOLUME &&
        met == 1);
  c[VSH_AUTO_GENERAL_CSM].predicted_error_pct = 0.0;
  c[VSH_AUTO_GENERAL_VOLUME].cost = cost(pixels, 200.0, 1e9);
  CHECK(vsh_auto_pick_cheapest(c, VSH_AUTO_GENERAL_COUNT, 0.5, &met) == VSH_AUTO_GENERAL_CSM);
  c[VSH_AUTO_GENERAL_CSM].predicted_error_pct = 2.0;
  CHECK(vsh_auto_pick_cheapest(c, VSH_AUTO_GENERAL_COUNT, 0.5, &met) ==
        VSH_AUTO_GENERAL_RAYTRACE);
  /* An unsupported caster: volume never meets the target. */
  c[VSH_AUTO_GENERAL_VOLUME].cost = 0.0;
  c[VSH_AUTO_GENERAL_VOLUME].predicted_error_pct = vsh_volume_predicted_error(1, 0);
  CHECK(vsh_auto_pick_cheapest(c, VSH_AUTO_GENERAL_COUNT, 0.5, &met) ==
        VSH_AUTO_GENERAL_RAYTRACE);
}

int main(void)
{
  test_terms();
  test_degenerate();
  test_error_and_choice();
  return vsh_check_report("core.volume_cost");
}
