/**
 * Reductions over the MPI ranks that draw one image (ParaView's pvbatch or
 * pvserver, sort-last compositing): what a shadow pass needs so that every
 * rank builds the same light matrices and the same maps. Each function is a
 * collective: every rank must call it, in the same order, or they deadlock.
 * With a null controller or one process every function does nothing.
 */
#ifndef vtkShadowRankReduction_h
#define vtkShadowRankReduction_h

#include "vsh_bounds.h"

#include <vector> // for std::vector

class vtkMultiProcessController;
class vtkTextureObject;

namespace vtkshadow
{
/// True when `controller` joins more than one process.
bool IsParallel(vtkMultiProcessController* controller);

/// Bounds of all ranks (empty bounds on a rank leave the others unchanged).
void AllReduceBounds(vtkMultiProcessController* controller, vsh_bounds* bounds);

/// The largest value over the ranks.
void AllReduceMax(vtkMultiProcessController* controller, unsigned long long* value);

/// The sum over the ranks.
void AllReduceSum(vtkMultiProcessController* controller, int* value);

/**
 * Min-reduce a region of a depth map: read it from the bound framebuffer's
 * depth attachment, keep the nearest depth of every rank, write it back to
 * `depth` (the attached texture). `scratch` keeps its memory between calls.
 */
void AllReduceDepthRegion(vtkMultiProcessController* controller, vtkTextureObject* depth, int x,
  int y, int width, int height, std::vector<float>& scratch);
}

#endif
