/* test_auto_soft.c - unit tests of vsh_auto_soft: the pen_mae model against
 * the measurements it was fitted to, the fewest samples meeting a target
 * (bounds, unreachable and NaN targets), the costs, and the choice with
 * degenerate targets (0, huge, NaN), without planar, without raytrace,
 * with nothing available, and with sample bounds out of range. */
#include "vsh_auto_soft.h"
#include "vsh_check.h"

#include <math.h>

static void test_model(void)
{
  /* The fits' own points (docs/results.md: planar sphere-disk light 0,
   * raytrace glyphs-soft light 0, the worse scene). */
  CHECK_NEAR(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_PLANAR, 16), 0.041, 0.001);
  CHECK_NEAR(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_PLANAR, 64), 0.026, 0.001);
  CHECK_NEAR(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_RAYTRACE, 16), 0.058, 0.004);
  CHECK_NEAR(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_RAYTRACE, 64), 0.024, 0.004);
  CHECK_NEAR(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_PCSS, 1), 0.09, 1e-12);
  CHECK(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_PCSS, 1024) == vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_PCSS, 1));
  /* Falls with N, never below the bias. */
  for (int n = 1; n < 1024; ++n) {
    CHECK(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_PLANAR, n + 1) <
          vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_PLANAR, n));
    CHECK(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_RAYTRACE, n + 1) <
          vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_RAYTRACE, n));
  }
  CHECK(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_PLANAR, 1 << 30) > 0.011);
  /* N < 1 counts as 1; unknown technique NaN. */
  CHECK(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_PLANAR, 0) == vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_PLANAR, 1));
  CHECK(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_RAYTRACE, -5) == vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_RAYTRACE, 1));
  CHECK(isnan(vsh_auto_soft_pen_mae(7, 16)));
  CHECK(isnan(vsh_auto_soft_pen_mae(-1, 16)));
}

static void test_samples_for(void)
{
  for (int t = VSH_AUTO_SOFT_PLANAR; t <= VSH_AUTO_SOFT_RAYTRACE; t += 2) {
    /* Huge target: the fewest; unreachable, zero, negative or NaN: the most. */
    CHECK(vsh_auto_soft_samples_for(t, 1.0, 4, 1024) == 4);
    CHECK(vsh_auto_soft_samples_for(t, 0.0, 4, 1024) == 1024);
    CHECK(vsh_auto_soft_samples_for(t, -1.0, 4, 1024) == 1024);
    CHECK(vsh_auto_soft_samples_for(t, NAN, 4, 1024) == 1024);
    /* max below min: min. */
    CHECK(vsh_auto_soft_samples_for(t, 0.0, 16, 8) == 16);
    /* The first N that meets the target: N meets it, N - 1 does not. */
    const double targets[] = {0.05, 0.03, 0.02, 0.015, 0.012};
    for (int i = 0; i < 5; ++i) {
      const int n = vsh_auto_soft_samples_for(t, targets[i], 4, 1024);
      if (vsh_auto_soft_pen_mae(t, 1024) <= targets[i]) {
        CHECK(vsh_auto_soft_pen_mae(t, n) <= targets[i]);
        CHECK(n == 4 || vsh_auto_soft_pen_mae(t, n - 1) > targets[i]);
      } else {
        CHECK(n == 1024);
      }
    }
  }
  /* Closed forms: raytrace 0.22 / sqrt(N) <= 0.015 from N = 216 on;
   * planar 0.12 / sqrt(N) + 0.011 <= 0.015 from N = 900 on; planar cannot
   * reach 0.011 at all. */
  CHECK(vsh_auto_soft_samples_for(VSH_AUTO_SOFT_RAYTRACE, 0.015, 4, 1024) == 216);
  CHECK(vsh_auto_soft_samples_for(VSH_AUTO_SOFT_PLANAR, 0.015, 4, 1024) == 900);
  CHECK(vsh_auto_soft_samples_for(VSH_AUTO_SOFT_PLANAR, 0.011, 4, 1024) == 1024);
  CHECK(vsh_auto_soft_samples_for(VSH_AUTO_SOFT_PCSS, 0.0, 4, 1024) == 4);
}

