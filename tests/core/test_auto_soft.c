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
  in.rt_frame.traced = 0.0;
  in.rt_adaptive = 1;
  /* volume off unless a test turns it on; its inputs a small scene's. */
  in.volume_available = 0;
  in.volume.pixels = in.pixels;
  in.volume.scene_triangles = 1000.0;
  in.volume.silhouette_edges = 100.0;
  in.volume.fill_px = 0.2 * in.pixels;
  /* csm's sampled maps: the test scene of harness.soft_csm_sampled (two
   * point lights and a sun: 13 planned maps, all of lights with a size) at
   * csm's defaults. */
  in.csm_resolution = 2048;
  in.csm_budget = 256LL << 20;
  in.csm_tiles = 13;
  in.csm_sampled_tiles = 13;
  in.csm_adaptive = 0;
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
  /* ... and without planar (shadows on non-planes): csm's sampled light at
   * N = 4 (5 lookups' worth against PCSS's 10; measured 122 against 204 ms),
   * not raytrace. */
  in.planar_available = 0;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_CSM_SAMPLED && c.met == 1);
  CHECK(c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].samples == VSH_AUTO_SOFT_MIN_SAMPLES);
  CHECK(c.candidates[VSH_AUTO_SOFT_PLANAR].available == 0);
  CHECK(c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].ms < c.candidates[VSH_AUTO_SOFT_PCSS].ms);
  CHECK(c.candidates[VSH_AUTO_SOFT_PCSS].ms < c.candidates[VSH_AUTO_SOFT_RAYTRACE].ms);
  /* At 0.09 sampled needs N = 12 (13 lookups): PCSS is the cheapest. */
  in.target = 0.09;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_PCSS && c.met == 1);
  CHECK(c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].samples == 12);
  in.target = 0.2;
  /* csm's soft switched off: csm draws the hard shadow (0.30), which misses
   * 0.2, and offers no sampled light. */
  in.pcss = 0;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_RAYTRACE && c.met == 1);
  CHECK_NEAR(c.candidates[VSH_AUTO_SOFT_PCSS].pen_mae, 0.30, 1e-12);
  CHECK(c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].available == 0);

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
  /* ... with csm alone: its sampled light at its lowest predicted error
   * (below PCSS's 0.09), not met. */
  in.planar_available = 0;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_CSM_SAMPLED && c.met == 0);
  CHECK(c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].pen_mae < 0.09);
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

static void test_volume_model(void)
{
  /* The fit's points (glyphs-soft light 0 against Cycles): 16, 32, 64. */
  CHECK_NEAR(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_VOLUME, 16), 0.0566, 0.0005);
  CHECK_NEAR(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_VOLUME, 32), 0.0348, 0.0010);
  CHECK_NEAR(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_VOLUME, 64), 0.0224, 0.0005);
  /* Closed form: 0.4235 / N^0.75 + 0.0037 <= 0.03 from N = 41 on, <= 0.02
   * from N = 77 on. */
  CHECK(vsh_auto_soft_samples_for(VSH_AUTO_SOFT_VOLUME, 0.03, 4, 255) == 41);
  CHECK(vsh_auto_soft_samples_for(VSH_AUTO_SOFT_VOLUME, 0.02, 4, 255) == 77);
  for (int n = 1; n < 255; ++n) {
    CHECK(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_VOLUME, n + 1) <
          vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_VOLUME, n));
  }
  CHECK(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_VOLUME, 0) ==
        vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_VOLUME, 1));
  CHECK(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_VOLUME, 1 << 30) > 0.0);
  /* The fewest N meeting a target: N meets it, N - 1 does not. */
  const double targets[] = {0.05, 0.03, 0.02, 0.015};
  for (int i = 0; i < 4; ++i) {
    const int n = vsh_auto_soft_samples_for(VSH_AUTO_SOFT_VOLUME, targets[i], 4, 255);
    if (vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_VOLUME, 255) <= targets[i]) {
      CHECK(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_VOLUME, n) <= targets[i]);
      CHECK(n == 4 || vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_VOLUME, n - 1) > targets[i]);
    } else {
      CHECK(n == 255);
    }
  }
}

