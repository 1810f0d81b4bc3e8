/* vsh_auto_soft.c - the soft-light choice of auto (vsh_auto_soft.h). */
#include "vsh_auto_soft.h"

#include "vsh_auto_general.h"
#include "vsh_csm_sampled.h"
#include "vsh_rt_adaptive.h"

#include <math.h>
#include <stddef.h>

/* pen_mae(N) = a / sqrt(N) + b, against POV-Ray's area light (grid 17),
 * light 0 of scenes/soft/sphere-disk at 640x480 (docs/results.md, "Soft
 * shadows"):
 * - planar: through N = 16 (0.0409) and 64 (0.0264): a = 0.12, b = 0.011.
 *   The bias is what planar never draws: the caster's own penumbra on its
 *   terminator (planar shadows receivers only) and the disk facing the
 *   caster's centre; against the exact penumbra on the plane alone planar
 *   has none (0.008 at N = 64, docs/soft-shadows.md).
 * - raytrace: unbiased (measured bias under 0.001); like PCSS, a is taken
 *   from the worse of the two scenes, so that a target is met on scenes
 *   the fit has not seen: glyphs-soft, N = 16 (0.058) and 64 (0.024),
 *   fitted through the origin: a = 0.22 (sphere-disk alone gives 0.106:
 *   0.0276 and 0.0111; glyphs-soft's narrow, overlapping penumbrae are a
 *   few pixels wide, where sampling noise weighs more). Rays rotated per
 *   pixel fall faster than 1/sqrt(N) from N = 1 to 16, so the model is
 *   pessimistic above 64 and optimistic below 16.
 * - PCSS (csm, soft=1): no N; the worse of the two scenes, glyphs-soft
 *   0.0904 (sphere-disk 0.0550): overlapping blockers at different depths
 *   get one width, which the glyphs are full of.
 * - csm with PCSS off: the hard shadow, 0.30 (glyphs-soft 0.3006,
 *   sphere-disk 0.1868). */
#define PLANAR_A 0.12
#define PLANAR_B 0.011
#define RAYTRACE_A 0.22
#define RAYTRACE_B 0.0
#define PCSS_PEN_MAE 0.090
#define HARD_PEN_MAE 0.30
/* volume (soft_samples N): pen_mae(N) = a / N^p + b against Cycles 1024
 * samples at pixel centres, 256x192 (`vtkshadow-render --set
 * soft_samples=N --light K --size 256x192` scored over Cycles' penumbra).
 * Its N sample positions are fixed and stratified (a quadrature, exact per
 * sample), so the error falls faster than random rays' 1/sqrt(N): against
 * the exact penumbra 0.0715 / 0.0235 / 0.0080 at N = 4 / 16 / 64
 * (harness.soft_volume), about N^-0.79. Fitted, like raytrace, to the
 * worse library scene, glyphs-soft light 0: 0.0566 / 0.0348 / 0.0224 at
 * N = 16 / 32 / 64; p = 0.75, then a and b through 16 and 64 (0.0352
 * predicted at 32). b (0.0037) is about Cycles' own noise there. The
 * simple scenes measured half of it: sphere-disk light 0 0.0261 / 0.0153 /
 * 0.0091 / 0.0054 at 16 / 32 / 64 / 128, light 1 0.0278 / 0.0157 /
 * 0.0096 / 0.0083; sun-angle 0.0204 / 0.0130 / 0.0077 / 0.0052 and 0.0176
 * / 0.0134 / 0.0120 / 0.0110 (a 2 degree sun's caster terminators);
 * glyphs-soft light 1 0.0401 / 0.0228 / 0.0137 at 16 / 32 / 64. */
#define VOLUME_A 0.4235
#define VOLUME_P 0.75
#define VOLUME_B 0.0037
/* csm's sampled light (soft=2, soft_samples N): pen_mae(N, t) = a / N^p + b
 * + c ln(t), t how many times coarser than the hard maps the budget makes
 * each map (vsh_auto_soft_csm_texel_ratio). Against Cycles (1024 samples,
 * pixel centres, 256x192; docs/soft-shadows.md, "csm against Cycles", and
 * docs/auto.md): 55 light-configurations of 3 library and 3 held-out scenes
 * at N = 5, 11, 16 and 64 (default budget) and 64 with a 1e9 budget, t from
 * 1 to 7.1, csm at its own map_resolution (2048) within the budget. a, b,
 * c and p (searched over 0.5..1) are the upper envelope of all 55 with the
 * least total excess, as the other candidates are fitted to their worse
 * scene. It touches glyphs-soft light 0 at N = 11 (0.0685, t 1.23;
 * predicted 0.069), torus-disk light 1 at N = 64 (0.0724, t 7.1; 0.0725),
 * glyphs-soft light 1 at N = 64 (0.0479, t 2.9; 0.050). Median excess
 * 0.038 (sphere-disk light 0 measured 0.0093 at N = 64, t 3.66, predicted
 * 0.056): a light's maps are coarse or fine in pixels, not in texels,
 * which the model cannot see, so it is safe on small glyphs and wasteful
 * on large smooth casters. */
