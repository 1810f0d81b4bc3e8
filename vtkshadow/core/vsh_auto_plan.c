/* vsh_auto_plan.c - the rules that span lights (vsh_auto_plan.h). */
#include "vsh_auto_plan.h"

#include <stddef.h>

static int is_weighed(const int *weighed, int l) { return weighed == NULL || weighed[l] != 0; }

static int soft_picked(const vsh_auto_soft_choice *choices, const int *weighed, int count,
                       int technique) {
  for (int l = 0; l < count; ++l) {
    if (is_weighed(weighed, l) && choices[l].pick == technique) return 1;
  }
  return 0;
}

/* A soft choice picked again among its available candidates. */
static void soft_repick(vsh_auto_soft_choice *c, double penumbra_target) {
  vsh_auto_candidate weighed[VSH_AUTO_SOFT_COUNT];
  for (int i = 0; i < VSH_AUTO_SOFT_COUNT; ++i) {
    weighed[i].available = c->candidates[i].available;
    weighed[i].predicted_error_pct = c->candidates[i].pen_mae;
    weighed[i].cost = c->candidates[i].ms;
  }
  c->pick = vsh_auto_pick_cheapest(weighed, VSH_AUTO_SOFT_COUNT, penumbra_target, &c->met);
}

/* `technique` made unavailable to every weighed light; 1 when some light
 * had picked it (and picked again). */
static int soft_drop(vsh_auto_soft_choice *choices, const int *weighed, int count, int technique,
                     double penumbra_target) {
  int changed = 0;
  for (int l = 0; l < count; ++l) {
    if (!is_weighed(weighed, l)) continue;
    vsh_auto_soft_choice *c = &choices[l];
    c->candidates[technique].available = 0;
    if (c->pick == technique) {
      soft_repick(c, penumbra_target);
      changed = 1;
    }
  }
  return changed;
}

int vsh_auto_plan_soft(vsh_auto_soft_choice *choices, const int *weighed, int count,
                       double penumbra_target) {
  if (count > 0 && choices == NULL) return -1;
  int rounds = 0;
  for (;;) {
    const int pcss = soft_picked(choices, weighed, count, VSH_AUTO_SOFT_CSM_SAMPLED) &&
                     soft_drop(choices, weighed, count, VSH_AUTO_SOFT_PCSS, penumbra_target);
    const int volume = soft_picked(choices, weighed, count, VSH_AUTO_SOFT_VOLUME) &&
                       soft_picked(choices, weighed, count, VSH_AUTO_SOFT_RAYTRACE) &&
                       soft_drop(choices, weighed, count, VSH_AUTO_SOFT_VOLUME, penumbra_target);
    if (!pcss && !volume) return rounds;
    ++rounds;
  }
}

void vsh_auto_plan_soft_samples(const vsh_auto_soft_choice *choices, const int *weighed,
                                int count, int out_samples[VSH_AUTO_SOFT_COUNT]) {
  for (int t = 0; t < VSH_AUTO_SOFT_COUNT; ++t) out_samples[t] = 0;
  for (int l = 0; choices != NULL && l < count; ++l) {
    const int pick = choices[l].pick;
    if (!is_weighed(weighed, l) || pick < 0 || pick >= VSH_AUTO_SOFT_COUNT ||
        pick == VSH_AUTO_SOFT_PCSS) {
      continue;
    }
    const int samples = choices[l].candidates[pick].samples;
    out_samples[pick] = samples > out_samples[pick] ? samples : out_samples[pick];
  }
}

int vsh_auto_plan_general(vsh_auto_general_light *lights, int count, double max_error_pct,
                          int soft_volume, int soft_raytrace) {
  if (count > 0 && lights == NULL) return -1;
  int any_volume = soft_volume != 0, any_rays = soft_raytrace != 0;
  for (int l = 0; l < count; ++l) {
    vsh_auto_general_light *light = &lights[l];
    if (soft_volume) light->candidates[VSH_AUTO_GENERAL_RAYTRACE].available = 0;
    light->pick = vsh_auto_pick_cheapest(light->candidates, VSH_AUTO_GENERAL_COUNT,
                                         max_error_pct, &light->met);
    any_volume = any_volume || light->pick == VSH_AUTO_GENERAL_VOLUME;
    any_rays = any_rays || light->pick == VSH_AUTO_GENERAL_RAYTRACE;
  }
  if (!(any_volume && any_rays)) return 0;
  for (int l = 0; l < count; ++l) {
    vsh_auto_general_light *light = &lights[l];
    if (light->pick != VSH_AUTO_GENERAL_VOLUME) continue;
    light->candidates[VSH_AUTO_GENERAL_VOLUME].available = 0;
    light->pick = vsh_auto_pick_cheapest(light->candidates, VSH_AUTO_GENERAL_COUNT,
                                         max_error_pct, &light->met);
  }
  return 0;
}
