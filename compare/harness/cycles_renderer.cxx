// cycles_renderer.cxx - Blender Cycles: the second ray tracer, the check of
// the POV-Ray reference itself (docs/harness.md, "Renderer settings").
#include "blender_renderer.h"

namespace vsh_harness
{

namespace
{
class CyclesRenderer : public BlenderRenderer
{
public:
  explicit CyclesRenderer(const Options& opt)
    : BlenderRenderer(opt, "cycles")
  {
  }

protected:
  std::string Settings() const override
  {
    return "cycles samples=" + std::to_string(this->Opt.cycles_samples) +
      " box filter, bounces 0, no denoise, EXR32 red channel, mask eps=1e-6*max";
  }
};
} // namespace

std::unique_ptr<ReferenceRenderer> MakeCyclesRenderer(const Options& opt)
{
  return std::unique_ptr<ReferenceRenderer>(new CyclesRenderer(opt));
}

} // namespace vsh_harness
