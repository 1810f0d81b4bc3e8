/* vsh_auto_plan.h - auto's policy across lights, as plain data.
 *
 * auto weighs each light's candidates with the cost and error models
 * (vsh_auto_soft for lights with a size, vsh_auto_general for the lights
 * the hard rules gave maps); these functions then apply the rules that
 * span lights, which exist because a pass takes one setting, or owns one
 * screen mask, for all the lights of a frame:
 *
 * - csm has one soft mode: when a light picks csm's sampled maps, PCSS is
 *   unavailable to every light;
 * - the volume and ray-traced passes each own a screen mask whose lighting
 *   hook declares the same names, so they cannot both serve one frame: when
 *   lights pick both, volume is dropped (raytrace is exact at any N);
 * - a dropped candidate is unavailable to every light, and the lights that
 *   had picked it choose again (vsh_auto_pick_cheapest): that can start the
 *   other clash, so the rules repeat until nothing changes;
 * - one sample count per pass: the largest any light that picked it needs.
 *
 * The VTK class gathers the inputs and applies the picks. */
#ifndef VSH_AUTO_PLAN_H
#define VSH_AUTO_PLAN_H

#include "vsh_auto_general.h"
#include "vsh_auto_soft.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The clash rules over the soft choices of `count` lights, in place
 * (choices[l].candidates[t].available cleared for dropped techniques,
 * .pick and .met redone for lights that had picked one). Lights whose
 * `weighed[l]` is 0 have no soft choice and are left alone (weighed may be
 * NULL: every light was weighed). Returns how many rounds changed
 * something, or -1 for bad input (NULL choices with count > 0). */
int vsh_auto_plan_soft(vsh_auto_soft_choice *choices, const int *weighed, int count,
                       double penumbra_target);

/* The sample count per soft technique (indexed by vsh_auto_soft_technique;
 * PCSS's is 0): the largest of the picks' samples among the weighed
 * lights, 0 where none picked it. */
void vsh_auto_plan_soft_samples(const vsh_auto_soft_choice *choices, const int *weighed,
                                int count, int out_samples[VSH_AUTO_SOFT_COUNT]);

/* One hard light's weighing: its candidates (vsh_auto_general indices) and
 * what it picks. */
typedef struct vsh_auto_general_light {
  vsh_auto_candidate candidates[VSH_AUTO_GENERAL_COUNT];
  int pick; /* out: a vsh_auto_general index, -1 when none is available */
  int met;  /* out: 1 when the pick's predicted error meets the target */
} vsh_auto_general_light;

/* Each light's cheapest candidate meeting max_error_pct, after the rules
 * with what the lights with a size took: raytrace is unavailable when they
 * took volumes (soft_volume), and when the frame would then have both
 * volumes and rays (soft or hard), the lights that picked volume pick
 * again without it. -1 for bad input, else 0. */
int vsh_auto_plan_general(vsh_auto_general_light *lights, int count, double max_error_pct,
                          int soft_volume, int soft_raytrace);

#ifdef __cplusplus
}
#endif

#endif