#define CSM_SAMPLED_A 0.44
#define CSM_SAMPLED_P 0.9
#define CSM_SAMPLED_B 0.013
#define CSM_SAMPLED_C 0.025

/* Costs (ms per pixel of the viewport), from the same table (glyphs-soft,
 * 640x480 = 307,200 px, 2 soft pairs, interleaved against none on a
 * loaded 2-core VM under llvmpipe: the order of magnitude, not more):
 * - planar: each sample (452.6 - 30.7) / 63 / 2 = 3.35 ms a pair: 1.09e-5
 *   per pixel (a stencil clear, the casters, a viewport quad); N = 1 costs
 *   13.0 ms over none, 6.5 ms a pair, so the pair's fixed part is 3.15 ms:
 *   1.03e-5 per pixel. The dearer of the two scenes (sphere-disk: 1.15 ms
 *   a sample and pair).
 * - PCSS: 16 blocker and 24 filter taps against one hard lookup measured
 *   212.8 / 21.1 = 10.1 times the hard map's shadow work on glyphs-soft
 *   (84.1 / 11.6 = 7.3 on sphere-disk): 10. */
#define PLANAR_BASE_MS_PER_PX 1.03e-5
#define PLANAR_SAMPLE_MS_PER_PX 1.09e-5
#define PCSS_COST_FACTOR 10.0
/* csm's sampled light per frame against a hard frame's shadow work, same
 * machine and table method (docs/soft-shadows.md, csm "Cost", 400x300):
 * N = 4 / 16 / 64 cost 4.4 / 15 / 49 hard lookups on the still test scene
 * and 19 / 56 at N = 16 / 64 on glyphs-soft, whose orbiting camera
 * re-renders every sample map each frame (taking PCSS as 10): 1 + N. The
 * adaptive batch of 8 (csm's `adaptive`) stops where it agrees. */
#define CSM_SAMPLED_BATCH 8

double vsh_auto_soft_pen_mae(int technique, int samples)
{
  const double n = samples > 1 ? (double)samples : 1.0;
  switch (technique) {
  case VSH_AUTO_SOFT_PLANAR:
    return PLANAR_A / sqrt(n) + PLANAR_B;
  case VSH_AUTO_SOFT_RAYTRACE:
    return RAYTRACE_A / sqrt(n) + RAYTRACE_B;
  case VSH_AUTO_SOFT_PCSS:
    return PCSS_PEN_MAE;
  case VSH_AUTO_SOFT_VOLUME:
    return VOLUME_A / pow(n, VOLUME_P) + VOLUME_B;
  case VSH_AUTO_SOFT_CSM_SAMPLED:
    return vsh_auto_soft_csm_sampled_pen_mae(samples, 1.0);
  default:
    return NAN;
  }
}

double vsh_auto_soft_csm_sampled_pen_mae(int samples, double texel_ratio)
{
  const double n = samples > 1 ? (double)samples : 1.0;
  const double t = texel_ratio > 1.0 && isfinite(texel_ratio) ? texel_ratio : 1.0;
  return CSM_SAMPLED_A / pow(n, CSM_SAMPLED_P) + CSM_SAMPLED_B + CSM_SAMPLED_C * log(t);
}

double vsh_auto_soft_csm_texel_ratio(const vsh_auto_soft_input *in, int samples)
{
  if (!in || in->csm_sampled_tiles <= 0 || in->csm_resolution < 16) {
    return 1.0;
  }
  const int n = samples > 1 ? samples : 1;
  const int hard_tiles = in->csm_tiles > 0 ? in->csm_tiles : in->csm_sampled_tiles;
  /* Tiles in doubles first: N x tiles cannot overflow an int here (64 x 24
   * at most in the pass), but the input is plain data from anyone. */
  const double tiles = (double)hard_tiles + (double)n * in->csm_sampled_tiles;
  const int sampled_tiles = tiles < 1e9 ? (int)tiles : 1000000000;
  const int hard = vsh_csm_sampled_resolution(in->csm_resolution, hard_tiles, in->csm_budget);
  const int coarse = vsh_csm_sampled_resolution(in->csm_resolution, sampled_tiles, in->csm_budget);
  return coarse > 0 && hard > coarse ? (double)hard / (double)coarse : 1.0;
}