static void test_costs(void)
{
  CHECK(vsh_auto_soft_planar_ms(0.0, 16) == 0.0);
  CHECK(vsh_auto_soft_planar_ms(-5.0, 16) == 0.0);
  CHECK(vsh_auto_soft_planar_ms(NAN, 16) == 0.0);
  CHECK(vsh_auto_soft_planar_ms(INFINITY, 16) == 0.0);
  /* Linear in N and in pixels. */
  const double a = vsh_auto_soft_planar_ms(307200.0, 1), b = vsh_auto_soft_planar_ms(307200.0, 64);
  CHECK_NEAR(a, 6.5, 0.1);
  CHECK_NEAR(b - a, 63 * 3.35, 1.0);
  CHECK_NEAR(vsh_auto_soft_planar_ms(2 * 307200.0, 64), 2 * b, 1e-9);
  CHECK(vsh_auto_soft_planar_ms(307200.0, 0) == a);
  CHECK_NEAR(vsh_auto_soft_pcss_ms(2.0), 20.0, 1e-12);
  CHECK(vsh_auto_soft_pcss_ms(-1.0) == 0.0);
  CHECK(vsh_auto_soft_pcss_ms(NAN) == 0.0);
}

/* A frame of 160x120 pixels with every candidate available. */
static vsh_auto_soft_input frame(double target)
{
  vsh_auto_soft_input in;
  in.target = target;
  in.pixels = 160.0 * 120.0;
  in.planar_available = 1;
  in.csm_available = 1;
  in.pcss = 1;
  in.raytrace_available = 1;
  in.min_samples = 0;
  in.max_samples = 0;
  in.map_ms = 11.5 / (800.0 * 600.0) * in.pixels;
  vsh_rt_cost_model_default(&in.rt_model);
  in.rt_frame.pixels = in.pixels;
  in.rt_frame.coverage = 1.0;
  in.rt_frame.lights = 1;
  in.rt_frame.samples = 1;
  in.rt_frame.threads = 2;
  in.rt_frame.first = 0;
  in.rt_frame.penumbra = 0.25;
  in.rt_adaptive = 1;
  return in;
}