static void test_volume_cost(void)
{
  vsh_volume_ms_input v = {160.0 * 120.0, 1000.0, 100.0, 4000.0, 0.0};
  /* N = 1 (and N < 1) is the hard model. */
  CHECK_NEAR(vsh_auto_soft_volume_ms(&v, 1), vsh_volume_cost_ms(&v), 1e-12);
  CHECK(vsh_auto_soft_volume_ms(&v, 0) == vsh_auto_soft_volume_ms(&v, 1));
  CHECK(vsh_auto_soft_volume_ms(&v, -7) == vsh_auto_soft_volume_ms(&v, 1));
  /* Linear in N: each further count pays edges, fill and the screen, not
   * the depth pre-pass. */
  const double per = VSH_VOLUME_MS_PER_EDGE * 100.0 + VSH_VOLUME_MS_PER_FILL_PX * 4000.0 +
                     VSH_VOLUME_MS_PER_PIXEL * v.pixels;
  CHECK_NEAR(vsh_auto_soft_volume_ms(&v, 16) - vsh_auto_soft_volume_ms(&v, 1), 15.0 * per, 1e-9);
  vsh_volume_ms_input more = v;
  more.scene_triangles *= 10.0;
  CHECK_NEAR(vsh_auto_soft_volume_ms(&more, 64) - vsh_auto_soft_volume_ms(&v, 64),
             VSH_VOLUME_MS_PER_TRIANGLE * 9000.0, 1e-9);
  /* Degenerate inputs: never cheaper than anything finite. */
  CHECK(isinf(vsh_auto_soft_volume_ms(NULL, 16)));
  vsh_volume_ms_input bad = v;
  bad.fill_px = NAN;
  CHECK(isinf(vsh_auto_soft_volume_ms(&bad, 16)));
  bad = v;
  bad.silhouette_edges = -1.0;
  CHECK(isinf(vsh_auto_soft_volume_ms(&bad, 16)));
  bad = v;
  bad.silhouette_edges = 1e308;
  CHECK(isinf(vsh_auto_soft_volume_ms(&bad, 255)));
  /* No edges, no fill: the screen and pre-pass terms alone, still linear. */
  vsh_volume_ms_input empty = {1000.0, 0.0, 0.0, 0.0, 0.0};
  CHECK_NEAR(vsh_auto_soft_volume_ms(&empty, 10), 10.0 * VSH_VOLUME_MS_PER_PIXEL * 1000.0, 1e-12);
}

static void test_choose_volume(void)
{
  vsh_auto_soft_choice c;
  /* Not available: weighed for the report, never picked. */
  vsh_auto_soft_input in = frame(0.03);
  in.planar_available = 0;
  CHECK(vsh_auto_soft_choose(&in, &c) != VSH_AUTO_SOFT_VOLUME);
  CHECK(c.candidates[VSH_AUTO_SOFT_VOLUME].available == 0);
  CHECK(c.candidates[VSH_AUTO_SOFT_VOLUME].samples >= VSH_AUTO_SOFT_MIN_SAMPLES);
  CHECK(isfinite(c.candidates[VSH_AUTO_SOFT_VOLUME].ms));
  /* A small scene (10 silhouette edges) without plane receivers: volume
   * with the fewest samples meeting the target, cheaper than the rays. */
  in.volume_available = 1;
  in.volume.silhouette_edges = 10.0;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_VOLUME && c.met == 1);
  const int n = c.candidates[VSH_AUTO_SOFT_VOLUME].samples;
  CHECK(n == vsh_auto_soft_samples_for(VSH_AUTO_SOFT_VOLUME, 0.03, 4, 255));
  CHECK(c.candidates[VSH_AUTO_SOFT_VOLUME].pen_mae <= 0.03);
  CHECK_NEAR(c.candidates[VSH_AUTO_SOFT_VOLUME].ms, vsh_auto_soft_volume_ms(&in.volume, n), 1e-12);
  /* A heavy one (glyphs: 200,000 side quads a count): the rays. */
  in.volume.silhouette_edges = 2e5;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_RAYTRACE && c.met == 1);
  /* Volume alone: picked whatever it costs; target 0 not met, at its most
   * samples (255, its own clamp, not 1024). */
  in = frame(0.0);
  in.planar_available = in.csm_available = in.raytrace_available = 0;
  in.volume_available = 1;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_VOLUME && c.met == 0);
  CHECK(c.candidates[VSH_AUTO_SOFT_VOLUME].samples == VSH_AUTO_SOFT_VOLUME_MAX_SAMPLES);
  /* ... with raytrace: the rays at 1024 are the lowest error. */
  in.raytrace_available = 1;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_RAYTRACE && c.met == 0);
  /* Bounds reversed (min 64, max 16): min for every sampled candidate. */
  in = frame(0.0);
  in.volume_available = 1;
  in.min_samples = 64;
  in.max_samples = 16;
  vsh_auto_soft_choose(&in, &c);
  CHECK(c.candidates[VSH_AUTO_SOFT_VOLUME].samples == 64);
  CHECK(c.candidates[VSH_AUTO_SOFT_RAYTRACE].samples == 64);
  CHECK(c.candidates[VSH_AUTO_SOFT_PLANAR].samples == 64);
  /* A minimum above volume's clamp: volume at 255, the others at min. */
  in.min_samples = 512;
  in.max_samples = 1024;
  vsh_auto_soft_choose(&in, &c);
  CHECK(c.candidates[VSH_AUTO_SOFT_VOLUME].samples == VSH_AUTO_SOFT_VOLUME_MAX_SAMPLES);
  CHECK(c.candidates[VSH_AUTO_SOFT_RAYTRACE].samples == 1024);
  /* Volume inputs the cost model refuses: +inf ms, never the cheapest. */
  in = frame(0.2);
  in.planar_available = 0;
  in.volume_available = 1;
  in.volume.fill_px = NAN;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_CSM_SAMPLED);
  CHECK(isinf(c.candidates[VSH_AUTO_SOFT_VOLUME].ms));
  /* Nothing available at all, volume included. */
  in = frame(0.03);
  in.planar_available = in.csm_available = in.raytrace_available = in.volume_available = 0;
  CHECK(vsh_auto_soft_choose(&in, &c) == -1 && c.met == 0);
}

