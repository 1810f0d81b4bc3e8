/* test_auto_plan.c - unit tests of vsh_auto_plan: the rules across lights
 * (PCSS dropped when a light takes csm's sampled maps; volume dropped when
 * lights take both volume and raytrace; chains of both; lights not weighed
 * left alone), one sample count per pass, the hard lights' picks with what
 * the soft lights took, and bad input. */
#include "vsh_check.h"
#include "vsh_auto_plan.h"

#include <stddef.h>
#include <string.h>

/* A soft choice with the given candidates (available, samples, pen_mae,
 * ms per technique), picked as vsh_auto_soft_choose would. */
static vsh_auto_soft_choice soft(const double spec[VSH_AUTO_SOFT_COUNT][4], double target) {
  vsh_auto_soft_choice c;
  memset(&c, 0, sizeof c);
  vsh_auto_candidate w[VSH_AUTO_SOFT_COUNT];
  for (int t = 0; t < VSH_AUTO_SOFT_COUNT; ++t) {
    c.candidates[t].available = (int)spec[t][0];
    c.candidates[t].samples = (int)spec[t][1];
    c.candidates[t].pen_mae = spec[t][2];
    c.candidates[t].ms = spec[t][3];
    w[t].available = c.candidates[t].available;
    w[t].predicted_error_pct = spec[t][2];
    w[t].cost = spec[t][3];
  }
  c.pick = vsh_auto_pick_cheapest(w, VSH_AUTO_SOFT_COUNT, target, &c.met);
  return c;
}

/* Candidates in vsh_auto_soft_technique order: planar, pcss, raytrace,
 * volume, csm_sampled; each {available, samples, pen_mae, ms}. */
static const double wants_sampled[VSH_AUTO_SOFT_COUNT][4] = {
    {0, 0, 0, 0}, {1, 1, 0.05, 5}, {1, 64, 0.01, 40}, {1, 32, 0.01, 30}, {1, 16, 0.01, 8}};
static const double wants_pcss[VSH_AUTO_SOFT_COUNT][4] = {
    {0, 0, 0, 0}, {1, 1, 0.01, 5}, {1, 64, 0.01, 40}, {1, 32, 0.01, 30}, {1, 8, 0.01, 9}};
static const double wants_volume[VSH_AUTO_SOFT_COUNT][4] = {
    {0, 0, 0, 0}, {1, 1, 0.05, 5}, {1, 64, 0.01, 40}, {1, 32, 0.01, 20}, {1, 16, 0.01, 25}};
static const double wants_rays[VSH_AUTO_SOFT_COUNT][4] = {
    {0, 0, 0, 0}, {1, 1, 0.05, 5}, {1, 128, 0.01, 10}, {1, 32, 0.01, 30}, {0, 0, 0, 0}};

static void test_pcss_dropped(void) {
  const double target = 0.02;
  vsh_auto_soft_choice c[2] = {soft(wants_sampled, target), soft(wants_pcss, target)};
  CHECK(c[0].pick == VSH_AUTO_SOFT_CSM_SAMPLED && c[1].pick == VSH_AUTO_SOFT_PCSS);
  CHECK(vsh_auto_plan_soft(c, NULL, 2, target) == 1);
  CHECK(c[0].pick == VSH_AUTO_SOFT_CSM_SAMPLED);
  /* Light 1 chooses again: csm's sampled maps (9 ms) are the next cheapest. */
  CHECK(c[1].pick == VSH_AUTO_SOFT_CSM_SAMPLED && c[1].met == 1);
  CHECK(c[1].candidates[VSH_AUTO_SOFT_PCSS].available == 0);
  int samples[VSH_AUTO_SOFT_COUNT];
  vsh_auto_plan_soft_samples(c, NULL, 2, samples);
  CHECK(samples[VSH_AUTO_SOFT_CSM_SAMPLED] == 16 && samples[VSH_AUTO_SOFT_PCSS] == 0);
}

static void test_volume_dropped_then_pcss(void) {
  /* Light 0 wants volume, light 1 rays: volume goes; light 0 then takes
   * csm's sampled maps, which drops PCSS for light 2 in the next round. */
  const double target = 0.02;
  vsh_auto_soft_choice c[3] = {soft(wants_volume, target), soft(wants_rays, target),
                               soft(wants_pcss, target)};
  CHECK(c[0].pick == VSH_AUTO_SOFT_VOLUME && c[1].pick == VSH_AUTO_SOFT_RAYTRACE &&
        c[2].pick == VSH_AUTO_SOFT_PCSS);
  CHECK(vsh_auto_plan_soft(c, NULL, 3, target) == 2);
  CHECK(c[0].pick == VSH_AUTO_SOFT_CSM_SAMPLED);
  CHECK(c[1].pick == VSH_AUTO_SOFT_RAYTRACE);
  CHECK(c[2].pick == VSH_AUTO_SOFT_CSM_SAMPLED);
  int samples[VSH_AUTO_SOFT_COUNT];
  vsh_auto_plan_soft_samples(c, NULL, 3, samples);
  CHECK(samples[VSH_AUTO_SOFT_RAYTRACE] == 128);
  CHECK(samples[VSH_AUTO_SOFT_CSM_SAMPLED] == 16); /* the larger of 16 and 8 */
  CHECK(samples[VSH_AUTO_SOFT_VOLUME] == 0);
}