int vsh_auto_soft_csm_samples_for(const vsh_auto_soft_input *in, double target, int min_samples,
                                  int max_samples)
{
  if (!in || max_samples <= min_samples) {
    return min_samples;
  }
  int best = min_samples;
  double best_error = INFINITY;
  for (int n = min_samples; n <= max_samples; ++n) {
    const double e = vsh_auto_soft_csm_sampled_pen_mae(n, vsh_auto_soft_csm_texel_ratio(in, n));
    if (e <= target) {
      return n;
    }
    if (e < best_error) {
      best_error = e;
      best = n;
    }
  }
  return best;
}

double vsh_auto_soft_csm_sampled_ms(double map_ms, int samples, int adaptive, double penumbra)
{
  if (!(map_ms > 0.0) || !isfinite(map_ms)) {
    return 0.0;
  }
  const double n = samples > 1 ? (double)samples : 1.0;
  double lookups = n;
  if (adaptive && n > CSM_SAMPLED_BATCH) {
    const double f = penumbra >= 0.0 && penumbra <= 1.0 ? penumbra : 1.0;
    lookups = CSM_SAMPLED_BATCH + f * (n - CSM_SAMPLED_BATCH);
  }
  return map_ms * (1.0 + lookups);
}

int vsh_auto_soft_samples_for(int technique, double target, int min_samples, int max_samples)
{
  if (technique == VSH_AUTO_SOFT_PCSS || max_samples <= min_samples) {
    return min_samples;
  }
  if (!(vsh_auto_soft_pen_mae(technique, max_samples) <= target)) {
    return max_samples; /* also a NaN target */
  }
  /* The error falls monotonically with N: bisect for the first N that
   * meets the target (at most 11 steps over 1..1024). */
  int lo = min_samples, hi = max_samples;
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (vsh_auto_soft_pen_mae(technique, mid) <= target) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  return lo;
}

double vsh_auto_soft_planar_ms(double pixels, int samples)
{
  const double px = pixels > 0.0 && isfinite(pixels) ? pixels : 0.0;
  const double n = samples > 1 ? (double)samples : 1.0;
  return px * (PLANAR_BASE_MS_PER_PX + n * PLANAR_SAMPLE_MS_PER_PX);
}

double vsh_auto_soft_volume_ms(const vsh_volume_ms_input *volume, int samples)
{
  const double hard = vsh_volume_cost_ms(volume);
  if (!isfinite(hard)) {
    return INFINITY;
  }
  const double n = samples > 1 ? (double)samples : 1.0;
  const double per_sample = VSH_VOLUME_MS_PER_EDGE * volume->silhouette_edges +
                            VSH_VOLUME_MS_PER_FILL_PX * volume->fill_px +
                            VSH_VOLUME_MS_PER_PIXEL * volume->pixels;
  const double ms = hard + (n - 1.0) * per_sample;
  return isfinite(ms) ? ms : INFINITY;
}

double vsh_auto_soft_pcss_ms(double map_ms)
{
  return map_ms > 0.0 && isfinite(map_ms) ? PCSS_COST_FACTOR * map_ms : 0.0;
}

static int clamp_samples(int n, int fallback)
{
  if (n <= 0) {
    return fallback;
  }
  return n < VSH_AUTO_SOFT_MIN_SAMPLES
           ? VSH_AUTO_SOFT_MIN_SAMPLES
           : (n > VSH_AUTO_SOFT_MAX_SAMPLES ? VSH_AUTO_SOFT_MAX_SAMPLES : n);
}

static double raytrace_ms(const vsh_auto_soft_input *in, int samples)
{
  vsh_rt_cost_input frame = in->rt_frame;
  frame.pixels = in->pixels;
  frame.samples = samples;
  frame.first = vsh_rt_adaptive_first(samples, in->rt_adaptive, VSH_RT_ADAPTIVE_BATCH);
  frame.traced = 1.0; /* the classifier decides hard lights only */
  return vsh_rt_cost_ms(&in->rt_model, &frame);
}

