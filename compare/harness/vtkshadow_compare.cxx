// vtkshadow-compare: render scenes with VTK techniques, POV-Ray, Blender
// Cycles and (on request) Blender EEVEE, extract per-light visibility from each, compute the metrics (C,
// compare/metrics) and write results.csv, results.json and index.html.
// See docs/harness.md.
#include "harness_export.h"
#include "harness_util.h"

#include "vtkShadowScene.h"
#include "vtkShadowTechnique.h"
#include "vsh_metrics.h"
#include "vsh_png.h"
#include "vsh_scene.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <cjson/cJSON.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

using namespace vsh_harness;

namespace
{
const char* const kFormatVersion = "vtkshadow-compare reference format 1";

const char* Usage()
{
  return "usage: vtkshadow-compare SCENE|DIR... --out DIR [options]\n"
         "  --renderers LIST      any of vtk,povray,cycles,eevee,eevee-best\n"
         "                        (default vtk,povray,cycles)\n"
         "  --techniques LIST     VTK techniques (default: all that vtkshadow knows)\n"
         "  --scale F             image size = scene size * F (default 1)\n"
         "  --check               compare with thresholds.json; exit 3 on a regression\n"
         "  --thresholds FILE     thresholds file (default: thresholds.json in the\n"
         "                        nearest folder above each scene)\n"
         "  --jobs N              scenes rendered in parallel (default 1)\n"
         "  --threads N           threads per ray-tracer render (default: cores / jobs)\n"
         "  --timeout S           per-render time limit in seconds (default 600)\n"
         "  --cache DIR           reference cache (default OUT/cache)\n"
         "  --no-cache            always render POV-Ray, Cycles and EEVEE fresh (no cache read)\n"
         "  --cycles-samples N    Cycles samples per pixel (default 1, pixel centre)\n"
         "  --povray-binary P     (default povray)\n"
         "  --blender-binary P    (default blender)\n"
         "  --render-binary P     vtkshadow-render (default: next to this program)\n"
         "  --cycles-script P     Blender script of Cycles and EEVEE\n"
         "                        (default: compare/blender/render_cycles.py of the source)\n"
         "  --no-report           skip index.html and the plot\n"
         "  --keep-work           keep the exported scene.pov / scene.bin (debugging, tests)\n"
         "Exit status: 0 all good, 1 a render or metric failed (other scenes go on),\n"
         "2 bad usage, 3 --check found a regression.\n";
}

struct Options
{
  std::vector<std::string> inputs;
  std::string out;
  std::vector<std::string> renderers{ "vtk", "povray", "cycles" };
  std::vector<std::string> techniques; // default: every known technique
  double scale = 1.0;
  bool check = false;
  std::string thresholds;
  int jobs = 1;
  int threads = 0;
  double timeout = 600;
  std::string cache;
  bool no_cache = false;
  int cycles_samples = 1;
  std::string povray = "povray";
  std::string blender = "blender";
  std::string render_bin;
  std::string cycles_script;
  bool report = true;
  bool keep_work = false;
};

std::vector<std::string> Split(const std::string& s)
{
  std::vector<std::string> r;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty())
      r.push_back(item);
  return r;
}

// Every renderer --renderers accepts. The Blender ones share one script,
// told which preset to use (render_cycles.py PRESETS); each has its own
// output folder, cache folder, rows and seconds under its name.
const char* const kRenderers[] = { "vtk", "povray", "cycles", "eevee", "eevee-best" };
const char* const kBlenderRenderers[] = { "cycles", "eevee", "eevee-best" };

std::mutex g_log_mutex;
void Progress(const std::string& msg)
{
  std::lock_guard<std::mutex> lock(g_log_mutex);
  fprintf(stderr, "vtkshadow-compare: %s\n", msg.c_str());
  fflush(stderr);
}

struct SceneEntry
{
  std::string path;   // as found
  std::string id;     // e.g. "basic/sphere-plane" (relative to the thresholds folder)
  std::string dir_id; // "basic-sphere-plane": folder name under OUT
  std::string thresholds; // thresholds.json governing it ("" if none)
};

