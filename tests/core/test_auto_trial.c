/* core.auto_trial: the timed choice between the exact techniques
 * (vsh_auto_trial.h): the schedule of warm-up and timed frames, the faster
 * timing winning against the models' pick, the hysteresis, expiry, the
 * lights that may take part, and degenerate input. */
#include "vsh_auto_trial.h"
#include "vsh_check.h"

#include <math.h>

enum { V = VSH_AUTO_TRIAL_VOLUME, R = VSH_AUTO_TRIAL_RAYTRACE };

/* Steps one frame and, when asked, reports `ms[technique]` as its time. */
static vsh_auto_trial_step frame(vsh_auto_trial *t, unsigned int lights, int model,
                                 const double *predicted, const double *ms)
{
  const vsh_auto_trial_step s = vsh_auto_trial_next(t, lights, 7u, model, predicted);
  if (s.time_frame) vsh_auto_trial_record(t, s.technique, ms[s.technique]);
  return s;
}

/* isosurface on the slower machine: the models pick volume (208 ms
 * predicted against 221), volume measures 290 ms and raytrace 195. */
static void test_timed_faster_wins(void)
{
  vsh_auto_trial t;
  vsh_auto_trial_reset(&t);
  const double predicted[2] = {208.0, 221.0}, ms[2] = {290.0, 195.0};
  /* Volume: warm-up, then its samples; raytrace the same; then raytrace
   * untimed. */
  const int per = VSH_AUTO_TRIAL_WARMUP + VSH_AUTO_TRIAL_SAMPLES;
  for (int f = 0; f < 2 * per + 1; ++f) {
    const vsh_auto_trial_step s = frame(&t, 3u, V, predicted, ms);
    CHECK(s.technique == (f < per ? V : R));
    CHECK(s.time_frame == (f < 2 * per && f % per >= VSH_AUTO_TRIAL_WARMUP));
  }
  CHECK(vsh_auto_trial_timed(&t, V) && vsh_auto_trial_timed(&t, R));
  CHECK_NEAR(t.ms[V], 290.0, 0.0);
  CHECK_NEAR(t.ms[R], 195.0, 0.0);
  /* It stays with raytrace, untimed, until the timings expire. */
  for (int f = 2 * per + 1; f < VSH_AUTO_TRIAL_MAX_AGE; ++f) {
    const vsh_auto_trial_step s = frame(&t, 3u, V, predicted, ms);
    CHECK(s.technique == R && s.time_frame == 0);
  }
}

/* The models were right: the other is tried, loses, and the pick stays. */
static void test_model_confirmed(void)
{
  vsh_auto_trial t;
  vsh_auto_trial_reset(&t);
  const double predicted[2] = {20.0, 30.0}, ms[2] = {25.0, 40.0};
  int last = -1, timed = 0, switches = 0;
  for (int f = 0; f < 40; ++f) {
    const vsh_auto_trial_step s = frame(&t, 1u, V, predicted, ms);
    switches += last >= 0 && s.technique != last;
    last = s.technique;
    timed += s.time_frame;
  }
  CHECK(last == V);
  CHECK(switches == 2); /* to raytrace for its trial, and back */
  CHECK(timed == 2 * VSH_AUTO_TRIAL_SAMPLES);
}

/* The median frame counts: one frame slowed (load) or sped up (work
 * skipped) does not decide. And the incumbent gives way only to one under
 * the switch ratio of its time. */