int vsh_auto_soft_choose(const vsh_auto_soft_input *in, vsh_auto_soft_choice *choice)
{
  if (!in || !choice) {
    return -1;
  }
  const int lo = clamp_samples(in->min_samples, VSH_AUTO_SOFT_MIN_SAMPLES);
  const int hi = clamp_samples(in->max_samples, VSH_AUTO_SOFT_MAX_SAMPLES);
  /* A target that is not a number meets nothing (then the lowest error). */
  const double target = isfinite(in->target) ? in->target : -1.0;
  vsh_auto_soft_candidate *c = choice->candidates;

  const int planar_n = vsh_auto_soft_samples_for(VSH_AUTO_SOFT_PLANAR, target, lo, hi);
  c[VSH_AUTO_SOFT_PLANAR].available = in->planar_available != 0;
  c[VSH_AUTO_SOFT_PLANAR].samples = planar_n;
  c[VSH_AUTO_SOFT_PLANAR].pen_mae = vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_PLANAR, planar_n);
  c[VSH_AUTO_SOFT_PLANAR].ms = vsh_auto_soft_planar_ms(in->pixels, planar_n);

  c[VSH_AUTO_SOFT_PCSS].available = in->csm_available != 0;
  c[VSH_AUTO_SOFT_PCSS].samples = 1;
  c[VSH_AUTO_SOFT_PCSS].pen_mae =
    in->pcss ? vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_PCSS, 1) : HARD_PEN_MAE;
  c[VSH_AUTO_SOFT_PCSS].ms =
    in->pcss ? vsh_auto_soft_pcss_ms(in->map_ms) : (in->map_ms > 0.0 ? in->map_ms : 0.0);

  const int ray_n = vsh_auto_soft_samples_for(VSH_AUTO_SOFT_RAYTRACE, target, lo, hi);
  c[VSH_AUTO_SOFT_RAYTRACE].available = in->raytrace_available != 0;
  c[VSH_AUTO_SOFT_RAYTRACE].samples = ray_n;
  c[VSH_AUTO_SOFT_RAYTRACE].pen_mae = vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_RAYTRACE, ray_n);
  c[VSH_AUTO_SOFT_RAYTRACE].ms = raytrace_ms(in, ray_n);

  /* volume's own clamp is lower (its 8-bit mask steps); reversed bounds
   * give min, as for the others. */
  const int top = hi > lo ? hi : lo;
  const int volume_hi =
    top < VSH_AUTO_SOFT_VOLUME_MAX_SAMPLES ? top : VSH_AUTO_SOFT_VOLUME_MAX_SAMPLES;
  const int volume_lo = lo < volume_hi ? lo : volume_hi;
  const int volume_n = vsh_auto_soft_samples_for(VSH_AUTO_SOFT_VOLUME, target, volume_lo, volume_hi);
  c[VSH_AUTO_SOFT_VOLUME].available = in->volume_available != 0;
  c[VSH_AUTO_SOFT_VOLUME].samples = volume_n;
  c[VSH_AUTO_SOFT_VOLUME].pen_mae = vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_VOLUME, volume_n);
  c[VSH_AUTO_SOFT_VOLUME].ms = vsh_auto_soft_volume_ms(&in->volume, volume_n);

  /* csm's sampled light: its pass's clamp (64), and only where csm may
   * soften at all (soft not off). */
  const int csm_hi = top < VSH_AUTO_SOFT_CSM_MAX_SAMPLES ? top : VSH_AUTO_SOFT_CSM_MAX_SAMPLES;
  const int csm_lo = lo < csm_hi ? lo : csm_hi;
  const int csm_n = vsh_auto_soft_csm_samples_for(in, target, csm_lo, csm_hi);
  c[VSH_AUTO_SOFT_CSM_SAMPLED].available = in->csm_available != 0 && in->pcss != 0;
  c[VSH_AUTO_SOFT_CSM_SAMPLED].samples = csm_n;
  c[VSH_AUTO_SOFT_CSM_SAMPLED].pen_mae =
    vsh_auto_soft_csm_sampled_pen_mae(csm_n, vsh_auto_soft_csm_texel_ratio(in, csm_n));
  c[VSH_AUTO_SOFT_CSM_SAMPLED].ms =
    vsh_auto_soft_csm_sampled_ms(in->map_ms, csm_n, in->csm_adaptive, in->rt_frame.penumbra);

  /* The same rule as the general choice: cheapest meeting the target, else
   * the lowest error (ties: cheaper). */
  vsh_auto_candidate weighed[VSH_AUTO_SOFT_COUNT];
  for (int i = 0; i < VSH_AUTO_SOFT_COUNT; ++i) {
    weighed[i].available = c[i].available;
    weighed[i].predicted_error_pct = c[i].pen_mae;
    weighed[i].cost = c[i].ms;
  }
  int met = 0;
  choice->pick = vsh_auto_pick_cheapest(weighed, VSH_AUTO_SOFT_COUNT, target, &met);
  choice->met = choice->pick >= 0 ? met : 0;
  return choice->pick;
}