/* csm's sampled light: the model at its fitted points, the texel ratio
 * from the budget, the non-monotone choice of N, the cost, degenerate
 * inputs. */
static void test_csm_sampled_model(void)
{
  /* Fitted points (vsh_auto_soft.c): glyphs-soft light 0 at N = 11, maps
   * 1664 of 2048 texels (0.0685 measured); torus-disk light 1 at N = 64,
   * 288 texels (0.0724). Upper envelope: at or above both, and above
   * glyphs-soft light 0 at N = 16 (0.0527, 1392 texels). */
  const double g = vsh_auto_soft_csm_sampled_pen_mae(11, 2048.0 / 1664.0);
  CHECK(vsh_auto_soft_csm_sampled_pen_mae(16, 2048.0 / 1392.0) >= 0.0527);
  const double t = vsh_auto_soft_csm_sampled_pen_mae(64, 2048.0 / 288.0);
  CHECK(g >= 0.0685 && g < 0.0685 + 0.002);
  CHECK(t >= 0.0724 && t < 0.0724 + 0.002);
  /* Ratio 1 is the technique's own figure; below 1 or NaN counts as 1. */
  CHECK(vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_CSM_SAMPLED, 16) ==
        vsh_auto_soft_csm_sampled_pen_mae(16, 1.0));
  CHECK(vsh_auto_soft_csm_sampled_pen_mae(16, 0.5) == vsh_auto_soft_csm_sampled_pen_mae(16, 1.0));
  CHECK(vsh_auto_soft_csm_sampled_pen_mae(16, NAN) == vsh_auto_soft_csm_sampled_pen_mae(16, 1.0));
  CHECK(vsh_auto_soft_csm_sampled_pen_mae(0, 1.0) == vsh_auto_soft_csm_sampled_pen_mae(1, 1.0));
  CHECK(isfinite(vsh_auto_soft_csm_sampled_pen_mae(64, INFINITY)));

  /* The texel ratio is the pass's own resolution rule: 13 planned maps at
   * 2048 fit 256 MiB (the hard maps lose nothing), N = 16 gives
   * 13 + 208 tiles: 544 texels, N = 64: 272 (docs/soft-shadows.md). */
  vsh_auto_soft_input in = frame(0.03);
  CHECK_NEAR(vsh_auto_soft_csm_texel_ratio(&in, 16), 2048.0 / 544.0, 1e-12);
  CHECK_NEAR(vsh_auto_soft_csm_texel_ratio(&in, 64), 2048.0 / 272.0, 1e-12);
  CHECK(vsh_auto_soft_csm_texel_ratio(NULL, 16) == 1.0);
  in.csm_sampled_tiles = 0; /* no light with a size has maps */
  CHECK(vsh_auto_soft_csm_texel_ratio(&in, 16) == 1.0);
  in = frame(0.03);
  in.csm_budget = 0; /* no cap: no loss */
  CHECK(vsh_auto_soft_csm_texel_ratio(&in, 64) == 1.0);
  in = frame(0.03);
  in.csm_sampled_tiles = 2000000000; /* absurd: no overflow, the 16 floor */
  CHECK_NEAR(vsh_auto_soft_csm_texel_ratio(&in, 64), 2048.0 / 16.0, 1e-9);

  /* Not monotone: at the default budget more samples coarsen the maps, so
   * the lowest predicted error is at a middle N, and an unreachable target
   * gets that N, not the most. */
  in = frame(0.0);
  const int best = vsh_auto_soft_csm_samples_for(&in, 0.0, 4, 64);
  CHECK(best > 4 && best < 64);
  const double at_best = vsh_auto_soft_csm_sampled_pen_mae(best, vsh_auto_soft_csm_texel_ratio(&in, best));
  for (int n = 4; n <= 64; ++n) {
    CHECK(vsh_auto_soft_csm_sampled_pen_mae(n, vsh_auto_soft_csm_texel_ratio(&in, n)) >= at_best);
  }
  CHECK(vsh_auto_soft_csm_samples_for(NULL, 0.03, 4, 64) == 4);
  CHECK(vsh_auto_soft_csm_samples_for(&in, 0.03, 8, 8) == 8);
  /* With memory to spare the error falls with N: 0.03 needs N = 38. */
  in.csm_budget = 0;
  CHECK(vsh_auto_soft_csm_samples_for(&in, 0.03, 4, 64) == 38);
  CHECK(vsh_auto_soft_csm_sampled_pen_mae(38, 1.0) <= 0.03);
  CHECK(vsh_auto_soft_csm_sampled_pen_mae(37, 1.0) > 0.03);

  /* Cost: 1 + N lookups; adaptive: 1 + 8 + penumbra x (N - 8). */
  CHECK_NEAR(vsh_auto_soft_csm_sampled_ms(2.0, 16, 0, 0.25), 34.0, 1e-12);
  CHECK_NEAR(vsh_auto_soft_csm_sampled_ms(2.0, 64, 1, 0.25), 2.0 * (1 + 8 + 14), 1e-12);
  CHECK_NEAR(vsh_auto_soft_csm_sampled_ms(2.0, 8, 1, 0.25), 18.0, 1e-12); /* no rest */
  CHECK_NEAR(vsh_auto_soft_csm_sampled_ms(2.0, 64, 1, NAN), 130.0, 1e-12); /* all pixels */
  CHECK(vsh_auto_soft_csm_sampled_ms(-1.0, 16, 0, 0.0) == 0.0);
  CHECK(vsh_auto_soft_csm_sampled_ms(NAN, 16, 0, 0.0) == 0.0);
}

