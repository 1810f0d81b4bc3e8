/* vsh_auto_soft.h - auto's choice for a light with a size (radius or
 * angle): which soft technique, with how many samples, meets a penumbra
 * error target at the least predicted cost.
 *
 * The target is a pen_mae (docs/metrics.md): the mean absolute visibility
 * error inside the reference's penumbra. Each candidate predicts it with
 * one stated model, pen_mae(N) = a / sqrt(N) + b: a sampling term that
 * falls with the N samples per pixel and a bias the technique keeps at any
 * N. PCSS has no N and predicts its bias alone. The constants are fitted
 * to the measurements against POV-Ray's area light in docs/results.md
 * ("Soft shadows", 640x480, light 0 of scenes/soft/sphere-disk and
 * glyphs-soft): a model of those scenes, not a bound for every scene.
 * Costs are milliseconds per frame from the cost estimates auto uses for
 * hard lights (vsh_rt_cost for rays, the per-pixel map lookup for csm)
 * and a planar per-sample term measured the same way. Plain data, no VTK.
 */
#ifndef VSH_AUTO_SOFT_H
#define VSH_AUTO_SOFT_H

#include "vsh_raytrace.h"
#include "vsh_volume_cost.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The soft candidates, in the order of their index in a choice. */
typedef enum vsh_auto_soft_technique {
  VSH_AUTO_SOFT_PLANAR = 0,   /* planar's sampled area light, soft_samples N */
  VSH_AUTO_SOFT_PCSS = 1,     /* csm with PCSS (soft=1) */
  VSH_AUTO_SOFT_RAYTRACE = 2, /* raytrace, samples N (adaptive or not) */
  VSH_AUTO_SOFT_VOLUME = 3,   /* volume's sampled area light, soft_samples N */
  VSH_AUTO_SOFT_CSM_SAMPLED = 4, /* csm's sampled area light (soft=2), soft_samples N */
  VSH_AUTO_SOFT_COUNT = 5
} vsh_auto_soft_technique;

/* Sample counts auto may give planar and raytrace. Below 4 a sampled light
 * is nearly the hard shadow and the model (fitted at 16 and 64) is too
 * optimistic (it predicts 0.13 for planar N = 1, measured 0.19); 1024 is
 * both passes' own upper clamp. */
#define VSH_AUTO_SOFT_MIN_SAMPLES 4
#define VSH_AUTO_SOFT_MAX_SAMPLES 1024
/* volume counts each sample's share of the 8-bit mask in whole steps, so
 * its pass clamps soft_samples to 255 (docs/soft-shadows.md). */
#define VSH_AUTO_SOFT_VOLUME_MAX_SAMPLES 255
/* csm's sampled light renders a map per sample; its pass clamps to 64
 * (VSH_CSM_MAX_SAMPLES). */
#define VSH_AUTO_SOFT_CSM_MAX_SAMPLES 64

/* What the choice needs to know about one light and the frame. */
typedef struct vsh_auto_soft_input {
  double target;          /* pen_mae target, 0 < target <= 1 (0: none meets it) */
  double pixels;          /* viewport pixels */
  int planar_available;   /* every shadow of the light falls on plane receivers */
  int csm_available;      /* cascaded maps can draw the light */
  int pcss;               /* csm may soften (its soft setting is not off): PCSS and
                             the sampled light are candidates; 0: csm is hard */
  int raytrace_available; /* the ray-traced pass can draw the light */
  int volume_available;   /* shadow volumes draw every caster of the light */
  int min_samples;        /* N bounds for planar, raytrace and volume (clamped */
  int max_samples;        /* to the VSH_AUTO_SOFT_* bounds; 0: those bounds) */
  double map_ms;          /* a hard map lookup's cost for the frame (auto's csm_ms) */
  /* The ray-traced pass's cost model and its frame (pixels, coverage,
   * lights, threads, penumbra fraction); samples and first are set per N. */
  vsh_rt_cost_model rt_model;
  vsh_rt_cost_input rt_frame;
  int rt_adaptive; /* the pass's adaptive setting (vsh_rt_adaptive_first) */
  /* The volume pass's hard inputs for the light (its centre): pixels,
   * scene triangles, silhouette edges, fill (vsh_volume_cost.h). */
  vsh_volume_ms_input volume;
  /* csm's sampled light: its maps share one atlas within a memory budget,
   * so more samples mean coarser maps (vsh_csm_sampled_resolution). */
  int csm_resolution;         /* the map resolution csm asks for */
  long long csm_budget;       /* its memory budget, bytes (<= 0: no cap) */
  int csm_tiles;              /* planned maps of every light (hard) */
  int csm_sampled_tiles;      /* planned maps of the lights with a size */
  int csm_adaptive;           /* the pass's adaptive setting (N > 8: a batch of 8) */
} vsh_auto_soft_input;

