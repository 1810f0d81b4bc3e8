// blender_renderer.h - what Cycles and EEVEE share: Blender 3.4 running the
// one fixed script compare/blender/render_cycles.py on the binary export
// (scene.bin), told the preset by a fixed word. The subclasses differ in
// the preset and in the settings line of their cache key.
#ifndef VTKSHADOW_BLENDER_RENDERER_H
#define VTKSHADOW_BLENDER_RENDERER_H

#include "reference_renderer.h"

namespace vsh_harness
{

class BlenderRenderer : public ReferenceRenderer
{
public:
  BlenderRenderer(const Options& opt, const std::string& preset)
    : ReferenceRenderer(opt)
    , Preset(preset)
  {
  }

  std::string Name() const override { return this->Preset; }
  std::string ExportFileName() const override { return "scene.bin"; }
  std::string LogName() const override { return "blender.log"; }
  void Prepare() override;
  std::string ExportBytes(const ExportScene& ex) const override;
  // The preset's settings line and the script's MD5 (which covers every
  // preset value written there).
  std::string KeySettings(const ExportScene& ex) const override;
  bool Render(const RenderJob& job, RenderOutput& out, std::string& err) const override;

protected:
  // One line describing the preset's settings (cache key, docs).
  virtual std::string Settings() const = 0;

private:
  bool ReadLight(const RenderJob& job, int k, LightPair& p, std::string& err) const;

  std::string Preset;
  std::string ScriptBytes;
};

} // namespace vsh_harness

#endif