static void test_not_weighed_left_alone(void) {
  const double target = 0.02;
  vsh_auto_soft_choice c[2] = {soft(wants_sampled, target), soft(wants_pcss, target)};
  const int weighed[2] = {1, 0};
  CHECK(vsh_auto_plan_soft(c, weighed, 2, target) == 0);
  CHECK(c[1].pick == VSH_AUTO_SOFT_PCSS && c[1].candidates[VSH_AUTO_SOFT_PCSS].available);
  int samples[VSH_AUTO_SOFT_COUNT];
  vsh_auto_plan_soft_samples(c, weighed, 2, samples);
  CHECK(samples[VSH_AUTO_SOFT_CSM_SAMPLED] == 16);
}

static vsh_auto_general_light hard(double csm_error, double csm_ms, double volume_ms,
                                   double ray_ms) {
  vsh_auto_general_light l;
  memset(&l, 0, sizeof l);
  l.candidates[VSH_AUTO_GENERAL_CSM] = (vsh_auto_candidate){1, csm_error, csm_ms};
  l.candidates[VSH_AUTO_GENERAL_VOLUME] = (vsh_auto_candidate){1, 0.0, volume_ms};
  l.candidates[VSH_AUTO_GENERAL_RAYTRACE] = (vsh_auto_candidate){1, 0.0, ray_ms};
  return l;
}

static void test_general(void) {
  /* Maps meet the target: csm. */
  vsh_auto_general_light a[1] = {hard(0.1, 5, 20, 30)};
  CHECK(vsh_auto_plan_general(a, 1, 0.5, 0, 0) == 0 && a[0].pick == VSH_AUTO_GENERAL_CSM);
  /* Maps lose a thin part: the cheaper exact one, here volume; a second
   * light picks rays: the volume light picks again, rays. */
  vsh_auto_general_light b[2] = {hard(3.0, 5, 20, 30), hard(3.0, 5, 40, 25)};
  CHECK(vsh_auto_plan_general(b, 2, 0.5, 0, 0) == 0);
  CHECK(b[0].pick == VSH_AUTO_GENERAL_RAYTRACE && b[1].pick == VSH_AUTO_GENERAL_RAYTRACE);
  CHECK(b[0].candidates[VSH_AUTO_GENERAL_VOLUME].available == 0);
  /* Soft lights took volumes: no rays this frame; volume stays. */
  vsh_auto_general_light c[1] = {hard(3.0, 5, 40, 25)};
  CHECK(vsh_auto_plan_general(c, 1, 0.5, 1, 0) == 0 && c[0].pick == VSH_AUTO_GENERAL_VOLUME);
  /* Soft lights took rays: a light that wants volume takes rays. */
  vsh_auto_general_light d[1] = {hard(3.0, 5, 20, 30)};
  CHECK(vsh_auto_plan_general(d, 1, 0.5, 0, 1) == 0 && d[0].pick == VSH_AUTO_GENERAL_RAYTRACE);
  /* Both unavailable after the rules: the lowest error left, csm, not met. */
  vsh_auto_general_light e[1] = {hard(3.0, 5, 20, 30)};
  e[0].candidates[VSH_AUTO_GENERAL_RAYTRACE].available = 0;
  CHECK(vsh_auto_plan_general(e, 1, 0.5, 0, 1) == 0);
  CHECK(e[0].pick == VSH_AUTO_GENERAL_CSM && e[0].met == 0);
}

static void test_bad_input(void) {
  CHECK(vsh_auto_plan_soft(NULL, NULL, 2, 0.02) == -1);
  CHECK(vsh_auto_plan_soft(NULL, NULL, 0, 0.02) == 0);
  CHECK(vsh_auto_plan_general(NULL, 1, 0.5, 0, 0) == -1);
  CHECK(vsh_auto_plan_general(NULL, 0, 0.5, 0, 0) == 0);
  int samples[VSH_AUTO_SOFT_COUNT] = {7, 7, 7, 7, 7};
  vsh_auto_plan_soft_samples(NULL, NULL, 3, samples);
  CHECK(samples[0] == 0 && samples[4] == 0);
}

int main(void) {
  test_pcss_dropped();
  test_volume_dropped_then_pcss();
  test_not_weighed_left_alone();
  test_general();
  test_bad_input();
  return vsh_check_report("test_auto_plan");
}