/* One candidate as weighed: its samples (1 for PCSS), predicted pen_mae
 * and milliseconds. */
typedef struct vsh_auto_soft_candidate {
  int available;
  int samples;
  double pen_mae;
  double ms;
} vsh_auto_soft_candidate;

typedef struct vsh_auto_soft_choice {
  vsh_auto_soft_candidate candidates[VSH_AUTO_SOFT_COUNT];
  int pick; /* a vsh_auto_soft_technique, or -1 when none is available */
  int met;  /* 1 when the pick's predicted pen_mae is at most the target */
} vsh_auto_soft_choice;

/* The model's predicted pen_mae for a technique at N samples (N < 1 counts
 * as 1; PCSS ignores N). NaN for an unknown technique. volume's sampling
 * term falls as a / N^p with its own fitted p (vsh_auto_soft.c): its N
 * fixed, stratified sample positions are a quadrature, not random rays. */
double vsh_auto_soft_pen_mae(int technique, int samples);

/* csm's sampled light at N samples whose maps are `texel_ratio` times
 * coarser than the hard maps would be (>= 1; 1: no loss): the sampling
 * term a / N^p, a floor, and c ln(texel_ratio) for the resolution the
 * budget takes away (vsh_auto_soft.c). texel_ratio < 1 or NaN counts as 1.
 * vsh_auto_soft_pen_mae(VSH_AUTO_SOFT_CSM_SAMPLED, N) is this at ratio 1. */
double vsh_auto_soft_csm_sampled_pen_mae(int samples, double texel_ratio);

/* How much coarser csm's maps get at N samples per map of the lights with a
 * size: resolution(hard tiles) / resolution(hard + N x sampled tiles), both
 * by vsh_csm_sampled_resolution. 1 for NULL or no sampled tiles. */
double vsh_auto_soft_csm_texel_ratio(const vsh_auto_soft_input *input, int samples);

/* The fewest samples in [min_samples, max_samples] whose predicted pen_mae
 * is at most `target`; max_samples when none is (the lowest error the
 * technique offers). min_samples for PCSS. Bounds are used as given
 * (callers clamp them); max_samples < min_samples gives min_samples. */
int vsh_auto_soft_samples_for(int technique, double target, int min_samples, int max_samples);

/* csm's sampled light: the fewest N in [min_samples, max_samples] whose
 * predicted pen_mae at its own texel ratio meets `target`; else the N with
 * the lowest prediction. Not a bisection: more samples also coarsen the
 * maps, so the error need not fall with N. min_samples for NULL. */
int vsh_auto_soft_csm_samples_for(const vsh_auto_soft_input *input, double target,
                                  int min_samples, int max_samples);

/* Planar's predicted milliseconds for one (receiver, light) pair at N
 * samples over `pixels` viewport pixels. */
double vsh_auto_soft_planar_ms(double pixels, int samples);

/* volume at N samples: the hard model (vsh_volume_cost_ms, one count)
 * plus N - 1 further counts, each paying the per-sample terms again (side
 * quads, fill, and the per-pixel stencil clear and accumulation); the depth
 * pre-pass (the triangle term) is paid once. +inf for NULL or inputs the
 * hard model refuses. N < 1 counts as 1. */
double vsh_auto_soft_volume_ms(const vsh_volume_ms_input *volume, int samples);

/* csm's sampled light: map_ms x (1 + lookups), lookups N or, adaptive
 * with N > 8, 8 + penumbra x (N - 8): each sample one more hard lookup and
 * its share of the map renders (vsh_auto_soft.c). */
double vsh_auto_soft_csm_sampled_ms(double map_ms, int samples, int adaptive, double penumbra);

/* csm with PCSS: map_ms (one hard lookup per pixel) times the measured
 * factor of PCSS's taps over a hard lookup. */
double vsh_auto_soft_pcss_ms(double map_ms);

/* Weighs the candidates and picks the cheapest available one whose
 * predicted pen_mae meets the target (ties: the lower index); when none
 * meets it, the one with the lowest predicted pen_mae (raytrace at its
 * largest N when it is available) and met = 0. Returns the pick (-1 when
 * no candidate is available or input is NULL). An unavailable candidate's
 * figures are still filled in for the report. */
int vsh_auto_soft_choose(const vsh_auto_soft_input *input, vsh_auto_soft_choice *choice);

#ifdef __cplusplus
}
#endif
#endif
