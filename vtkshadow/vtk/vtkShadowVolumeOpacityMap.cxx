#include "vtkShadowVolumeOpacityMap.h"

#include "vtkCascadedShadowMapPassInternals.h" // for ToFloatTransposed
#include "vtkShadowFrame.h"
#include "vtkShadowScreenMask.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vsh_mat4.h"

#include "vtkShadowScreenQuadVS.h"
#include "vtkShadowVolumeMapFS.h"

#include <algorithm>
#include <chrono>
#include <sstream>
#include <thread>

namespace
{
// Under this a ray counts as blocked: the tracer's rule
// (vtkShadowVolumeCasters::Transmittance), below what the 8-bit mask holds.
constexpr double Cutoff = 1.0 / 1024;

const char* StatusNote(int status)
{
  return status == VSH_VOLUME_MAP_INSIDE
    ? "volumes cast no shadow: the light is inside or at a volume's box (raytrace casts them)"
    : "volumes cast no shadow under this light (raytrace casts them)";
}
}

struct vtkShadowVolumeOpacityMap::LightMap
{
  std::vector<double> Key; // the volumes' key, then the light's
  vsh_volume_map_plan Plan;
  std::vector<float> Texels;
  vtkSmartPointer<vtkTextureObject> Texture;
  bool Uploaded = false;
  bool Casts = false; // a casting light this frame
};

//------------------------------------------------------------------------------
vtkShadowVolumeOpacityMap::vtkShadowVolumeOpacityMap() = default;

//------------------------------------------------------------------------------
vtkShadowVolumeOpacityMap::~vtkShadowVolumeOpacityMap() = default;