static void test_median_and_hysteresis(void)
{
  CHECK(VSH_AUTO_TRIAL_SAMPLES == 3);
  vsh_auto_trial t;
  vsh_auto_trial_reset(&t);
  const double predicted[2] = {10.0, 10.0};
  for (int f = 0; f < VSH_AUTO_TRIAL_WARMUP; ++f)
    CHECK(vsh_auto_trial_next(&t, 1u, 7u, V, predicted).time_frame == 0);
  const double volume[3] = {100.0, 61.0, 5.0};
  for (int i = 0; i < 3; ++i) {
    CHECK(vsh_auto_trial_next(&t, 1u, 7u, V, predicted).time_frame == 1);
    vsh_auto_trial_record(&t, V, volume[i]);
    CHECK(vsh_auto_trial_timed(&t, V) == (i == 2));
  }
  CHECK_NEAR(t.ms[V], 61.0, 0.0);
  /* Samples past the timing are not taken. */
  vsh_auto_trial_record(&t, V, 1.0);
  CHECK_NEAR(t.ms[V], 61.0, 0.0);
  /* Raytrace at 0.95x: not enough to take over. */
  const double ms[2] = {61.0, 0.95 * 61.0};
  int last = -1;
  for (int f = 0; f < 30; ++f) last = frame(&t, 1u, V, predicted, ms).technique;
  CHECK(last == V);
  /* Just under 0.9x it takes over. */
  vsh_auto_trial u;
  vsh_auto_trial_reset(&u);
  const double faster[2] = {60.0, 0.9 * 60.0 - 0.01};
  for (int f = 0; f < 30; ++f) last = frame(&u, 1u, V, predicted, faster).technique;
  CHECK(last == R);
  /* The hysteresis is the incumbent's, not the last tried's: raytrace
   * first (the models' pick) at 0.95x of volume stays. */
  vsh_auto_trial w;
  vsh_auto_trial_reset(&w);
  const double close[2] = {60.0, 57.0};
  for (int f = 0; f < 30; ++f) last = frame(&w, 1u, R, predicted, close).technique;
  CHECK(last == R && w.incumbent == R);
}

/* A technique predicted far dearer is never tried; a prediction that is
 * NaN, negative or infinite counts as never worth trying. */
static void test_not_worth_trying(void)
{
  const double cases[4][2] = {
      {10.0, 10.0 * VSH_AUTO_TRIAL_MAX_PREDICTED_RATIO + 1.0},
      {10.0, NAN},
      {10.0, -1.0},
      {10.0, INFINITY},
  };
  for (int c = 0; c < 4; ++c) {
    vsh_auto_trial t;
    vsh_auto_trial_reset(&t);
    const double ms[2] = {50.0, 1.0};
    int drew_other = 0;
    for (int f = 0; f < 40; ++f) drew_other |= frame(&t, 1u, V, cases[c], ms).technique != V;
    CHECK(!drew_other);
  }
  /* At the ratio it is tried. */
  vsh_auto_trial t;
  vsh_auto_trial_reset(&t);
  const double at[2] = {10.0, 10.0 * VSH_AUTO_TRIAL_MAX_PREDICTED_RATIO}, ms[2] = {50.0, 1.0};
  int last = -1;
  for (int f = 0; f < 30; ++f) last = frame(&t, 1u, V, at, ms).technique;
  CHECK(last == R);
}

/* Timings expire after MAX_AGE frames and the trial runs again: the cost
 * changed with the camera, so the other technique wins now. */
static void test_expiry(void)
{
  vsh_auto_trial t;
  vsh_auto_trial_reset(&t);
  const double predicted[2] = {10.0, 10.0}, before[2] = {20.0, 40.0}, after[2] = {80.0, 40.0};
  int last = -1;
  for (int f = 0; f < 50; ++f) last = frame(&t, 1u, V, predicted, before).technique;
  CHECK(last == V);
  int timed = 0;
  for (int f = 50; f < VSH_AUTO_TRIAL_MAX_AGE + 20; ++f) {
    const vsh_auto_trial_step s = frame(&t, 1u, V, predicted, after);
    timed += s.time_frame;
    last = s.technique;
  }
  CHECK(last == R);
  CHECK(timed == 2 * VSH_AUTO_TRIAL_SAMPLES);
}

/* An edit (a new scene key) drops the timings once the scene has held
 * still for SETTLE frames after it; a scene edited every frame keeps them
 * until they expire. */