std::string SafeName(const std::string& id)
{
  std::string r;
  for (char c : id)
    r += (c == '/') ? '-' : (isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
  return r;
}

std::string FindThresholds(const std::string& scene_abs)
{
  std::string dir = DirName(scene_abs);
  while (!dir.empty())
  {
    std::string cand = dir + "/thresholds.json";
    if (FileExists(cand))
      return cand;
    std::string parent = DirName(dir);
    if (parent == dir || parent.empty())
      break;
    dir = parent;
  }
  return "";
}

void CollectScenes(const std::string& input, std::vector<std::string>& out)
{
  if (vtksys::SystemTools::FileIsDirectory(input))
  {
    vtksys::Directory d;
    d.Load(input);
    std::vector<std::string> names;
    for (unsigned long i = 0; i < d.GetNumberOfFiles(); ++i)
      names.push_back(d.GetFile(i));
    std::sort(names.begin(), names.end());
    for (const auto& n : names)
    {
      if (n == "." || n == ".." || n == "meshes" || n == "thresholds.json")
        continue;
      std::string p = input + "/" + n;
      if (vtksys::SystemTools::FileIsDirectory(p))
        CollectScenes(p, out);
      else if (n.size() > 5 && n.compare(n.size() - 5, 5, ".json") == 0)
        out.push_back(p);
    }
  }
  else
    out.push_back(input);
}

// ---------------------------------------------------------------- results
struct Row
{
  std::string scene, test, reference = "povray", light_type, status, error, heatmap;
  int light = 0, width = 0, height = 0;
  vsh_metrics m{};
};

struct SceneResult
{
  SceneEntry entry;
  std::string description;
  int lights = 0, width = 0, height = 0;
  std::vector<std::string> light_types;
  std::vector<std::string> errors;  // render failures
  std::vector<Row> rows;
  std::map<std::string, double> seconds; // renderer -> render time
  std::map<std::string, double> frame_seconds; // Blender renderer -> mean seconds per frame
  std::map<std::string, bool> cached;
};

// -------------------------------------------------------- visibility I/O
bool WriteVisibility(const std::string& dir, int k, const std::vector<float>& v,
                     const std::vector<unsigned char>& mask, int w, int h, std::string& err)
{
  char e[1024] = "";
  std::string vis = dir + "/light" + std::to_string(k) + "_visibility.png";
  std::string msk = dir + "/light" + std::to_string(k) + "_mask.png";
  if (vsh_png_write_gray16_float(vis.c_str(), v.data(), w, h, e, sizeof e) != 0 ||
      vsh_png_write_gray8(msk.c_str(), mask.data(), w, h, e, sizeof e) != 0)
  {
    err = e;
    return false;
  }
  return true;
}

void RemoveLightFiles(const std::string& dir, int lights)
{
  for (int k = 0; k < lights; ++k)
  {
    unlink((dir + "/light" + std::to_string(k) + "_visibility.png").c_str());
    unlink((dir + "/light" + std::to_string(k) + "_mask.png").c_str());
  }
}

// Visibility from a shadows-on/off pair; mask where I_off > eps.
void OnOff(const std::vector<float>& on, const std::vector<float>& off, double eps,
           std::vector<float>& v, std::vector<unsigned char>& mask)
{
  v.assign(on.size(), 0.0f);
  mask.assign(on.size(), 0);
  for (size_t i = 0; i < on.size(); ++i)
  {
    const bool valid = off[i] > eps;
    mask[i] = valid ? 255 : 0;
    if (off[i] > 0)
      v[i] = static_cast<float>(std::min(1.0, std::max(0.0, double(on[i]) / off[i])));
  }
}

// ------------------------------------------------------------- harness
class Harness
{
public:
  Options opt;
  std::string povray_version, blender_version, script_bytes;
  std::string pov_version_error, blender_version_error;

  bool Has(const std::string& r) const
  {
    return std::find(opt.renderers.begin(), opt.renderers.end(), r) != opt.renderers.end();
  }

  void Prepare()
  {
    if (Has("povray"))
    {
      povray_version = CommandVersion({ opt.povray, "--version" }, "POV-Ray", 60);
      if (povray_version.empty())
        pov_version_error = "POV-Ray not usable: '" + opt.povray + " --version' failed (is povray installed? apt-get install povray)";
    }
    if (Has("cycles") || Has("eevee") || Has("eevee-best"))
    {
      blender_version = CommandVersion({ opt.blender, "--version" }, "Blender", 120);
      if (blender_version.empty())
        blender_version_error = "Blender not usable: '" + opt.blender + " --version' failed (is blender installed? apt-get install blender)";
      if (!ReadFile(opt.cycles_script, script_bytes))
        blender_version_error = "cannot read the Blender script " + opt.cycles_script;
    }
  }

  int PovThreads() const { return opt.threads; }

  // Scene content hash: file bytes + every mesh file's bytes.
  static bool ContentKey(const vsh_scene* s, const std::string& path, std::string& key,
                         std::string& err)
  {
    std::string bytes;
    if (!ReadFile(path, bytes))
    {
      err = path + ": cannot read";
      return false;
    }
    key = "scene " + MD5Hex(bytes) + "\n";
    for (size_t i = 0; i < s->object_count; ++i)
      if (s->objects[i].kind == VSH_OBJECT_MESH)
      {
        std::string mb;
        if (!ReadFile(s->objects[i].mesh_resolved_path, mb))
        {
          err = path + ": cannot read a mesh file of objects[" + std::to_string(i) + "]";
          return false;
        }
        key += "mesh " + std::to_string(i) + " " + MD5Hex(mb) + "\n";
      }
    return true;
  }

  static bool BuildExport(vtkShadowScene* vs, const vsh_scene* s, int w, int h, ExportScene& ex)
  {
    ex.width = w;
    ex.height = h;
    const vsh_camera& c = s->camera;
    double dist = 0;
    for (int i = 0; i < 3; ++i)
      dist += (c.focal_point[i] - c.position[i]) * (c.focal_point[i] - c.position[i]);
    dist = std::sqrt(dist);
    ex.scale = std::ldexp(1.0, static_cast<int>(std::lround(std::log2(10.0 / dist))));
    for (int i = 0; i < 3; ++i)
    {
      ex.anchor[i] = c.position[i];
      ex.eye[i] = 0;
      ex.focal[i] = (c.focal_point[i] - c.position[i]) * ex.scale;
      ex.up[i] = c.view_up[i];
    }
    ex.view_angle = c.view_angle;
    double lo[3] = { 1e308, 1e308, 1e308 }, hi[3] = { -1e308, -1e308, -1e308 };
    for (int o = 0; o < vs->GetNumberOfObjects(); ++o)
    {
      vtkPolyData* pd = vs->GetObjectPolyData(o);
      if (!pd)
        return false;
      ExportObject eo;
      eo.casts = vs->GetObjectCasts(o);
      vtkPoints* pts = pd->GetPoints();
      vtkDataArray* nrm = pd->GetPointData()->GetNormals();
      if (!nrm)
        nrm = pd->GetPointData()->GetArray("Normals");
      const vtkIdType np = pts ? pts->GetNumberOfPoints() : 0;
      eo.points.resize(3 * np);
      eo.normals.resize(3 * np);
      for (vtkIdType i = 0; i < np; ++i)
      {
        double p[3], n[3] = { 0, 0, 1 };
        pts->GetPoint(i, p);
        if (nrm)
          nrm->GetTuple(i, n);
        for (int j = 0; j < 3; ++j)
        {
          eo.points[3 * i + j] = (p[j] - ex.anchor[j]) * ex.scale;
          eo.normals[3 * i + j] = n[j];
          lo[j] = std::min(lo[j], eo.points[3 * i + j]);
          hi[j] = std::max(hi[j], eo.points[3 * i + j]);
        }
      }
      vtkCellArray* polys = pd->GetPolys();
      vtkNew<vtkIdList> ids;
      polys->InitTraversal();
      while (polys->GetNextCell(ids))
      {
        // The loader gives triangles; fan anything larger, exactly as VTK draws it.
        for (vtkIdType t = 1; t + 1 < ids->GetNumberOfIds(); ++t)
        {
          eo.triangles.push_back(static_cast<uint32_t>(ids->GetId(0)));
          eo.triangles.push_back(static_cast<uint32_t>(ids->GetId(t)));
          eo.triangles.push_back(static_cast<uint32_t>(ids->GetId(t + 1)));
        }
      }
      if (!eo.triangles.empty())
        ex.objects.push_back(std::move(eo));
    }
    double diag = 0;
    for (int j = 0; j < 3; ++j)
    {
      ex.bounds_center[j] = 0.5 * (lo[j] + hi[j]);
      diag += (hi[j] - lo[j]) * (hi[j] - lo[j]);
    }
    ex.bounds_diagonal = std::sqrt(diag);
    for (size_t k = 0; k < s->light_count; ++k)
    {
      const vsh_light& L = s->lights[k];
      ExportLight el;
      el.type = L.type == VSH_LIGHT_DIRECTIONAL ? 0 : L.type == VSH_LIGHT_POINT ? 1 : 2;
      el.cone = L.cone_angle;
      if (el.type == 0)
      {
        double n = std::sqrt(L.direction[0] * L.direction[0] + L.direction[1] * L.direction[1] +
                             L.direction[2] * L.direction[2]);
        // Far outside the scene: POV-Ray's parallel shadow rays stop at the
        // plane through the light position.
        const double far = 10.0 * (ex.bounds_diagonal + 1.0);
        for (int j = 0; j < 3; ++j)
        {
          el.axis[j] = L.direction[j] / n;
          el.position[j] = ex.bounds_center[j] - far * el.axis[j];
        }
      }
      else
      {
        double ax[3], n = 0;
        for (int j = 0; j < 3; ++j)
        {
          el.position[j] = (L.position[j] - ex.anchor[j]) * ex.scale;
          ax[j] = el.type == 2 ? L.focal_point[j] - L.position[j] : (j == 2 ? -1.0 : 0.0);
          n += ax[j] * ax[j];
        }
        n = std::sqrt(n);
        for (int j = 0; j < 3; ++j)
          el.axis[j] = ax[j] / n;
      }
      ex.lights.push_back(el);
    }
    return true;
  }

  // The cache directory for `key`, or "" when caching is off.
  std::string CacheDir(const std::string& renderer, const std::string& key) const
  {
    return opt.cache + "/" + renderer + "/" + key;
  }

  bool CacheLoad(const std::string& cdir, const std::string& outdir, int lights)
  {
    if (opt.no_cache || !FileExists(cdir + "/complete"))
      return false;
    std::string err;
    for (int k = 0; k < lights; ++k)
      for (const char* f : { "_visibility.png", "_mask.png" })
      {
        std::string name = "/light" + std::to_string(k) + f;
        if (!CopyFileAtomic(cdir + name, outdir + name, err))
        {
          RemoveLightFiles(outdir, lights);
          return false;
        }
      }
    return true;
  }

  void CacheStore(const std::string& cdir, const std::string& outdir, int lights,
                  const std::string& keytext)
  {
    std::string err;
    if (!MakeDirs(cdir))
      return;
    for (int k = 0; k < lights; ++k)
      for (const char* f : { "_visibility.png", "_mask.png" })
      {
        std::string name = "/light" + std::to_string(k) + f;
        if (!CopyFileAtomic(outdir + name, cdir + name, err))
          return;
      }
    WriteFileAtomic(cdir + "/key.txt", keytext, err);
    WriteFileAtomic(cdir + "/complete", "ok\n", err); // last: marks the entry usable
  }

  // ---------------------------------------------------------------- POV-Ray
  bool RenderPovray(const SceneEntry& e, const ExportScene& ex, const std::string& content_key,
                    SceneResult& res)
  {
    const int L = static_cast<int>(ex.lights.size());
    const std::string outdir = opt.out + "/" + e.dir_id + "/povray";
    MakeDirs(outdir);
    RemoveLightFiles(outdir, L);
    if (!pov_version_error.empty())
    {
      res.errors.push_back("povray: " + pov_version_error);
      return false;
    }
    const std::string pov = PovScene(ex);
    const std::string settings = "povray -D -A +FN16 File_Gamma=1.0 Display_Gamma=1.0 +W" +
      std::to_string(ex.width) + " +H" + std::to_string(ex.height) + " eps=1e-3";
    const std::string keytext = std::string(kFormatVersion) + "\nrenderer " + povray_version +
      "\nsettings " + settings + "\n" + content_key + "export " + MD5Hex(pov) + "\n";
    const std::string key = MD5Hex(keytext);
    const std::string cdir = CacheDir("povray", key);
    if (CacheLoad(cdir, outdir, L))
    {
      Progress(e.id + ": povray from cache " + key);
      res.cached["povray"] = true;
      return true;
    }
    const std::string work = outdir + "/.work" + std::to_string(getpid());
    RemoveTree(work);
    MakeDirs(work);
    std::string err;
    if (!WriteFileAtomic(work + "/scene.pov", pov, err))
    {
      res.errors.push_back("povray: " + err);
      RemoveTree(work);
      return false;
    }
    const std::string log = AbsPath(outdir + "/povray.log");
    unlink(log.c_str());
    double total = 0;
    for (int k = 0; k < L; ++k)
    {
      std::vector<float> img[2];
      int w = 0, h = 0;
      for (int shadows = 1; shadows >= 0; --shadows)
      {
        const std::string name = std::string(shadows ? "on" : "off") + std::to_string(k) + ".png";
        std::vector<std::string> argv{ opt.povray, "-D", "-P", "-V", "-A", "+FN16",
          "File_Gamma=1.0", "Display_Gamma=1.0", "+W" + std::to_string(ex.width),
          "+H" + std::to_string(ex.height), "+WT" + std::to_string(opt.threads),
          "Declare=VSH_LIGHT=" + std::to_string(k),
          "Declare=VSH_SHADOWS=" + std::to_string(shadows), "+Iscene.pov", "+O" + name };
        RunResult r = RunProcess(argv, work, log, opt.timeout);
        total += r.seconds;
        Progress(e.id + ": povray light " + std::to_string(k) + " shadows " +
                 (shadows ? "on" : "off") + (r.ok() ? "" : " FAILED") + " (" +
                 Fmt(r.seconds, "%.1f") + " s)");
        if (!r.ok())
        {
          res.errors.push_back("povray light " + std::to_string(k) + ": " + r.error);
          RemoveLightFiles(outdir, L);
          RemoveTree(work);
          return false;
        }
        if (!ReadPNGChannel(work + "/" + name, img[shadows], w, h, err) || w != ex.width ||
            h != ex.height)
        {
          res.errors.push_back("povray light " + std::to_string(k) + ": bad output " +
                               (err.empty() ? "size" : err));
          RemoveLightFiles(outdir, L);
          RemoveTree(work);
          return false;
        }
      }
      std::vector<float> v;
      std::vector<unsigned char> mask;
      OnOff(img[1], img[0], 1e-3, v, mask);
      if (!WriteVisibility(outdir, k, v, mask, w, h, err))
      {
        res.errors.push_back("povray: " + err);
        RemoveLightFiles(outdir, L);
        RemoveTree(work);
        return false;
      }
    }
    if (!opt.keep_work)
      RemoveTree(work);
    res.seconds["povray"] = total;
    CacheStore(cdir, outdir, L, keytext);
    return true;
  }

  // The settings line of a Blender renderer's cache key (the script's MD5
  // is in the key too, so every preset value written there is covered).
  std::string BlenderSettings(const std::string& name) const
  {
    if (name == "cycles")
      return "cycles samples=" + std::to_string(opt.cycles_samples) +
        " box filter, bounces 0, no denoise, EXR32 red channel, mask eps=1e-6*max";
    return "preset " + name + ", filter_size 0, fitted clip and light cutoff, EXR32 red "
      "channel, mask eps=1e-6*max";
  }

  // ------------------------------------------------- Cycles and EEVEE
  // `name` is one of kBlenderRenderers: the preset argument of the script.
  bool RenderBlender(const std::string& name, const SceneEntry& e, const ExportScene& ex,
                     const std::string& content_key, SceneResult& res)
  {
    const int L = static_cast<int>(ex.lights.size());
    const std::string outdir = opt.out + "/" + e.dir_id + "/" + name;
    MakeDirs(outdir);
    RemoveLightFiles(outdir, L);
    if (!blender_version_error.empty())
    {
      res.errors.push_back(name + ": " + blender_version_error);
      return false;
    }
    const std::string data = CyclesData(ex, opt.cycles_samples);
    const std::string settings = BlenderSettings(name);
    const std::string keytext = std::string(kFormatVersion) + "\nrenderer " + blender_version +
      "\nsettings " + settings + "\nscript " + MD5Hex(script_bytes) + "\n" + content_key +
      "export " + MD5Hex(data) + "\n";
    const std::string key = MD5Hex(keytext);
    const std::string cdir = CacheDir(name, key);
    if (CacheLoad(cdir, outdir, L))
    {
      Progress(e.id + ": " + name + " from cache " + key);
      res.cached[name] = true;
      return true;
    }
    const std::string work = AbsPath(outdir + "/.work" + std::to_string(getpid()));
    RemoveTree(work);
    MakeDirs(work);
    std::string err;
    if (!WriteFileAtomic(work + "/scene.bin", data, err))
    {
      res.errors.push_back(name + ": " + err);
      RemoveTree(work);
      return false;
    }
    const std::string log = AbsPath(outdir + "/blender.log");
    unlink(log.c_str());
    std::vector<std::string> argv{ opt.blender, "-b", "--factory-startup",
      "--python-exit-code", "1", "-t", std::to_string(opt.threads), "--python",
      opt.cycles_script, "--", work + "/scene.bin", work, name };
    Progress(e.id + ": " + name + " " + std::to_string(L) + " light(s) x shadows on/off ...");
    RunResult r = RunProcess(argv, work, log, opt.timeout * 2 * L + 60);
    Progress(e.id + ": " + name + (r.ok() ? " done" : " FAILED") + " (" +
             Fmt(r.seconds, "%.1f") + " s)");
    if (!r.ok())
    {
      res.errors.push_back(name + ": " + r.error + "; log: " + log);
      RemoveTree(work);
      return false;
    }
    const size_t n = static_cast<size_t>(ex.width) * ex.height;
    for (int k = 0; k < L; ++k)
    {
      std::vector<float> img[2];
      for (int shadows = 0; shadows < 2; ++shadows)
      {
        std::string raw;
        const std::string f = work + "/light" + std::to_string(k) + (shadows ? "_on" : "_off") + ".f32";
        if (!ReadFile(f, raw) || raw.size() != 4 * n)
        {
          res.errors.push_back(name + ": missing or short output " + f + "; log: " + log);
          RemoveLightFiles(outdir, L);
          RemoveTree(work);
          return false;
        }
        img[shadows].resize(n);
        // Blender's rows are bottom-up: flip to row 0 on top.
        for (int y = 0; y < ex.height; ++y)
          std::memcpy(&img[shadows][static_cast<size_t>(y) * ex.width],
                      raw.data() + 4 * static_cast<size_t>(ex.height - 1 - y) * ex.width,
                      4 * static_cast<size_t>(ex.width));
      }
      float mx = 0;
      for (float x : img[0])
        if (std::isfinite(x))
          mx = std::max(mx, x);
      std::vector<float> v;
      std::vector<unsigned char> mask;
      OnOff(img[1], img[0], 1e-6 * mx, v, mask);
      if (!WriteVisibility(outdir, k, v, mask, ex.width, ex.height, err))
      {
        res.errors.push_back(name + ": " + err);
        RemoveLightFiles(outdir, L);
        RemoveTree(work);
        return false;
      }
    }
    // Seconds per frame (one bpy.ops.render.render, without Blender start-up).
    std::string frames;
    if (ReadFile(work + "/frame_seconds.txt", frames))
    {
      std::stringstream fs(frames);
      int light = 0, count = 0;
      std::string state;
      double sec = 0, sum = 0;
      while (fs >> light >> state >> sec)
      {
        sum += sec;
        ++count;
      }
      if (count)
        res.frame_seconds[name] = sum / count;
    }
    if (!opt.keep_work)
      RemoveTree(work);
    res.seconds[name] = r.seconds;
    CacheStore(cdir, outdir, L, keytext);
    return true;
  }

  // -------------------------------------------------------------------- VTK
  void RenderVtk(const SceneEntry& e, int w, int h, int L, SceneResult& res,
                 std::set<std::string>& ok_techniques)
  {
    for (const std::string& t : opt.techniques)
    {
      const std::string outdir = opt.out + "/" + e.dir_id + "/vtk/" + t;
      MakeDirs(outdir);
      RemoveLightFiles(outdir, L);
      const std::string log = AbsPath(outdir + "/render.log");
      unlink(log.c_str());
      bool ok = true;
      double total = 0;
      for (int k = 0; k < L && ok; ++k)
      {
        std::vector<std::string> argv{ opt.render_bin, AbsPath(e.path), "--technique", t,
          "--image", AbsPath(outdir + "/image.png"), "--light", std::to_string(k),
          "--visibility", AbsPath(outdir + "/light" + std::to_string(k) + "_visibility.png"),
          "--mask", AbsPath(outdir + "/light" + std::to_string(k) + "_mask.png"), "--size",
          std::to_string(w) + "x" + std::to_string(h), "--quiet" };
        RunResult r = RunProcess(argv, "", log, opt.timeout);
        total += r.seconds;
        Progress(e.id + ": vtk/" + t + " light " + std::to_string(k) + (r.ok() ? "" : " FAILED") +
                 " (" + Fmt(r.seconds, "%.1f") + " s)");
        if (!r.ok())
        {
          res.errors.push_back("vtk/" + t + " light " + std::to_string(k) + ": " + r.error);
          RemoveLightFiles(outdir, L);
          ok = false;
        }
      }
      if (ok)
      {
        ok_techniques.insert(t);
        res.seconds["vtk/" + t] = total;
      }
    }
  }

  // ---------------------------------------------------------------- metrics
  Row Compare(const SceneEntry& e, int k, const std::string& test, const std::string& testdir,
              const std::string& type)
  {
    Row row;
    row.scene = e.id;
    row.light = k;
    row.light_type = type;
    row.test = test;
    const std::string base = opt.out + "/" + e.dir_id;
    const std::string lk = "/light" + std::to_string(k);
    std::vector<float> ref, mask, tv;
    int w = 0, h = 0, w2 = 0, h2 = 0, w3 = 0, h3 = 0;
    std::string err;
    if (!ReadPNGChannel(base + "/povray" + lk + "_visibility.png", ref, w, h, err) ||
        !ReadPNGChannel(base + "/povray" + lk + "_mask.png", mask, w2, h2, err) ||
        !ReadPNGChannel(base + "/" + testdir + lk + "_visibility.png", tv, w3, h3, err))
    {
      row.status = "error";
      row.error = err;
      return row;
    }
    if (w != w2 || w != w3 || h != h2 || h != h3)
    {
      row.status = "error";
      row.error = "image sizes differ";
      return row;
    }
    std::vector<unsigned char> valid(mask.size());
    for (size_t i = 0; i < mask.size(); ++i)
      valid[i] = mask[i] > 0.5f;
    row.width = w;
    row.height = h;
    int rc = vsh_metrics_compute(tv.data(), ref.data(), valid.data(), nullptr, w, h, &row.m);
    if (rc < 0)
    {
      row.status = "error";
      row.error = "metrics failed";
      return row;
    }
    row.status = rc == VSH_METRICS_EMPTY ? "empty" : "ok";
    std::vector<unsigned char> rgb(3 * static_cast<size_t>(w) * h);
    vsh_error_heatmap_rgb(tv.data(), ref.data(), valid.data(), w, h, rgb.data());
    MakeDirs(base + "/heatmap");
    std::string tname = test;
    std::replace(tname.begin(), tname.end(), '/', '-');
    row.heatmap = e.dir_id + "/heatmap/" + tname + lk.substr(1) + ".png";
    char e2[1024];
    if (vsh_png_write_rgb8((opt.out + "/" + row.heatmap).c_str(), rgb.data(), w, h, e2,
                           sizeof e2) != 0)
      row.heatmap.clear();
    return row;
  }

  SceneResult RunScene(const SceneEntry& e)
  {
    SceneResult res;
    res.entry = e;
    char err[VSH_SCENE_ERROR_MAX];
    vsh_scene* s = nullptr;
    if (vsh_scene_load(e.path.c_str(), &s, err, sizeof err) != 0)
    {
      res.errors.push_back(std::string("scene: ") + err);
      return res;
    }
    vtkNew<vtkShadowScene> vs;
    if (!vs->Load(e.path.c_str()))
    {
      res.errors.push_back(std::string("scene: ") + vs->GetErrorMessage());
      vsh_scene_free(s);
      return res;
    }
    const int w = std::max(1, static_cast<int>(std::lround(s->width * opt.scale)));
    const int h = std::max(1, static_cast<int>(std::lround(s->height * opt.scale)));
    const int L = static_cast<int>(s->light_count);
    res.width = w;
    res.height = h;
    res.lights = L;
    res.description = s->description ? s->description : "";
    for (int k = 0; k < L; ++k)
      res.light_types.push_back(vsh_light_type_name(s->lights[k].type));
    std::string content_key, kerr;
    ExportScene ex;
    bool have_export = ContentKey(s, e.path, content_key, kerr) && BuildExport(vs, s, w, h, ex);
    if (!have_export)
      res.errors.push_back("export: " + (kerr.empty() ? std::string("cannot build the scene") : kerr));
    vsh_scene_free(s);
    Progress(e.id + ": " + std::to_string(w) + "x" + std::to_string(h) + ", " +
             std::to_string(L) + " light(s)");

    bool pov_ok = false;
    std::vector<std::string> blender_ok;
    if (have_export && Has("povray"))
      pov_ok = RenderPovray(e, ex, content_key, res);
    for (const char* b : kBlenderRenderers)
      if (have_export && Has(b) && RenderBlender(b, e, ex, content_key, res))
        blender_ok.push_back(b);
    std::set<std::string> ok_t;
    if (Has("vtk"))
      RenderVtk(e, w, h, L, res, ok_t);
    if (pov_ok)
    {
      for (int k = 0; k < L; ++k)
      {
        for (const std::string& t : opt.techniques)
          if (ok_t.count(t))
            res.rows.push_back(Compare(e, k, "vtk/" + t, "vtk/" + t, res.light_types[k]));
        for (const std::string& b : blender_ok)
          res.rows.push_back(Compare(e, k, b, b, res.light_types[k]));
      }
    }
    for (const Row& r : res.rows)
      if (r.status == "error")
        res.errors.push_back("metrics " + r.test + " light " + std::to_string(r.light) + ": " + r.error);
    for (const std::string& m : res.errors)
      Progress("ERROR " + e.id + ": " + m);
    return res;
  }
};

// ----------------------------------------------------------- thresholds
struct Thresholds
{
  cJSON* root = nullptr;
  ~Thresholds() { cJSON_Delete(root); }
};

double Metric(const vsh_metrics& m, const std::string& name, bool& known)
{
  known = true;
  if (name == "vis_mae") return m.vis_mae;
  if (name == "wrong_pct") return m.wrong_pct;
  if (name == "edge_px") return m.edge_px;
  if (name == "false_shadow_pct") return m.false_shadow_pct;
  if (name == "false_light_pct") return m.false_light_pct;
  known = false;
  return 0;
}

// ---------------------------------------------------------------- report
void WriteResults(const Options& opt, const std::vector<SceneResult>& all)
{
  std::string csv = "scene,light,light_type,test,reference,width,height,valid_pixels,"
                    "compared_pixels,vis_mae,wrong_pct,edge_px,false_shadow_pct,false_light_pct,status\n";
  std::string json = "{\n  \"scenes\": [\n";
  for (size_t si = 0; si < all.size(); ++si)
  {
    const SceneResult& sr = all[si];
    json += "    {\"scene\": \"" + JsonEscape(sr.entry.id) + "\", \"file\": \"" +
      JsonEscape(sr.entry.path) + "\", \"width\": " + std::to_string(sr.width) +
      ", \"height\": " + std::to_string(sr.height) + ", \"lights\": " + std::to_string(sr.lights) +
      ",\n     \"render_seconds\": {";
    bool first = true;
    for (const auto& kv : sr.seconds)
    {
      json += std::string(first ? "" : ", ") + "\"" + JsonEscape(kv.first) + "\": " + Fmt(kv.second, "%.3f");
      first = false;
    }
    json += "},\n     \"frame_seconds\": {";
    first = true;
    for (const auto& kv : sr.frame_seconds)
    {
      json += std::string(first ? "" : ", ") + "\"" + JsonEscape(kv.first) + "\": " + Fmt(kv.second, "%.3f");
      first = false;
    }
    json += "},\n     \"cached\": [";
    first = true;
    for (const auto& kv : sr.cached)
    {
      json += std::string(first ? "" : ", ") + "\"" + kv.first + "\"";
      first = false;
    }
    json += "],\n     \"errors\": [";
    for (size_t i = 0; i < sr.errors.size(); ++i)
      json += std::string(i ? ", " : "") + "\"" + JsonEscape(sr.errors[i]) + "\"";
    json += "],\n     \"results\": [";
    for (size_t i = 0; i < sr.rows.size(); ++i)
    {
      const Row& r = sr.rows[i];
      char buf[2048];
      snprintf(buf, sizeof buf,
               "%s,%d,%s,%s,%s,%d,%d,%ld,%ld,%.9g,%.9g,%.9g,%.9g,%.9g,%s\n", r.scene.c_str(), r.light,
               r.light_type.c_str(), r.test.c_str(), r.reference.c_str(), r.width, r.height,
               r.m.valid_pixels, r.m.compared_pixels, r.m.vis_mae, r.m.wrong_pct, r.m.edge_px,
               r.m.false_shadow_pct, r.m.false_light_pct, r.status.c_str());
      csv += buf;
      snprintf(buf, sizeof buf,
               "%s\n       {\"light\": %d, \"light_type\": \"%s\", \"test\": \"%s\", "
               "\"reference\": \"%s\", \"valid_pixels\": %ld, \"compared_pixels\": %ld, "
               "\"vis_mae\": %.9g, \"wrong_pct\": %.9g, \"edge_px\": %.9g, "
               "\"false_shadow_pct\": %.9g, \"false_light_pct\": %.9g, \"status\": \"%s\", "
               "\"heatmap\": \"%s\"}",
               i ? "," : "", r.light, r.light_type.c_str(), JsonEscape(r.test).c_str(),
               r.reference.c_str(), r.m.valid_pixels, r.m.compared_pixels, r.m.vis_mae,
               r.m.wrong_pct, r.m.edge_px, r.m.false_shadow_pct, r.m.false_light_pct,
               r.status.c_str(), JsonEscape(r.heatmap).c_str());
      json += buf;
    }
    json += "]}";
    json += si + 1 < all.size() ? ",\n" : "\n";
  }
  json += "  ]\n}\n";
  std::string err;
  if (!WriteFileAtomic(opt.out + "/results.csv", csv, err) ||
      !WriteFileAtomic(opt.out + "/results.json", json, err))
    Progress("ERROR writing results: " + err);
}

// The plot: wrong_pct (worst light) per test per scene, clustered bars, by gnuplot.
bool WritePlot(const Options& opt, const std::vector<SceneResult>& all,
               const std::vector<std::string>& tests)
{
  std::string dat = "scene";
  for (const auto& t : tests)
    dat += " " + t;
  dat += "\n";
  for (const SceneResult& sr : all)
  {
    dat += SafeName(sr.entry.id);
    for (const auto& t : tests)
    {
      double worst = -1;
      for (const Row& r : sr.rows)
        if (r.test == t && r.status != "error")
          worst = std::max(worst, r.m.wrong_pct);
      dat += worst < 0 ? " NaN" : " " + Fmt(std::max(worst, 1e-4), "%.6g");
    }
    dat += "\n";
  }
  std::string err;
  if (!WriteFileAtomic(opt.out + "/plot.dat", dat, err))
    return false;
  // Fixed script text; names reach gnuplot only as data (column headers).
  std::string gp =
    "set terminal pngcairo size 1400,600 font 'sans,9'\n"
    "set output 'wrong_pct.png.tmp'\n"
    "set title 'wrong\\_pct (worst light) against POV-Ray, per scene; log scale, floor 1e-4'\n"
    "set style data histogram\nset style histogram cluster gap 1\n"
    "set style fill solid border -1\nset boxwidth 0.9\nset logscale y\nset yrange [1e-4:100]\n"
    "set ylabel 'wrong pixels (%)'\nset xtics rotate by -45 scale 0\nset key outside right top\n"
    "set grid ytics\nset datafile missing 'NaN'\n"
    "plot for [i=2:" + std::to_string(tests.size() + 1) + "] 'plot.dat' using i:xtic(1) title columnheader(i)\n";
  if (!WriteFileAtomic(opt.out + "/wrong_pct.gp", gp, err))
    return false;
  RunResult r = RunProcess({ "gnuplot", "wrong_pct.gp" }, opt.out, opt.out + "/gnuplot.log", 120);
  if (!r.ok() || rename((opt.out + "/wrong_pct.png.tmp").c_str(), (opt.out + "/wrong_pct.png").c_str()) != 0)
  {
    unlink((opt.out + "/wrong_pct.png.tmp").c_str());
    Progress("WARNING: plot not made (gnuplot: " + r.error + "; apt-get install gnuplot-nox)");
    return false;
  }
  return true;
}

void WriteHtml(const Options& opt, const std::vector<SceneResult>& all,
               const std::vector<std::string>& tests, bool plot,
               const std::vector<std::string>& check_failures)
{
  std::string h = "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>vtkshadow-compare"
                  "</title><style>body{font-family:sans-serif;margin:1em}table{border-collapse:"
                  "collapse}td,th{border:1px solid #ccc;padding:2px 6px;font-size:90%}"
                  "img{max-width:320px;image-rendering:pixelated}.err{color:#b00}"
                  "figure{display:inline-block;margin:2px}figcaption{font-size:80%}</style>"
                  "</head><body>\n<h1>vtkshadow: shadows against ray tracers</h1>\n";
  h += "<p>Visibility per light (white = lit). Reference: POV-Ray; Cycles row = the check of "
       "the reference itself; eevee / eevee-best rows = Blender's rasterizer as a peer. Heat maps: blue = test too dark (false shadow), red = too "
       "bright (false light), grey = not valid. See docs/harness.md.</p>\n";
  if (plot)
    h += "<p><img src=\"wrong_pct.png\" style=\"max-width:100%\" alt=\"wrong_pct plot\"></p>\n";
  if (!check_failures.empty())
  {
    h += "<h2 class=\"err\">--check regressions</h2><ul>";
    for (const auto& f : check_failures)
      h += "<li class=\"err\">" + HtmlEscape(f) + "</li>";
    h += "</ul>\n";
  }
  h += "<h2>Scenes</h2><ul>";
  for (const SceneResult& sr : all)
    h += "<li><a href=\"#" + HtmlEscape(sr.entry.dir_id) + "\">" + HtmlEscape(sr.entry.id) +
      "</a>" + (sr.errors.empty() ? "" : " <span class=\"err\">(errors)</span>") + "</li>";
  h += "</ul>\n";
  for (const SceneResult& sr : all)
  {
    h += "<h2 id=\"" + HtmlEscape(sr.entry.dir_id) + "\">" + HtmlEscape(sr.entry.id) + "</h2>\n<p>" +
      HtmlEscape(sr.description) + " (" + std::to_string(sr.width) + "x" +
      std::to_string(sr.height) + ")</p>\n";
    for (const auto& err : sr.errors)
      h += "<p class=\"err\">" + HtmlEscape(err) + "</p>\n";
    for (int k = 0; k < sr.lights; ++k)
    {
      h += "<h3>light " + std::to_string(k) + " (" + HtmlEscape(sr.light_types[k]) + ")</h3>\n<div>";
      std::vector<std::pair<std::string, std::string>> imgs{ { "povray", "povray" } };
      for (const char* b : kBlenderRenderers)
        imgs.push_back({ b, b });
      for (const auto& t : opt.techniques)
        imgs.push_back({ "vtk/" + t, "vtk/" + t });
      const std::string lk = "light" + std::to_string(k);
      for (const auto& im : imgs)
      {
        std::string rel = sr.entry.dir_id + "/" + im.second + "/" + lk + "_visibility.png";
        if (FileExists(opt.out + "/" + rel))
          h += "<figure><img src=\"" + HtmlEscape(rel) + "\"><figcaption>" + HtmlEscape(im.first) +
            "</figcaption></figure>";
      }
      h += "</div><div>";
      for (const Row& r : sr.rows)
        if (r.light == k && !r.heatmap.empty())
          h += "<figure><img src=\"" + HtmlEscape(r.heatmap) + "\"><figcaption>" +
            HtmlEscape(r.test) + " &minus; povray</figcaption></figure>";
      h += "</div>\n<table><tr><th>test</th><th>valid px</th><th>vis_mae</th><th>wrong_pct</th>"
           "<th>edge_px</th><th>false_shadow_pct</th><th>false_light_pct</th><th>status</th></tr>";
      for (const Row& r : sr.rows)
        if (r.light == k)
        {
          char buf[512];
          snprintf(buf, sizeof buf,
                   "<tr><td>%s</td><td>%ld</td><td>%.4g</td><td>%.4g</td><td>%.4g</td><td>%.4g</td>"
                   "<td>%.4g</td><td>%s</td></tr>",
                   HtmlEscape(r.test).c_str(), r.m.valid_pixels, r.m.vis_mae, r.m.wrong_pct,
                   r.m.edge_px, r.m.false_shadow_pct, r.m.false_light_pct, r.status.c_str());
          h += buf;
        }
      h += "</table>\n";
    }
  }
  h += "<p>Machine-readable: <a href=\"results.csv\">results.csv</a>, "
       "<a href=\"results.json\">results.json</a>.</p></body></html>\n";
  (void)tests;
  std::string err;
  if (!WriteFileAtomic(opt.out + "/index.html", h, err))
    Progress("ERROR writing index.html: " + err);
}

std::string SelfDir()
{
  char buf[4096];
  ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0)
    return ".";
  buf[n] = 0;
  return DirName(buf);
}

} // namespace