//------------------------------------------------------------------------------
void vtkShadowVolumeOpacityMap::Update(
  const vtkshadow::ShadowFrame& frame, vtkOpenGLRenderWindow* window)
{
  this->FrameComputed = 0;
  this->Shown = frame.ShowsVolumes;
  this->Lights.resize(frame.Lights.size());
  if (!this->Shown)
  {
    for (LightMap& map : this->Lights)
    {
      map.Casts = false;
    }
    return;
  }
  this->VolumesKey.clear();
  this->Casters.Gather(frame.Renderer, this->VolumesKey);
  double bounds[6];
  if (this->Casters.GetBounds(bounds))
  {
    for (int a = 0; a < 3; ++a)
    {
      this->Origin[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
    }
  }
  this->VolumesKey.insert(this->VolumesKey.end(), this->Origin, this->Origin + 3);
  for (size_t l = 0; l < frame.Lights.size(); ++l)
  {
    const vtkshadow::ShadowFrameLight& light = frame.Lights[l];
    LightMap& map = this->Lights[l];
    map.Casts = light.Casts && !this->Casters.IsEmpty();
    if (!map.Casts)
    {
      continue;
    }
    double h[4];
    vsh_volume_opacity_map_light(light.Homogeneous, this->Origin, h);
    std::vector<double> key(this->VolumesKey);
    key.insert(key.end(), h, h + 4);
    if (key != map.Key)
    {
      map.Key.swap(key);
      map.Uploaded = false;
      this->Compute(map, h);
    }
    if (!map.Uploaded && map.Plan.status == VSH_VOLUME_MAP_OK && window)
    {
      if (!map.Texture)
      {
        map.Texture = vtkSmartPointer<vtkTextureObject>::New();
      }
      map.Texture->SetContext(window);
      map.Texture->SetInternalFormat(GL_RGBA32F);
      map.Texture->SetFormat(GL_RGBA);
      map.Texture->SetDataType(GL_FLOAT);
      map.Texture->SetMinificationFilter(vtkTextureObject::Nearest);
      map.Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      map.Uploaded = map.Texture->Create2DFromRaw(
        map.Plan.size[0], map.Plan.size[1], 4, VTK_FLOAT, map.Texels.data());
    }
  }
}

//------------------------------------------------------------------------------
// Plans and fills one light's map, the rows split over the cores (every
// sampler only reads).
bool vtkShadowVolumeOpacityMap::Compute(LightMap& map, const double light[4])
{
  const auto start = std::chrono::steady_clock::now();
  std::vector<vsh_volume_map_volume> volumes;
  this->Casters.Describe(this->Origin, volumes);
  const int count = static_cast<int>(volumes.size());
  vsh_volume_opacity_map_plan(volumes.data(), count, light, VSH_VOLUME_MAP_SIZE, &map.Plan);
  ++this->Computed;
  ++this->FrameComputed;
  if (map.Plan.status != VSH_VOLUME_MAP_OK)
  {
    map.Texels.clear();
    return false;
  }
  const int rows = map.Plan.size[1];
  map.Texels.assign(static_cast<size_t>(4) * map.Plan.size[0] * rows, 1.0f);
  const int threads =
    std::max(1, std::min(static_cast<int>(std::thread::hardware_concurrency()), rows));
  std::vector<long long> samples(static_cast<size_t>(threads), 0);
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
  {
    pool.emplace_back(
      [&, t]()
      {
        samples[static_cast<size_t>(t)] = vsh_volume_opacity_map_fill(&map.Plan, volumes.data(),
          count, Cutoff, rows * t / threads, rows * (t + 1) / threads, map.Texels.data());
      });
  }
  for (std::thread& t : pool)
  {
    t.join();
  }
  this->LastSamples = 0;
  for (long long s : samples)
  {
    this->LastSamples += s;
  }
  this->LastSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

//------------------------------------------------------------------------------
bool vtkShadowVolumeOpacityMap::Covers(int light) const
{
  if (light < 0 || light >= static_cast<int>(this->Lights.size()))
  {
    return false;
  }
  const LightMap& map = this->Lights[static_cast<size_t>(light)];
  return map.Casts && map.Uploaded && map.Plan.status == VSH_VOLUME_MAP_OK;
}

//------------------------------------------------------------------------------
bool vtkShadowVolumeOpacityMap::CoversAny() const
{
  for (int l = 0; l < static_cast<int>(this->Lights.size()); ++l)
  {
    if (this->Covers(l))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
std::string vtkShadowVolumeOpacityMap::GetLightNote(int light) const
{
  if (!this->Shown || this->Covers(light))
  {
    return std::string();
  }
  if (this->Casters.IsEmpty())
  {
    std::string why = "volumes cast no shadow (none supported";
    for (const std::string& skipped : this->Casters.GetSkipped())
    {
      why += "; " + skipped;
    }
    return why + ")";
  }
  const bool planned = light >= 0 && light < static_cast<int>(this->Lights.size());
  return StatusNote(planned ? this->Lights[static_cast<size_t>(light)].Plan.status : -1);
}

//------------------------------------------------------------------------------
bool vtkShadowVolumeOpacityMap::Apply(
  vtkOpenGLRenderWindow* window, vtkShadowScreenMask& mask, const vtkshadow::ShadowFrame& frame)
{
  bool ok = true;
  for (int l = 0; l < mask.GetLightCount() && ok; ++l)
  {
    if (this->Covers(l))
    {
      ok = this->ApplyLight(window, mask, frame, l);
    }
  }
  return ok;
}

//------------------------------------------------------------------------------
// One light: blend the map's transmittance into the light's channel alone.
bool vtkShadowVolumeOpacityMap::ApplyLight(vtkOpenGLRenderWindow* window, vtkShadowScreenMask& mask,
  const vtkshadow::ShadowFrame& frame, int light)
{
  vtkTextureObject* depth = mask.GetDepthTexture();
  vtkShaderProgram* program = depth
    ? window->GetShaderCache()->ReadyShaderProgram(vtkShadowScreenQuadVS, vtkShadowVolumeMapFS, "")
    : nullptr;
  if (!program)
  {
    return false;
  }
  const LightMap& map = this->Lights[static_cast<size_t>(light)];
  // The camera in the maps' frame, and the view -> map matrix in double.
  double eye[3], viewToMap[16], ndcToView[16];
  for (int a = 0; a < 3; ++a)
  {
    eye[a] = frame.Eye[a] - this->Origin[a];
  }
  vsh_volume_opacity_map_view_matrix(&map.Plan, frame.ViewRotation, eye, viewToMap);
  vsh_mat4_inverse(frame.Projection, ndcToView);
  float viewToMapF[16], ndcToViewF[16];
  vtkshadow::ToFloatTransposed(viewToMap, viewToMapF);
  vtkshadow::ToFloatTransposed(ndcToView, ndcToViewF);
  const vsh_volume_map_plan& plan = map.Plan;
  const float window4[4] = { static_cast<float>(plan.lo[0]), static_cast<float>(plan.lo[1]),
    static_cast<float>(plan.hi[0]), static_cast<float>(plan.hi[1]) };
  const float mapSize[2] = { static_cast<float>(plan.size[0]), static_cast<float>(plan.size[1]) };
  const float maskSize[2] = { static_cast<float>(mask.GetSize()[0]),
    static_cast<float>(mask.GetSize()[1]) };

  depth->Activate();
  map.Texture->Activate();
  program->SetUniformi("vshDepth", depth->GetTextureUnit());
  program->SetUniformi("vshMap", map.Texture->GetTextureUnit());
  program->SetUniformMatrix4x4("vshNDCToView", ndcToViewF);
  program->SetUniformMatrix4x4("vshViewToMap", viewToMapF);
  program->SetUniform2f("vshMaskSize", maskSize);
  program->SetUniform4f("vshMapWindow", window4);
  program->SetUniform2f("vshMapSize", mapSize);
  program->SetUniformi("vshPerspective", plan.perspective);
  mask.BeginDraw(light, false);
  mask.MultiplyLight(light, program);
  mask.EndDraw();
  map.Texture->Deactivate();
  depth->Deactivate();
  return mask.GetError().empty();
}

//------------------------------------------------------------------------------
std::string vtkShadowVolumeOpacityMap::StatsJSON() const
{
  int maps = 0;
  for (int l = 0; l < static_cast<int>(this->Lights.size()); ++l)
  {
    maps += this->Covers(l) ? 1 : 0;
  }
  std::ostringstream out;
  out << "\"volume_maps\": " << maps << ", \"volume_maps_computed\": " << this->Computed
      << ", \"volume_maps_computed_last_frame\": " << this->FrameComputed
      << ", \"volume_map_samples\": " << this->LastSamples
      << ", \"volume_map_ms\": " << 1000.0 * this->LastSeconds;
  return out.str();
}

//------------------------------------------------------------------------------
long long vtkShadowVolumeOpacityMap::GetMemoryBytes() const
{
  long long bytes = 0;
  for (const LightMap& map : this->Lights)
  {
    // The CPU copy and the texture: 16 bytes a texel each.
    bytes += 2 * static_cast<long long>(map.Texels.size() * sizeof(float));
  }
  return bytes;
}

//------------------------------------------------------------------------------
void vtkShadowVolumeOpacityMap::ReleaseGraphicsResources(vtkWindow* w)
{
  for (LightMap& map : this->Lights)
  {
    if (map.Texture)
    {
      map.Texture->ReleaseGraphicsResources(w);
    }
    map.Uploaded = false;
  }
}