/* The choice with csm's sampled light: a band of targets where it is the
 * cheapest (no planar), the pass's clamp of 64, adaptive making it cheaper. */
static void test_choose_csm_sampled(void)
{
  vsh_auto_soft_choice c;
  vsh_auto_soft_input in = frame(0.1);
  in.planar_available = 0;
  /* 13 maps of sized lights: at 0.1 sampled needs N = 10, 11 lookups
   * against PCSS's 10 ... */
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_PCSS && c.met == 1);
  CHECK(c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].samples == 10);
  /* ... glyphs-soft's 2 maps stay at full resolution longer: N = 7, 8
   * lookups, cheaper than PCSS. */
  in.csm_tiles = in.csm_sampled_tiles = 2;
  CHECK(vsh_auto_soft_choose(&in, &c) == VSH_AUTO_SOFT_CSM_SAMPLED && c.met == 1);
  CHECK(c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].samples == 7);
  CHECK(c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].pen_mae <= 0.1);
  /* Its N never passes the pass's clamp, even when the bounds allow more. */
  in = frame(0.0);
  in.min_samples = 100;
  in.max_samples = 1024;
  vsh_auto_soft_choose(&in, &c);
  CHECK(c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].samples == VSH_AUTO_SOFT_CSM_MAX_SAMPLES);
  /* Adaptive lookups cost less at the same N. */
  in = frame(0.05);
  in.planar_available = 0;
  vsh_auto_soft_choose(&in, &c);
  const double full = c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].ms;
  const int n = c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].samples;
  in.csm_adaptive = 1;
  vsh_auto_soft_choose(&in, &c);
  CHECK(c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].samples == n);
  CHECK(n <= 8 || c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].ms < full);
  /* csm not available: neither csm candidate. */
  in.csm_available = 0;
  vsh_auto_soft_choose(&in, &c);
  CHECK(c.candidates[VSH_AUTO_SOFT_CSM_SAMPLED].available == 0);
  CHECK(c.pick != VSH_AUTO_SOFT_CSM_SAMPLED && c.pick != VSH_AUTO_SOFT_PCSS);
}

int main(void)
{
  test_csm_sampled_model();
  test_choose_csm_sampled();
  test_model();
  test_samples_for();
  test_costs();
  test_choose();
  test_volume_model();
  test_volume_cost();
  test_choose_volume();
  return vsh_check_report("core.auto_soft");
}