int main(int argc, char* argv[])
{
  Options opt;
  {
    std::stringstream known(vtkShadowTechnique::GetKnownTechniques());
    for (std::string t; known >> t;)
      opt.techniques.push_back(t);
  }
  std::string usage_error;
  auto need = [&](int& i) -> const char* {
    if (i + 1 >= argc)
    {
      usage_error = std::string(argv[i]) + ": missing value";
      return nullptr;
    }
    return argv[++i];
  };
  for (int i = 1; i < argc && usage_error.empty(); ++i)
  {
    std::string a = argv[i];
    const char* v = nullptr;
    if (a == "--help" || a == "-h")
    {
      fputs(Usage(), stdout);
      return 0;
    }
    else if (a == "--check")
      opt.check = true;
    else if (a == "--no-cache")
      opt.no_cache = true;
    else if (a == "--no-report")
      opt.report = false;
    else if (a == "--keep-work")
      opt.keep_work = true;
    else if (a.rfind("--", 0) == 0)
    {
      if (!(v = need(i)))
        break;
      std::string s = v;
      char* end = nullptr;
      if (a == "--out") opt.out = s;
      else if (a == "--renderers") opt.renderers = Split(s);
      else if (a == "--techniques") opt.techniques = Split(s);
      else if (a == "--thresholds") opt.thresholds = s;
      else if (a == "--cache") opt.cache = s;
      else if (a == "--povray-binary") opt.povray = s;
      else if (a == "--blender-binary") opt.blender = s;
      else if (a == "--render-binary") opt.render_bin = s;
      else if (a == "--cycles-script") opt.cycles_script = s;
      else if (a == "--scale" || a == "--timeout")
      {
        double d = strtod(v, &end);
        if (*end || !(d > 0) || !std::isfinite(d) || (a == "--scale" && d > 16))
          usage_error = a + ": expected a positive number (got '" + s + "')";
        else
          (a == "--scale" ? opt.scale : opt.timeout) = d;
      }
      else if (a == "--jobs" || a == "--threads" || a == "--cycles-samples")
      {
        long n = strtol(v, &end, 10);
        if (*end || n < 1 || n > 1024)
          usage_error = a + ": expected a whole number >= 1 (got '" + s + "')";
        else
          (a == "--jobs" ? opt.jobs : a == "--threads" ? opt.threads : opt.cycles_samples) = int(n);
      }
      else
        usage_error = "unknown option " + a;
    }
    else
      opt.inputs.push_back(a);
  }
  if (usage_error.empty() && opt.out.empty())
    usage_error = "missing required option --out";
  if (usage_error.empty() && opt.inputs.empty())
    usage_error = "no scene given";
  for (const auto& r : opt.renderers)
    if (usage_error.empty() &&
        std::find(std::begin(kRenderers), std::end(kRenderers), r) == std::end(kRenderers))
      usage_error = "--renderers: unknown renderer '" + r +
        "' (known: vtk, povray, cycles, eevee, eevee-best)";
  for (const auto& t : opt.techniques)
    if (usage_error.empty() && (t.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-") != std::string::npos ||
                                !vtkShadowTechnique::IsKnownTechnique(t.c_str())))
      usage_error = "--techniques: unknown technique '" + t + "' (known: " +
        vtkShadowTechnique::GetKnownTechniques() + ")";
  if (!usage_error.empty())
  {
    fprintf(stderr, "vtkshadow-compare: %s\n%s", usage_error.c_str(), Usage());
    return 2;
  }
  const std::string self = SelfDir();
  if (opt.render_bin.empty())
    opt.render_bin = self + "/vtkshadow-render";
  if (opt.cycles_script.empty())
  {
#ifdef VTKSHADOW_CYCLES_SCRIPT
    opt.cycles_script = VTKSHADOW_CYCLES_SCRIPT;
#endif
    if (!FileExists(opt.cycles_script))
      opt.cycles_script = self + "/../share/vtkshadow/render_cycles.py";
  }
  opt.cycles_script = AbsPath(opt.cycles_script);
  if (opt.threads == 0)
    opt.threads = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / opt.jobs);
  if (!MakeDirs(opt.out))
  {
    fprintf(stderr, "vtkshadow-compare: cannot create %s\n", opt.out.c_str());
    return 2;
  }
  opt.out = AbsPath(opt.out);
  if (opt.cache.empty())
    opt.cache = opt.out + "/cache";
  opt.cache = AbsPath(opt.cache);

  // Scenes.
  std::vector<std::string> files;
  for (const auto& in : opt.inputs)
  {
    if (!FileExists(in))
    {
      fprintf(stderr, "vtkshadow-compare: %s: no such file or folder\n", in.c_str());
      return 2;
    }
    CollectScenes(in, files);
  }
  std::vector<SceneEntry> scenes;
  std::set<std::string> used;
  for (const auto& f : files)
  {
    SceneEntry e;
    e.path = f;
    std::string abs = AbsPath(f);
    e.thresholds = opt.thresholds.empty() ? FindThresholds(abs) : AbsPath(opt.thresholds);
    std::string base = e.thresholds.empty() ? DirName(abs) : DirName(e.thresholds);
    std::string rel = abs.rfind(base + "/", 0) == 0 ? abs.substr(base.size() + 1)
                                                    : vtksys::SystemTools::GetFilenameName(abs);
    if (rel.size() > 5 && rel.compare(rel.size() - 5, 5, ".json") == 0)
      rel.resize(rel.size() - 5);
    e.id = rel;
    e.dir_id = SafeName(rel);
    while (used.count(e.dir_id))
      e.dir_id += "_";
    used.insert(e.dir_id);
    scenes.push_back(e);
  }

  Harness H;
  H.opt = opt;
  H.Prepare();
  if ((H.Has("vtk") || H.Has("eevee") || H.Has("eevee-best")) && !getenv("DISPLAY"))
    Progress("WARNING: DISPLAY is not set; vtkshadow-render and EEVEE need an X server (run "
             "under xvfb-run -a or tests/gl-run.sh)");

  std::vector<SceneResult> results(scenes.size());
  std::atomic<size_t> next{ 0 };
  auto worker = [&]() {
    for (size_t i; (i = next++) < scenes.size();)
      results[i] = H.RunScene(scenes[i]);
  };
  std::vector<std::thread> pool;
  for (int j = 0; j < std::min<int>(opt.jobs, static_cast<int>(scenes.size())); ++j)
    pool.emplace_back(worker);
  for (auto& t : pool)
    t.join();

  std::vector<std::string> tests;
  for (const auto& t : opt.techniques)
    if (H.Has("vtk"))
      tests.push_back("vtk/" + t);
  for (const char* b : kBlenderRenderers)
    if (H.Has(b))
      tests.push_back(b);

  // --check.
  std::vector<std::string> failures;
  int checked = 0;
  if (opt.check)
  {
    std::map<std::string, std::unique_ptr<Thresholds>> files_cache;
    for (const SceneResult& sr : results)
    {
      if (sr.entry.thresholds.empty())
      {
        failures.push_back(sr.entry.id + ": no thresholds.json found for this scene");
        continue;
      }
      auto& th = files_cache[sr.entry.thresholds];
      if (!th)
      {
        th.reset(new Thresholds);
        std::string text;
        if (ReadFile(sr.entry.thresholds, text))
          th->root = cJSON_ParseWithLength(text.data(), text.size());
        if (!th->root)
          failures.push_back(sr.entry.thresholds + ": cannot read or not valid JSON");
      }
      if (!th->root)
        continue;
      const cJSON* def = cJSON_GetObjectItemCaseSensitive(th->root, "default");
      const cJSON* sc = cJSON_GetObjectItemCaseSensitive(
        cJSON_GetObjectItemCaseSensitive(th->root, "scenes"), sr.entry.id.c_str());
      for (const Row& r : sr.rows)
      {
        std::map<std::string, double> limits;
        for (const cJSON* level : { def, sc })
        {
          const cJSON* t = cJSON_GetObjectItemCaseSensitive(level, r.test.c_str());
          const cJSON* it = nullptr;
          cJSON_ArrayForEach(it, t)
          {
            if (cJSON_IsNumber(it))
              limits[it->string] = it->valuedouble;
            else if (cJSON_IsNull(it))
              limits.erase(it->string);
          }
        }
        for (const auto& lim : limits)
        {
          bool known = false;
          double value = Metric(r.m, lim.first, known);
          ++checked;
          if (!known)
            failures.push_back(sr.entry.thresholds + ": unknown metric '" + lim.first + "'");
          else if (r.status == "error" || value > lim.second)
            failures.push_back("scene " + sr.entry.id + ", light " + std::to_string(r.light) +
                               ", " + r.test + ": " + lim.first + " = " + Fmt(value, "%.6g") +
                               " > threshold " + Fmt(lim.second, "%.6g"));
        }
      }
      if (!sr.errors.empty())
        failures.push_back("scene " + sr.entry.id + ": " + std::to_string(sr.errors.size()) +
                           " render error(s), not checked: " + sr.errors[0]);
    }
  }

  WriteResults(opt, results);
  if (opt.report)
  {
    bool plot = WritePlot(opt, results, tests);
    WriteHtml(opt, results, tests, plot, failures);
  }

  int failed_scenes = 0;
  for (const SceneResult& sr : results)
    if (!sr.errors.empty())
    {
      ++failed_scenes;
      for (const auto& m : sr.errors)
        fprintf(stderr, "vtkshadow-compare: ERROR %s: %s\n", sr.entry.id.c_str(), m.c_str());
    }
  for (const auto& f : failures)
    fprintf(stderr, "vtkshadow-compare: CHECK FAILED %s\n", f.c_str());
  if (opt.check)
    fprintf(stderr, "vtkshadow-compare: --check: %d comparisons, %zu failure(s)\n", checked,
            failures.size());
  fprintf(stderr, "vtkshadow-compare: %zu scene(s), %d with errors\n", results.size(), failed_scenes);
  if (opt.report)
    printf("%s/index.html\n", opt.out.c_str());
  if (failed_scenes)
    return 1;
  if (!failures.empty())
    return 3;
  return 0;
}
