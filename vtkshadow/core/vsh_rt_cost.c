/* vsh_rt_cost.c - the cost of a frame of ray-traced shadows, from rays per
 * second measured on the machine (vsh_raytrace.h). */
#include "vsh_raytrace.h"
#include "vsh_rt_adaptive.h"

#include <math.h>

void vsh_rt_cost_model_default(vsh_rt_cost_model *model)
{
  /* Measured by bench/bench_growth.py and the library bench of
   * scripts/results.sh on an otherwise idle 2-core VM (Embree 3.13, 10k to
   * 1M triangles): 4.5 to 9.1 M occlusion rays per second per thread; the
   * low end, so that auto does not promise raytrace too cheaply, and not a
   * rate measured under load (2e6 makes raytrace 1.7x too dear on
   * arrow-glyphs). The pass refines it from every frame it traces. */
  model->rays_per_second_per_thread = 4.5e6;
  model->pixel_ns = 60.0;
  model->frame_ms = 1.0;
}

void vsh_rt_cost_model_observe(vsh_rt_cost_model *model, double rays, double seconds,
                               int threads)
{
  if (!(rays > 0.0) || !(seconds > 0.0) || threads < 1 || !isfinite(rays) ||
      !isfinite(seconds)) {
    return;
  }
  const double rate = rays / seconds / threads;
  model->rays_per_second_per_thread = 0.75 * model->rays_per_second_per_thread + 0.25 * rate;
}

static double clamp01(double v)
{
  return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
}

double vsh_rt_cost_rays(const vsh_rt_cost_input *input)
{
  const double pixels = input->pixels > 0.0 ? input->pixels : 0.0;
  const double lights = input->lights > 0 ? input->lights : 0;
  /* Only a penumbra pixel pays for all samples under adaptive counts. */
  const double samples =
    input->samples > 0 ? vsh_rt_adaptive_expected_rays(input->samples, input->first, input->penumbra)
                       : 0;
  if (lights == 0.0) {
    return 0.0;
  }
  const double traced = input->traced > 0.0 ? clamp01(input->traced) : 1.0;
  return clamp01(input->coverage) * traced * pixels * (1.0 + lights * samples);
}

double vsh_rt_cost_ms(const vsh_rt_cost_model *model, const vsh_rt_cost_input *input)
{
  const double rays = vsh_rt_cost_rays(input);
  if (rays == 0.0) {
    return 0.0;
  }
  const int threads = input->threads > 1 ? input->threads : 1;
  const double rate = model->rays_per_second_per_thread > 0.0
                          ? model->rays_per_second_per_thread * threads
                          : 1.0;
  const double pixels = input->pixels > 0.0 ? input->pixels : 0.0;
  return model->frame_ms + 1e-6 * model->pixel_ns * pixels + 1e3 * rays / rate;
}
