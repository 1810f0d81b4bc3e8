// eevee_renderer.cxx - Blender EEVEE, a rasterizer measured as a peer of the
// VTK techniques; two presets, "eevee" (Blender's defaults) and
// "eevee-best" (docs/harness.md, "EEVEE as a peer"). The preset values are
// in compare/blender/render_cycles.py, whose MD5 is part of the cache key.
#include "blender_renderer.h"

namespace vsh_harness
{

namespace
{
class EeveeRenderer : public BlenderRenderer
{
public:
  using BlenderRenderer::BlenderRenderer;

protected:
  std::string Settings() const override
  {
    return "preset " + this->Name() +
      ", filter_size 0, fitted clip and light cutoff, EXR32 red channel, mask eps=1e-6*max";
  }
};
} // namespace

std::unique_ptr<ReferenceRenderer> MakeEeveeRenderer(const Options& opt, const std::string& preset)
{
  return std::unique_ptr<ReferenceRenderer>(new EeveeRenderer(opt, preset));
}

} // namespace vsh_harness
