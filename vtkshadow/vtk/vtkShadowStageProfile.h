// vtkShadowStageProfile.h - where a frame's time goes, stage by stage.
//
// A diagnostic for issue 14's "where the time goes": with the profile on,
// every shadow pass marks the end of each of its stages (csm.maps,
// csm.resolve, planar.mask, volume.stencil, raytrace.trace, ..., and
// "scene" for the lit draw of the scene through the delegate). A mark
// finishes the GL work queued so far (glFinish) and books the wall time since
// the previous mark to its stage, so nested passes (auto's chain, a mirror's
// reflection pass) need no bookkeeping of their own: each stage gets the
// time between its own mark and the one before it.
//
// glFinish serializes the CPU and the GL (on llvmpipe, the rasterizer
// threads), so a profiled frame is slower than a timed one and its stages
// add up to its own total, not to the interleaved timing's median. Use the
// stages for proportions and for what changes between techniques; use the
// interleaved timing (vtkshadow-render --stats) for ratios. Off by default;
// a mark costs one branch then.
//
// Each stage has two times: wall clock, and the process's CPU time (every
// thread, so llvmpipe's rasterizer threads count). On a machine shared with
// other work the CPU time is the steadier of the two: it does not grow while
// the process waits for a core.
#ifndef vtkShadowStageProfile_h
#define vtkShadowStageProfile_h

#include "vtkshadowModule.h" // for export macro

#include <string>
#include <utility>
#include <vector>

namespace vtkshadow
{
/** Switch the profile on or off (process-wide; off by default). */
VTKSHADOW_EXPORT void SetStageProfiling(bool on);
VTKSHADOW_EXPORT bool GetStageProfiling();

/**
 * Start a profiled frame: finish the GL work queued before it, forget the
 * previous frame's stages and start the clock. Call with a current context.
 */
VTKSHADOW_EXPORT void BeginStageFrame();

/**
 * Book the time since the previous mark (or BeginStageFrame) to `stage`,
 * after finishing the GL work queued so far. Nothing when profiling is off.
 * A stage marked twice in a frame adds up.
 */
VTKSHADOW_EXPORT void MarkStage(const char* stage);

/**
 * The stages of the current frame in the order they were first marked,
 * milliseconds each: wall clock, or the process's CPU time.
 */
VTKSHADOW_EXPORT std::vector<std::pair<std::string, double>> GetStageTimes();
VTKSHADOW_EXPORT std::vector<std::pair<std::string, double>> GetStageCPUTimes();
}

#endif
