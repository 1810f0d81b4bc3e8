// reference_renderer.h - one interface for every renderer that renders the
// exported scene itself (POV-Ray, Cycles, EEVEE), and the one driver that
// runs any of them with the cache (docs/harness.md).
//
// A renderer says what it is (name, version, cache-key settings), turns the
// exported scene into its input file, and renders the shadows-on/off pair
// of every light into linear intensities. Everything else is the driver's
// and identical for all: output folder, removal of old images, cache key,
// cache lookup and store, work folder, visibility = on/off, mask, writing,
// clean-up after a failure.
#ifndef VTKSHADOW_REFERENCE_RENDERER_H
#define VTKSHADOW_REFERENCE_RENDERER_H

#include "compare_options.h"
#include "harness_export.h"
#include "harness_results.h"

#include <memory>
#include <string>
#include <vector>

namespace vsh_harness
{

// One light's renders: intensities with shadows on and off (width * height,
// row 0 on top), and the threshold of off above which a pixel is valid.
// on and off are the red channel; a tinted scene's renders also give the
// green and blue ones (the valid mask is the red channel's).
struct LightPair
{
  std::vector<float> on, off;
  std::vector<float> on_g, off_g, on_b, off_b; // tinted scenes only
  double eps = 0;
};

struct RenderOutput
{
  std::vector<LightPair> lights; // one per light of the scene
  double seconds = 0;            // wall time of the renderer's processes
  double frame_seconds = -1;     // mean per frame, when the renderer measures it
};

// What Render() gets: the scene, its export (already written as
// work/ExportFileName()), a work folder and the log file to append to.
struct RenderJob
{
  const SceneEntry& entry;
  const ExportScene& ex;
  std::string work;
  std::string log;
};

class ReferenceRenderer
{
public:
  explicit ReferenceRenderer(const Options& opt)
    : Opt(opt)
  {
  }
  virtual ~ReferenceRenderer() = default;

  // Output folder, cache folder and result rows are named by this.
  virtual std::string Name() const = 0;
  // Probes the program once per run: sets Version (part of every cache
  // key) or Unusable (why it cannot run: every scene then fails with it).
  virtual void Prepare() = 0;
  // File name of the exported scene in the work folder, and its bytes.
  virtual std::string ExportFileName() const = 0;
  virtual std::string ExportBytes(const ExportScene& ex) const = 0;
  // The settings lines of the cache key (each ending in '\n').
  virtual std::string KeySettings(const ExportScene& ex) const = 0;
  virtual std::string LogName() const = 0;
  // Renders every light; false with `err` set on any failure. Must be safe
  // to call from several threads at once (scenes in parallel).
  virtual bool Render(const RenderJob& job, RenderOutput& out, std::string& err) const = 0;

  const std::string& GetVersion() const { return this->Version; }
  const std::string& GetUnusable() const { return this->Unusable; }

protected:
  const Options& Opt;
  std::string Version;
  std::string Unusable;
};

// The renderers of --renderers that render the export (POV-Ray first: it is
// the reference of every row), each prepared.
std::vector<std::unique_ptr<ReferenceRenderer>> MakeReferenceRenderers(const Options& opt);

std::unique_ptr<ReferenceRenderer> MakePovrayRenderer(const Options& opt);
std::unique_ptr<ReferenceRenderer> MakeCyclesRenderer(const Options& opt);
// preset: "eevee" (Blender's defaults) or "eevee-best".
std::unique_ptr<ReferenceRenderer> MakeEeveeRenderer(const Options& opt, const std::string& preset);

// The one cached-run driver: the renderer's visibility and mask of every
// light end up in OUT/<scene>/<name>/, from the cache or rendered (and then
// stored). False after a failure: the reason is in res.errors and no image
// of this renderer is left for the scene.
bool RunReference(const ReferenceRenderer& r, const Options& opt, const SceneEntry& e,
  const ExportScene& ex, const std::string& content_key, SceneResult& res);

} // namespace vsh_harness

#endif