static void test_scene_edits(void)
{
  const double predicted[2] = {10.0, 10.0}, before[2] = {20.0, 40.0}, after[2] = {80.0, 40.0};
  vsh_auto_trial t;
  vsh_auto_trial_reset(&t);
  int last = -1;
  for (int f = 0; f < 20; ++f) {
    const vsh_auto_trial_step s = vsh_auto_trial_next(&t, 1u, 5u, V, predicted);
    if (s.time_frame) vsh_auto_trial_record(&t, s.technique, before[s.technique]);
    last = s.technique;
  }
  CHECK(last == V && vsh_auto_trial_timed(&t, R));
  /* The edit, then the scene still: timed again after SETTLE frames. */
  int timed = 0, settled_at = -1;
  for (int f = 0; f < VSH_AUTO_TRIAL_SETTLE + 20; ++f) {
    const vsh_auto_trial_step s = vsh_auto_trial_next(&t, 1u, 6u, V, predicted);
    if (s.time_frame) {
      if (settled_at < 0) settled_at = f;
      vsh_auto_trial_record(&t, s.technique, after[s.technique]);
      ++timed;
    }
    last = s.technique;
  }
  CHECK(settled_at == VSH_AUTO_TRIAL_SETTLE);
  CHECK(timed == 2 * VSH_AUTO_TRIAL_SAMPLES);
  CHECK(last == R);
  /* Edited every frame: nothing timed again before the timings expire. */
  vsh_auto_trial u;
  vsh_auto_trial_reset(&u);
  for (int f = 0; f < 20; ++f) {
    const vsh_auto_trial_step s = vsh_auto_trial_next(&u, 1u, 5u, V, predicted);
    if (s.time_frame) vsh_auto_trial_record(&u, s.technique, before[s.technique]);
  }
  timed = 0;
  for (int f = 20; f < VSH_AUTO_TRIAL_MAX_AGE; ++f)
    timed += vsh_auto_trial_next(&u, 1u, 100u + (unsigned long long)f, V, predicted).time_frame;
  CHECK(timed == 0);
}

/* Another set of exact lights drops the timings; no exact light hands the
 * frame to the models, untimed. */
static void test_lights_change(void)
{
  vsh_auto_trial t;
  vsh_auto_trial_reset(&t);
  const double predicted[2] = {10.0, 10.0}, ms[2] = {20.0, 40.0};
  for (int f = 0; f < 30; ++f) frame(&t, 1u, V, predicted, ms);
  CHECK(vsh_auto_trial_timed(&t, V) && vsh_auto_trial_timed(&t, R));
  vsh_auto_trial_step s = frame(&t, 3u, V, predicted, ms);
  CHECK(!vsh_auto_trial_timed(&t, V) && !vsh_auto_trial_timed(&t, R));
  CHECK(s.technique == V && s.time_frame == 1); /* volume was drawn already: no warm-up */
  s = vsh_auto_trial_next(&t, 0u, 7u, R, predicted);
  CHECK(s.technique == R && s.time_frame == 0);
  CHECK(!vsh_auto_trial_timed(&t, V));
}

static void test_degenerate(void)
{
  const double predicted[2] = {1.0, 1.0};
  vsh_auto_trial t;
  vsh_auto_trial_reset(&t);
  vsh_auto_trial_step s = vsh_auto_trial_next(NULL, 1u, 7u, V, predicted);
  CHECK(s.technique == V && s.time_frame == 0);
  s = vsh_auto_trial_next(&t, 1u, 7u, V, NULL);
  CHECK(s.technique == V && s.time_frame == 0);
  s = vsh_auto_trial_next(&t, 1u, 7u, 2, predicted);
  CHECK(s.technique == 2 && s.time_frame == 0);
  s = vsh_auto_trial_next(&t, 1u, 7u, -1, predicted);
  CHECK(s.technique == -1 && s.time_frame == 0);
  vsh_auto_trial_reset(NULL);
  /* Times that are no measurement are ignored. */
  const double bad[5] = {NAN, INFINITY, -INFINITY, 0.0, -3.0};
  for (int i = 0; i < 5; ++i) vsh_auto_trial_record(&t, V, bad[i]);
  vsh_auto_trial_record(&t, 2, 5.0);
  vsh_auto_trial_record(&t, -1, 5.0);
  vsh_auto_trial_record(NULL, V, 5.0);
  CHECK(t.samples[V] == 0 && t.samples[R] == 0 && isinf(t.ms[V]));
  CHECK(!vsh_auto_trial_timed(NULL, V) && !vsh_auto_trial_timed(&t, 5));
}

static vsh_auto_general_light exact_light(int pick, double volume_error, double ray_error)
{
  vsh_auto_general_light l = {0};
  l.candidates[VSH_AUTO_GENERAL_CSM] = (vsh_auto_candidate){1, 1.0, 5.0};
  l.candidates[VSH_AUTO_GENERAL_VOLUME] = (vsh_auto_candidate){1, volume_error, 100.0};
  l.candidates[VSH_AUTO_GENERAL_RAYTRACE] = (vsh_auto_candidate){1, ray_error, 110.0};
  l.pick = pick;
  l.met = 1;
  return l;
}

