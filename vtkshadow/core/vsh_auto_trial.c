/* vsh_auto_trial.c - timed choice between the exact techniques
 * (vsh_auto_trial.h). */
#include "vsh_auto_trial.h"

#include <math.h>
#include <stddef.h>

/* The models were off by 1.4-1.8x on isosurface and within 2x on most
 * rows of their fit (vsh_volume_cost.c): 4x leaves room for a model wrong
 * by 2x in each direction. */
const double VSH_AUTO_TRIAL_MAX_PREDICTED_RATIO = 4.0;
/* Single frames on the shared 2-core machine vary by 10-20 %; the fastest
 * of two varies less. A technique must be 10 % faster to take over. */
const double VSH_AUTO_TRIAL_SWITCH_RATIO = 0.9;

static void drop_timings(vsh_auto_trial *t)
{
  for (int i = 0; i < VSH_AUTO_TRIAL_COUNT; ++i) {
    t->ms[i] = INFINITY;
    t->samples[i] = 0;
  }
  t->started = -1;
  t->tried_other = 0;
  t->incumbent = -1;
}

void vsh_auto_trial_reset(vsh_auto_trial *trial)
{
  if (!trial) return;
  trial->frame = 0;
  trial->lights = 0;
  trial->drawn = -1;
  trial->run = 0;
  trial->scene = 0;
  trial->changed = 0;
  drop_timings(trial);
}

int vsh_auto_trial_timed(const vsh_auto_trial *trial, int technique)
{
  return trial && technique >= 0 && technique < VSH_AUTO_TRIAL_COUNT &&
         trial->samples[technique] >= VSH_AUTO_TRIAL_SAMPLES;
}

static double prediction(const double *predicted, int technique)
{
  const double p = predicted[technique];
  return isnan(p) || p < 0.0 ? INFINITY : p;
}

/* Whether the untimed technique `other` is worth frames: predicted at most
 * the ratio times the timed one's prediction. */
static int worth_trying(const double *predicted, int timed, int other)
{
  const double mine = prediction(predicted, timed), theirs = prediction(predicted, other);
  if (isinf(theirs)) return 0;
  return isinf(mine) || theirs <= VSH_AUTO_TRIAL_MAX_PREDICTED_RATIO * mine;
}

/* The technique to draw with what is timed so far. */
static int choose(vsh_auto_trial *t, int current, const double *predicted)
{
  if (t->incumbent < 0) t->incumbent = current;
  const int other = 1 - current;
  if (!vsh_auto_trial_timed(t, current)) return current;
  if (!vsh_auto_trial_timed(t, other)) {
    if (!t->tried_other && worth_trying(predicted, current, other)) return other;
    t->tried_other = 1;
    return current;
  }
  /* The hysteresis favours the technique drawn before the pair's timing,
   * not the one tried last. */
  const int challenger = 1 - t->incumbent;
  return t->ms[challenger] < VSH_AUTO_TRIAL_SWITCH_RATIO * t->ms[t->incumbent] ? challenger
                                                                                : t->incumbent;
}

/* Timings too old, or taken before an edit the scene has since held
 * still after. */
static int stale(const vsh_auto_trial *t)
{
  if (t->started < 0) return 0;
  return t->frame - t->started > VSH_AUTO_TRIAL_MAX_AGE ||
         (t->changed > t->started && t->frame - t->changed >= VSH_AUTO_TRIAL_SETTLE);
}