static void test_choose(void)
{
  vsh_auto_soft_choice c;
  CHECK(vsh_auto_soft_choose(NULL, &c) == -1);
  vsh_auto_soft_input in = frame(0.03);
  CHECK(vsh_auto_soft_choose(&in, NULL) == -1);

  /* Loose target: planar at the fewest samples, cheaper than PCSS. */
  in = frame(0.2);
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_PLANAR);
  CHECK(c.met == 1 && c.candidates[VSH_AUTO_SOFT_PLANAR].samples == VSH_AUTO_SOFT_MIN_SAMPLES);
  CHECK(c.candidates[VSH_AUTO_SOFT_PLANAR].ms < c.candidates[VSH_AUTO_SOFT_PCSS].ms);
  /* ... and without planar (shadows on non-planes): PCSS, not raytrace. */
  in.planar_available = 0;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_PCSS && c.met == 1);
  CHECK(c.candidates[VSH_AUTO_SOFT_PLANAR].available == 0);
  CHECK(c.candidates[VSH_AUTO_SOFT_PCSS].ms < c.candidates[VSH_AUTO_SOFT_RAYTRACE].ms);
  /* PCSS switched off: csm draws the hard shadow (0.30), which misses 0.2. */
  in.pcss = 0;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_RAYTRACE && c.met == 1);
  CHECK_NEAR(c.candidates[VSH_AUTO_SOFT_PCSS].pen_mae, 0.30, 1e-12);

  /* Huge target: everything meets it, the cheapest wins. */
  in = frame(1.0);
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_PLANAR && c.met == 1);

  /* Default target 0.03: planar with enough samples (cheaper than rays). */
  in = frame(0.03);
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_PLANAR && c.met == 1);
  CHECK(c.candidates[VSH_AUTO_SOFT_PLANAR].pen_mae <= 0.03);
  CHECK(c.candidates[VSH_AUTO_SOFT_PLANAR].samples == 40);

  /* Tight target 0.015: planar needs 900 samples, rays 216 and are cheaper. */
  in = frame(0.015);
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_RAYTRACE && c.met == 1);
  CHECK(c.candidates[VSH_AUTO_SOFT_RAYTRACE].samples == 216);
  CHECK(c.candidates[VSH_AUTO_SOFT_PLANAR].samples == 900);
  CHECK(c.candidates[VSH_AUTO_SOFT_RAYTRACE].ms < c.candidates[VSH_AUTO_SOFT_PLANAR].ms);
  /* The ray cost is vsh_rt_cost_ms at N = 216, adaptive: 8 + 0.25 x 208 rays. */
  vsh_rt_cost_input rt = in.rt_frame;
  rt.samples = 216;
  rt.first = 8;
  CHECK_NEAR(c.candidates[VSH_AUTO_SOFT_RAYTRACE].ms, vsh_rt_cost_ms(&in.rt_model, &rt), 1e-9);

  /* Target 0: nothing meets it; the lowest error is raytrace at the most. */
  in = frame(0.0);
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_RAYTRACE && c.met == 0);
  CHECK(c.candidates[VSH_AUTO_SOFT_RAYTRACE].samples == VSH_AUTO_SOFT_MAX_SAMPLES);
  /* ... without rays: planar at the most (0.0148 < PCSS 0.09). */
  in.raytrace_available = 0;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_PLANAR && c.met == 0);
  CHECK(c.candidates[VSH_AUTO_SOFT_PLANAR].samples == VSH_AUTO_SOFT_MAX_SAMPLES);
  /* ... with csm alone: PCSS, not met. */
  in.planar_available = 0;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_PCSS && c.met == 0);
  /* Nothing available. */
  in.csm_available = 0;
  CHECK(vsh_auto_soft_choose(&in, &c) == -1 && c.met == 0);
  /* NaN target: like 0. */
  in = frame(NAN);
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_RAYTRACE && c.met == 0);

  /* N bounds: clamped to [4, 1024]; a cap below what the target needs
   * gives the cap and the lowest error. */
  in = frame(0.0);
  in.min_samples = -3;
  in.max_samples = 100000;
  vsh_auto_soft_choose(&in, &c);
  CHECK(c.candidates[VSH_AUTO_SOFT_RAYTRACE].samples == VSH_AUTO_SOFT_MAX_SAMPLES);
  in = frame(1.0);
  in.min_samples = 1;
  vsh_auto_soft_choose(&in, &c);
  CHECK(c.candidates[VSH_AUTO_SOFT_PLANAR].samples == VSH_AUTO_SOFT_MIN_SAMPLES);
  in = frame(0.015);
  in.max_samples = 32;
  /* neither meets it at 32: the lower predicted error, planar's 0.032
   * against the rays' 0.039 */
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_PLANAR && c.met == 0);
  CHECK(c.candidates[VSH_AUTO_SOFT_RAYTRACE].samples == 32);
  CHECK(c.candidates[VSH_AUTO_SOFT_PLANAR].samples == 32);
  /* No pixels: every cost 0 or the per-frame constant; still a pick. */
  in = frame(0.03);
  in.pixels = 0.0;
  CHECK(vsh_auto_soft_choose(&in, &c) >= 0);
}

int main(void)
{
  test_model();
  test_samples_for();
  test_costs();
  test_choose();
  return vsh_check_report("core.auto_soft");
}
