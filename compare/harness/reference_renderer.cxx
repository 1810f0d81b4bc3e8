// reference_renderer.cxx - the cached-run driver shared by POV-Ray, Cycles
// and EEVEE.
#include "reference_renderer.h"

#include "harness_files.h"
#include "harness_progress.h"
#include "reference_cache.h"
#include "visibility_io.h"

#include <unistd.h>

namespace vsh_harness
{

namespace
{
// Part of every cache key: bump it when the meaning of a cached image changes.
const char* const kFormatVersion = "vtkshadow-compare reference format 1";
const char* const kUpdateReferences = "sh scripts/update-references.sh (docs/harness.md)";

struct DriverState
{
  const ReferenceRenderer& r;
  const Options& opt;
  const SceneEntry& e;
  const ExportScene& ex;
  SceneResult& res;
  std::string outdir;
  int lights = 0;

  // Records `msg` as this renderer's error of the scene and leaves no image.
  bool Fail(const std::string& msg)
  {
    res.errors.push_back(r.Name() + ": " + msg);
    RemoveLightFiles(outdir, lights);
    return false;
  }
};

// Writes light k's visibility and mask from its on/off renders; a tinted
// scene's green and blue visibility too (valid where the red channel is).
bool WriteLight(const DriverState& s, int k, const LightPair& p, std::string& err)
{
  std::vector<float> v, gb[2];
  std::vector<unsigned char> mask, unused;
  OnOff(p.on, p.off, p.eps, v, mask);
  if (!s.ex.tinted)
    return WriteVisibility(s.outdir, k, v, mask, s.ex.width, s.ex.height, err);
  const size_t n = p.on.size();
  if (p.on_g.size() != n || p.off_g.size() != n || p.on_b.size() != n || p.off_b.size() != n)
  {
    err = "light " + std::to_string(k) + ": no green and blue renders of a tinted scene";
    return false;
  }
  OnOff(p.on_g, p.off_g, p.eps, gb[0], unused);
  OnOff(p.on_b, p.off_b, p.eps, gb[1], unused);
  return WriteVisibility(s.outdir, k, v, mask, s.ex.width, s.ex.height, err, gb);
}

// Renders in a fresh work folder and writes the visibility of every light.
bool RenderFresh(DriverState& s, const std::string& exported)
{
  const std::string work = AbsPath(s.outdir + "/.work" + std::to_string(getpid()));
  std::string err;
  if (!MakeWorkDir(work, s.r.ExportFileName(), exported, err))
  {
    RemoveTree(work);
    return s.Fail("cannot write the exported scene in " + work + ": " + err);
  }
  const std::string log = AbsPath(s.outdir + "/" + s.r.LogName());
  unlink(log.c_str());
  RenderOutput out;
  RenderJob job{ s.e, s.ex, work, log };
  bool ok = s.r.Render(job, out, err);
  if (ok && out.lights.size() != static_cast<size_t>(s.lights))
  {
    ok = false;
    err =
      "rendered " + std::to_string(out.lights.size()) + " light(s) of " + std::to_string(s.lights);
  }
  for (int k = 0; ok && k < s.lights; ++k)
    ok = WriteLight(s, k, out.lights[k], err);
  if (!ok || !s.opt.keep_work)
    RemoveTree(work);
  if (!ok)
    return s.Fail(err);
  s.res.seconds[s.r.Name()] = out.seconds;
  if (out.frame_seconds >= 0)
    s.res.frame_seconds[s.r.Name()] = out.frame_seconds;
  return true;
}

// The shipped references of a scene: --references, else references/ beside
// its thresholds.json; "" when there are none to read.
std::string ShippedFolder(const Options& opt, const SceneEntry& e)
{
  if (opt.no_references || opt.no_cache)
    return "";
  if (!opt.references.empty())
    return opt.references;
  return e.thresholds.empty() ? "" : DirName(e.thresholds) + "/references";
}

enum class Shipped
{
  Used,   // the images are in the output folder
  Absent, // no entry: render (or fail, with --require-references)
  Failed  // the scene failed (message recorded)
};

// The shipped entry of `key`, read only: a damaged one fails the scene
// rather than being rendered over, since only the update script writes there.
Shipped LoadShipped(DriverState& s, const std::string& key)
{
  const std::string folder = ShippedFolder(s.opt, s.e);
  const std::string name = s.r.Name();
  const std::string entry = folder + "/" + name + "/" + key;
  std::string why;
  switch (folder.empty()
      ? CacheLoadResult::Miss
      : CacheLoad(entry, s.outdir, s.lights, s.ex.tinted, why, /*read_only=*/true))
  {
    case CacheLoadResult::Hit:
      Progress(s.e.id + ": " + name + " shipped reference " + key);
      s.res.cached[name] = true;
      return Shipped::Used;
    case CacheLoadResult::Failed:
      s.Fail("cannot copy the shipped reference: " + why);
      return Shipped::Failed;
    case CacheLoadResult::Corrupt:
      s.Fail("the shipped reference " + entry + " is damaged (" + why + "): render it again with " +
        kUpdateReferences);
      return Shipped::Failed;
    case CacheLoadResult::Miss:
      break;
  }
  if (!s.opt.require_references)
    return Shipped::Absent;
  s.Fail("no shipped reference " + name + "/" + key + " in " +
    (folder.empty() ? std::string("(no references folder)") : folder) +
    " (the scene, its meshes, the settings or the renderer differ from those it was rendered "
    "for): render it with " +
    kUpdateReferences);
  return Shipped::Failed;
}

} // namespace

bool RunReference(const ReferenceRenderer& r, const Options& opt, const SceneEntry& e,
  const ExportScene& ex, const std::string& content_key, SceneResult& res)
{
  const std::string name = r.Name();
  DriverState s{ r, opt, e, ex, res, opt.out + "/" + e.dir_id + "/" + name,
    static_cast<int>(ex.lights.size()) };
  std::string why;
  if (!MakeDirs(s.outdir, why))
    return s.Fail("cannot create " + s.outdir + ": " + why);
  RemoveLightFiles(s.outdir, s.lights);
  if (!r.GetUnusable().empty())
    return s.Fail(r.GetUnusable());
  const std::string exported = r.ExportBytes(ex);
  // A tinted scene's entries hold the green and blue channels too: a line of
  // its own, so the keys of every other scene stay what they were.
  const std::string keytext = std::string(kFormatVersion) + "\nrenderer " + r.GetVersion() + "\n" +
    r.KeySettings(ex) + content_key + "export " + MD5Hex(exported) + "\n" +
    (ex.tinted ? "channels red green blue\n" : "");
  const std::string key = MD5Hex(keytext);
  res.reference_keys[name] = key;
  const Shipped shipped = LoadShipped(s, key);
  if (shipped != Shipped::Absent)
    return shipped == Shipped::Used;
  const std::string cdir = opt.cache + "/" + name + "/" + key;
  if (!opt.no_cache)
    switch (CacheLoad(cdir, s.outdir, s.lights, ex.tinted, why))
    {
      case CacheLoadResult::Hit:
        Progress(e.id + ": " + name + " from cache " + key);
        res.cached[name] = true;
        return true;
      case CacheLoadResult::Failed:
        return s.Fail("cannot copy the cached images: " + why);
      case CacheLoadResult::Corrupt:
        Progress("WARNING " + e.id + ": " + name + " cache entry " + key + " is damaged (" + why +
          "); deleted, rendering again");
        break;
      case CacheLoadResult::Miss:
        break;
    }
  if (!RenderFresh(s, exported))
    return false;
  if (!CacheStore(cdir, s.outdir, s.lights, ex.tinted, keytext, why))
    Progress("WARNING " + e.id + ": " + name + " not cached: " + why);
  return true;
}

std::vector<std::unique_ptr<ReferenceRenderer>> MakeReferenceRenderers(const Options& opt)
{
  std::vector<std::unique_ptr<ReferenceRenderer>> r;
  if (opt.Has("povray"))
    r.push_back(MakePovrayRenderer(opt));
  if (opt.Has("cycles"))
    r.push_back(MakeCyclesRenderer(opt));
  for (const char* preset : { "eevee", "eevee-best" })
    if (opt.Has(preset))
      r.push_back(MakeEeveeRenderer(opt, preset));
  for (auto& x : r)
    x->Prepare();
  return r;
}

} // namespace vsh_harness