vsh_auto_trial_step vsh_auto_trial_next(vsh_auto_trial *trial, unsigned int lights,
                                        unsigned long long scene, int model,
                                        const double predicted[VSH_AUTO_TRIAL_COUNT])
{
  vsh_auto_trial_step step = {model, 0};
  if (!trial || !predicted || model < 0 || model >= VSH_AUTO_TRIAL_COUNT) return step;
  vsh_auto_trial *t = trial;
  ++t->frame;
  if (scene != t->scene) {
    t->scene = scene;
    t->changed = t->frame;
  }
  if (lights == 0 || lights != t->lights) {
    drop_timings(t);
    t->lights = lights;
  }
  if (lights == 0) {
    t->run = t->drawn == model ? t->run + 1 : 1;
    t->drawn = model;
    return step;
  }
  if (stale(t)) drop_timings(t);
  const int current = t->drawn >= 0 ? t->drawn : model;
  step.technique = choose(t, current, predicted);
  if (step.technique != current) {
    /* Leaving the current one for good ends the other's trial too. */
    t->tried_other = 1;
  }
  t->run = step.technique == t->drawn ? t->run + 1 : 1;
  t->drawn = step.technique;
  step.time_frame =
    t->run > VSH_AUTO_TRIAL_WARMUP && !vsh_auto_trial_timed(t, step.technique) ? 1 : 0;
  return step;
}

void vsh_auto_trial_record(vsh_auto_trial *trial, int technique, double ms)
{
  if (!trial || technique < 0 || technique >= VSH_AUTO_TRIAL_COUNT || !isfinite(ms) || ms <= 0.0)
    return;
  int *n = &trial->samples[technique];
  if (*n >= VSH_AUTO_TRIAL_SAMPLES) return;
  if (trial->started < 0) trial->started = trial->frame;
  double *times = trial->times[technique];
  /* Insertion keeps the samples sorted: the median is the middle one. */
  int at = (*n)++;
  for (; at > 0 && times[at - 1] > ms; --at) times[at] = times[at - 1];
  times[at] = ms;
  if (*n == VSH_AUTO_TRIAL_SAMPLES) trial->ms[technique] = times[VSH_AUTO_TRIAL_SAMPLES / 2];
}

/* The general candidate of each exact technique. */
static const int General[VSH_AUTO_TRIAL_COUNT] = {VSH_AUTO_GENERAL_VOLUME,
                                                  VSH_AUTO_GENERAL_RAYTRACE};

static int trial_of(int pick)
{
  return pick == VSH_AUTO_GENERAL_VOLUME     ? VSH_AUTO_TRIAL_VOLUME
         : pick == VSH_AUTO_GENERAL_RAYTRACE ? VSH_AUTO_TRIAL_RAYTRACE
                                             : -1;
}

static int meets(const vsh_auto_candidate *c, double max_error_pct)
{
  return c->available && !isnan(c->cost) && c->predicted_error_pct <= max_error_pct;
}

unsigned int vsh_auto_trial_lights(const vsh_auto_general_light *lights, const int *index,
                                   int count, double max_error_pct, int *model,
                                   double predicted[VSH_AUTO_TRIAL_COUNT])
{
  if (!lights || !index || !model || !predicted || count <= 0 || isnan(max_error_pct)) return 0;
  unsigned int mask = 0;
  int picked = -1;
  double sums[VSH_AUTO_TRIAL_COUNT] = {0.0, 0.0};
  for (int i = 0; i < count; ++i) {
    const int t = trial_of(lights[i].pick);
    if (t < 0) continue;
    const vsh_auto_candidate *c = lights[i].candidates;
    if ((picked >= 0 && t != picked) || index[i] < 0 || index[i] > 31 ||
        !meets(&c[General[0]], max_error_pct) || !meets(&c[General[1]], max_error_pct))
      return 0;
    picked = t;
    mask |= 1u << index[i];
    for (int k = 0; k < VSH_AUTO_TRIAL_COUNT; ++k) sums[k] += c[General[k]].cost;
  }
  if (mask) {
    *model = picked;
    predicted[0] = sums[0];
    predicted[1] = sums[1];
  }
  return mask;
}

void vsh_auto_trial_apply(vsh_auto_general_light *lights, const int *index, int count,
                          unsigned int mask, int technique)
{
  if (!lights || !index || technique < 0 || technique >= VSH_AUTO_TRIAL_COUNT) return;
  for (int i = 0; i < count; ++i) {
    if (index[i] >= 0 && index[i] <= 31 && (mask >> index[i]) & 1u) {
      /* met stays: vsh_auto_trial_lights found both within the target. */
      lights[i].pick = General[technique];
    }
  }
}
