/* vsh_auto_trial.h - which exact technique draws auto's exact lights:
 * chosen by frames timed on this machine, not by the cost models alone.
 * Plain data, no GL: the pass times the frames and reports them here.
 *
 * Shadow volumes and ray tracing are both exact, so where every light auto
 * gives an exact technique could take either (both available, both
 * predicted within the error target), they draw the same image and only
 * their cost tells them apart. The cost models (vsh_volume_cost.h,
 * vsh_raytrace.h) are fitted on one machine and a set of scenes; on
 * another machine or scene they can rank the two wrongly (scivis/isosurface
 * at 800x600 on a 2.4x slower CPU: volumes predicted at 208 ms a frame for
 * both lights against rays' 221-266, and measured at 254-307 against
 * 184-196). So auto times each for a few frames and keeps the faster:
 *
 *   1. the technique drawn (the models' pick at first) is timed on
 *      VSH_AUTO_TRIAL_SAMPLES frames, after VSH_AUTO_TRIAL_WARMUP untimed
 *      ones: the first frame after a switch builds (a BVH, volumes, the
 *      classifier's maps), and the ray tracer's next two were still 1.2x
 *      its later frames on isosurface (189, 184, then 145-161 ms) while
 *      its classifier's block and pixel yields settle;
 *   2. then the other, the same way, unless the models predict it more
 *      than VSH_AUTO_TRIAL_MAX_PREDICTED_RATIO times dearer (a trial of a
 *      technique that cannot win costs frames for nothing);
 *   3. the faster timing wins; the one drawn before the trial (the
 *      incumbent) gives way only to one under VSH_AUTO_TRIAL_SWITCH_RATIO
 *      of its time (noise does not flip it);
 *   4. timings are per set of exact lights and expire together after
 *      VSH_AUTO_TRIAL_MAX_AGE frames (the camera moves, the cost with it),
 *      or once the scene (a key of the casters' meshes and placements and
 *      the lights) has changed since they were taken and then held still
 *      for VSH_AUTO_TRIAL_SETTLE frames: then the trial runs again. A scene
 *      edited every frame (an animation) keeps its timings until they
 *      expire rather than timing again on every edit.
 * A timing is the median of its frames: one frame slowed by load on a
 * shared machine, or sped up by work it skipped, does not decide. */
#ifndef VSH_AUTO_TRIAL_H
#define VSH_AUTO_TRIAL_H

#include "vsh_auto_plan.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The two exact techniques. */
enum { VSH_AUTO_TRIAL_VOLUME = 0, VSH_AUTO_TRIAL_RAYTRACE = 1, VSH_AUTO_TRIAL_COUNT = 2 };

#define VSH_AUTO_TRIAL_WARMUP 3   /* untimed frames after a switch */
#define VSH_AUTO_TRIAL_SAMPLES 3  /* timed frames per technique */
#define VSH_AUTO_TRIAL_MAX_AGE 300 /* frames a pair of timings stays valid */
#define VSH_AUTO_TRIAL_SETTLE 30   /* still frames after an edit before timing again */

/* The other technique is left untried when predicted dearer than this
 * times the drawn one's prediction. */
extern const double VSH_AUTO_TRIAL_MAX_PREDICTED_RATIO;
/* The incumbent gives way only to one timed under this times its own
 * timing. */
extern const double VSH_AUTO_TRIAL_SWITCH_RATIO;

typedef struct vsh_auto_trial {
  long long frame;                 /* frames stepped */
  unsigned int lights;             /* the exact lights (bit per light) the timings are for */
  int drawn;                       /* the technique of the last step, -1 none */
  int run;                         /* consecutive steps drawn with it */
  double ms[VSH_AUTO_TRIAL_COUNT]; /* the timing (median of the samples), +inf until timed */
  double times[VSH_AUTO_TRIAL_COUNT][VSH_AUTO_TRIAL_SAMPLES]; /* the timed frames, ms */
  int samples[VSH_AUTO_TRIAL_COUNT]; /* timed frames so far */
  long long started;               /* frame of the pair's first timing */
  int tried_other;                 /* 1 once the current pair's second technique was weighed */
  int incumbent;                   /* the technique drawn when the pair's timing began, -1 none */
  unsigned long long scene;        /* the last step's scene key */
  long long changed;               /* frame the scene key last changed */
} vsh_auto_trial;

/* One frame's decision: the technique that draws the exact lights, and
 * whether to time the frame (then report it with vsh_auto_trial_record). */
typedef struct vsh_auto_trial_step {
  int technique;
  int time_frame;
} vsh_auto_trial_step;

/* Nothing timed, nothing drawn. */
void vsh_auto_trial_reset(vsh_auto_trial *trial);

/* The frame's step. `lights`: the exact lights that could take either
 * technique (0 when some exact light can take only one, or there is none:
 * then the models decide, `model` is returned untimed, and the timings are
 * dropped). `scene`: a key of what the cost depends on besides the camera
 * (any value; a new one is an edit). `model`: the models' pick
 * (VSH_AUTO_TRIAL_*); `predicted`: the models' ms for both over those
 * lights. A NULL trial or predicted, or a model outside the two, gives
 * {model, 0}. NaN or negative predictions count as +inf (never tried
 * unless drawn). */
vsh_auto_trial_step vsh_auto_trial_next(vsh_auto_trial *trial, unsigned int lights,
                                        unsigned long long scene, int model,
                                        const double predicted[VSH_AUTO_TRIAL_COUNT]);

/* The time of a frame the last step asked to time, drawn with `technique`.
 * Ignored for a technique outside the two, a NULL trial, and a NaN,
 * infinite or non-positive ms (a clock that did not run). */
void vsh_auto_trial_record(vsh_auto_trial *trial, int technique, double ms);

/* The exact lights that could take either technique, from lights weighed
 * by vsh_auto_plan_general: bit index[i] for each light whose pick is
 * volume or raytrace when every such light has both candidates available
 * and predicted within max_error_pct. 0 when some exact pick cannot take
 * both, the picks mix volume and raytrace, an index is outside 0..31, or no
 * light is exact. *model gets the picks' technique (VSH_AUTO_TRIAL_*) and
 * predicted[] both candidates' costs summed over those lights (both
 * untouched when 0 is returned). */
unsigned int vsh_auto_trial_lights(const vsh_auto_general_light *lights, const int *index,
                                   int count, double max_error_pct, int *model,
                                   double predicted[VSH_AUTO_TRIAL_COUNT]);

/* Each light whose bit index[i] is in `mask` picks `technique`. */
void vsh_auto_trial_apply(vsh_auto_general_light *lights, const int *index, int count,
                          unsigned int mask, int technique);

/* 1 when technique's timing is complete (VSH_AUTO_TRIAL_SAMPLES frames). */
int vsh_auto_trial_timed(const vsh_auto_trial *trial, int technique);

#ifdef __cplusplus
}
#endif
#endif
