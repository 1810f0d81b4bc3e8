#include "vtkShadowRankReduction.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <algorithm>

namespace vtkshadow
{
//------------------------------------------------------------------------------
bool IsParallel(vtkMultiProcessController* controller)
{
  return controller && controller->GetNumberOfProcesses() > 1;
}

//------------------------------------------------------------------------------
void AllReduceBounds(vtkMultiProcessController* controller, vsh_bounds* bounds)
{
  if (!IsParallel(controller))
  {
    return;
  }
  // One MIN reduction: the maxima negated. Empty bounds (min > max, from
  // vsh_bounds_init_empty) are +huge/-huge and so neutral.
  double mine[6], all[6];
  for (int i = 0; i < 3; ++i)
  {
    mine[i] = bounds->min[i];
    mine[3 + i] = -bounds->max[i];
  }
  controller->AllReduce(mine, all, 6, vtkCommunicator::MIN_OP);
  for (int i = 0; i < 3; ++i)
  {
    bounds->min[i] = all[i];
    bounds->max[i] = -all[3 + i];
  }
}

//------------------------------------------------------------------------------
void AllReduceMax(vtkMultiProcessController* controller, unsigned long long* value)
{
  if (IsParallel(controller))
  {
    unsigned long long all = 0;
    controller->AllReduce(value, &all, 1, vtkCommunicator::MAX_OP);
    *value = all;
  }
}

//------------------------------------------------------------------------------
void AllReduceSum(vtkMultiProcessController* controller, int* value)
{
  if (IsParallel(controller))
  {
    int all = 0;
    controller->AllReduce(value, &all, 1, vtkCommunicator::SUM_OP);
    *value = all;
  }
}

//------------------------------------------------------------------------------
void AllReduceDepthRegion(vtkMultiProcessController* controller, vtkTextureObject* depth, int x,
  int y, int width, int height, std::vector<float>& scratch)
{
  if (!IsParallel(controller) || width <= 0 || height <= 0)
  {
    return;
  }
  const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
  scratch.resize(2 * n);
  float* mine = scratch.data();
  float* all = mine + n;
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glReadPixels(x, y, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, mine);
  controller->AllReduce(mine, all, static_cast<vtkIdType>(n), vtkCommunicator::MIN_OP);
  depth->Bind();
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glTexSubImage2D(GL_TEXTURE_2D, 0, x, y, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, all);
}
}