static void test_lights(void)
{
  const double target = 0.05;
  int model = -7;
  double predicted[2] = {-1.0, -1.0};
  vsh_auto_general_light lights[3] = {exact_light(VSH_AUTO_GENERAL_VOLUME, 0.0, 0.0),
                                      exact_light(VSH_AUTO_GENERAL_CSM, 0.0, 0.0),
                                      exact_light(VSH_AUTO_GENERAL_VOLUME, 0.01, 0.0)};
  const int index[3] = {0, 2, 5};
  CHECK(vsh_auto_trial_lights(lights, index, 3, target, &model, predicted) == (1u | 1u << 5));
  CHECK(model == V);
  CHECK_NEAR(predicted[V], 200.0, 1e-12);
  CHECK_NEAR(predicted[R], 220.0, 1e-12);
  vsh_auto_trial_apply(lights, index, 3, 1u | 1u << 5, R);
  CHECK(lights[0].pick == VSH_AUTO_GENERAL_RAYTRACE && lights[2].pick == VSH_AUTO_GENERAL_RAYTRACE);
  CHECK(lights[1].pick == VSH_AUTO_GENERAL_CSM);
  /* An exact light that can take only one technique: no trial at all
   * (one frame would otherwise mix volumes and rays). */
  model = -7;
  lights[2] = exact_light(VSH_AUTO_GENERAL_VOLUME, 0.0, 0.5);
  CHECK(vsh_auto_trial_lights(lights, index, 3, target, &model, predicted) == 0);
  CHECK(model == -7);
  lights[2] = exact_light(VSH_AUTO_GENERAL_RAYTRACE, 0.0, 0.0);
  lights[2].candidates[VSH_AUTO_GENERAL_VOLUME].available = 0;
  CHECK(vsh_auto_trial_lights(lights, index, 3, target, &model, predicted) == 0);
  lights[2] = exact_light(VSH_AUTO_GENERAL_RAYTRACE, 0.0, 0.0);
  lights[2].candidates[VSH_AUTO_GENERAL_VOLUME].cost = NAN;
  CHECK(vsh_auto_trial_lights(lights, index, 3, target, &model, predicted) == 0);
  /* Mixed picks, an index out of the mask's range, no exact light. */
  lights[0] = exact_light(VSH_AUTO_GENERAL_RAYTRACE, 0.0, 0.0);
  lights[2] = exact_light(VSH_AUTO_GENERAL_VOLUME, 0.0, 0.0);
  CHECK(vsh_auto_trial_lights(lights, index, 3, target, &model, predicted) == 0);
  lights[0] = exact_light(VSH_AUTO_GENERAL_VOLUME, 0.0, 0.0);
  const int out_of_range[3] = {0, 1, 32};
  CHECK(vsh_auto_trial_lights(lights, out_of_range, 3, target, &model, predicted) == 0);
  const vsh_auto_general_light maps[1] = {exact_light(VSH_AUTO_GENERAL_CSM, 0.0, 0.0)};
  CHECK(vsh_auto_trial_lights(maps, index, 1, target, &model, predicted) == 0);
  CHECK(vsh_auto_trial_lights(NULL, index, 3, target, &model, predicted) == 0);
  CHECK(vsh_auto_trial_lights(lights, NULL, 3, target, &model, predicted) == 0);
  CHECK(vsh_auto_trial_lights(lights, index, 0, target, &model, predicted) == 0);
  CHECK(vsh_auto_trial_lights(lights, index, 3, NAN, &model, predicted) == 0);
  CHECK(vsh_auto_trial_lights(lights, index, 3, target, NULL, predicted) == 0);
  vsh_auto_trial_apply(NULL, index, 3, 1u, R);
  vsh_auto_trial_apply(lights, index, 3, 1u, 7);
  CHECK(lights[0].pick == VSH_AUTO_GENERAL_VOLUME);
}

int main(void)
{
  test_timed_faster_wins();
  test_model_confirmed();
  test_median_and_hysteresis();
  test_not_worth_trying();
  test_expiry();
  test_lights_change();
  test_scene_edits();
  test_degenerate();
  test_lights();
  return vsh_check_report("core.auto_trial");
}
