#include "vtkShadowVolumeReceiver.h"

#include "vtkShadowActorFlags.h"
#include "vtkShadowFrame.h"
#include "vtkShadowPassBase.h"

#include "vtkCollectionIterator.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"
#include "vtkVolumeCollection.h"
#include "vtkVolumeProperty.h"
#include "vtk_glew.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <regex>
#include <sstream>

namespace
{
// The volume shader's light arrays (vtkVolumeShaderComposer: 6 lights).
constexpr int MaxLights = 6;
constexpr int Size = VSH_VOLUME_MAP_SIZE;
// A texel whose ray meets no caster.
constexpr float Miss = 3.0e38f;

std::atomic<int> NextId{ 0 };

// The uniforms and the lit test, "@" standing for the receiver's suffix.
const char* const LitCode = R"(
uniform sampler2D vshVR@Map;
uniform int vshVR@Lights;
uniform int vshVR@On[6];
uniform mat4 vshVR@ToMap[6];
uniform vec4 vshVR@Window[6];
uniform int vshVR@Persp[6];
uniform float vshVR@Bias;
uniform float vshVR@Residual;
float vshVR@Lit(int light, vec3 dataPos)
{
  if (light >= vshVR@Lights || vshVR@On[light] == 0)
  {
    return 1.0;
  }
  vec4 world = in_volumeMatrix[0] * in_textureDatasetMatrix[0] * vec4(dataPos, 1.0);
  vec3 m = (vshVR@ToMap[light] * vec4(world.xyz / world.w, 1.0)).xyz;
  vec2 st = m.xy;
  float d = m.z;
  if (vshVR@Persp[light] != 0)
  {
    if (m.z <= 0.0)
    {
      return 1.0;
    }
    st = m.xy / m.z;
    d = length(m);
  }
  vec4 win = vshVR@Window[light];
  vec2 uv = (st - win.xy) / (win.zw - win.xy);
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThanEqual(uv, vec2(1.0))))
  {
    return 1.0;
  }
  ivec2 size = textureSize(vshVR@Map, 0);
  ivec2 texel = ivec2(uv * vec2(size.x, size.x));
  float depth = texelFetch(vshVR@Map, ivec2(texel.x, light * size.x + texel.y), 0).r;
  return d > depth + vshVR@Bias ? vshVR@Residual : 1.0;
}
)";

const char* const LoopHead = "for (int lightNum = 0; lightNum < in_numberOfLights; lightNum++)";
const char* const More = "/*vshVolumeLitMore*/";

std::string Named(const std::string& text, int id)
{
  return std::regex_replace(text, std::regex("@"), std::to_string(id));
}

// The row-major 3x4 of a plan's frame from world: (u, v, w) = axes (p - eye).
void WorldToMap(const vsh_volume_map_plan& plan, const double origin[3], float out[16])
{
  double eye[3];
  for (int a = 0; a < 3; ++a)
  {
    eye[a] = plan.eye[a] + origin[a];
  }
  // Column major for SetUniformMatrix4x4's float array (as GLSL reads it).
  for (int r = 0; r < 3; ++r)
  {
    const double* axis = plan.axes + 3 * r;
    for (int c = 0; c < 3; ++c)
    {
      out[4 * c + r] = static_cast<float>(axis[c]);
    }
    out[12 + r] = static_cast<float>(-(axis[0] * eye[0] + axis[1] * eye[1] + axis[2] * eye[2]));
    out[4 * r + 3] = 0.0f;
  }
  out[15] = 1.0f;
}
}

//------------------------------------------------------------------------------
vtkShadowVolumeReceiver::vtkShadowVolumeReceiver()
  : Id(NextId++)
{
}

//------------------------------------------------------------------------------
vtkShadowVolumeReceiver::~vtkShadowVolumeReceiver() = default;

//------------------------------------------------------------------------------
// The shaded, visible volumes' world boxes as grids of 2 points a side, in
// the frame of their centre; false when there is none.
bool vtkShadowVolumeReceiver::GatherVolumes(const vtkshadow::ShadowFrame& frame)
{
  this->Boxes.clear();
  vtkVolumeCollection* volumes = frame.Renderer ? frame.Renderer->GetVolumes() : nullptr;
  double lo[3] = { INFINITY, INFINITY, INFINITY }, hi[3] = { -INFINITY, -INFINITY, -INFINITY };
  std::vector<const double*> bounds;
  vtkCollectionSimpleIterator it;
  if (volumes)
  {
    volumes->InitTraversal(it);
  }
  while (vtkVolume* v = volumes ? volumes->GetNextVolume(it) : nullptr)
  {
    if (!v->GetVisibility() || !v->GetProperty() || !v->GetProperty()->GetShade() ||
      !v->GetMapper())
    {
      continue;
    }
    const double* b = v->GetBounds();
    if (!b || !(b[1] > b[0] && b[3] > b[2] && b[5] > b[4]))
    {
      continue;
    }
    bounds.push_back(b);
    for (int a = 0; a < 3; ++a)
    {
      lo[a] = std::min(lo[a], b[2 * a]);
      hi[a] = std::max(hi[a], b[2 * a + 1]);
    }
  }
  if (bounds.empty())
  {
    return false;
  }
  double diagonal = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    this->Origin[a] = 0.5 * (lo[a] + hi[a]);
    diagonal += (hi[a] - lo[a]) * (hi[a] - lo[a]);
  }
  this->Bias = 1e-4 * std::sqrt(diagonal);
  for (const double* b : bounds)
  {
    vsh_volume_map_volume box{};
    for (int a = 0; a < 3; ++a)
    {
      box.grid.origin[a] = b[2 * a];
      box.grid.spacing[a] = b[2 * a + 1] - b[2 * a];
      box.grid.dims[a] = 2;
      box.to_data[4 * a + a] = 1.0;
      box.to_data[4 * a + 3] = this->Origin[a];
    }
    this->Boxes.push_back(box);
  }
  return true;
}

//------------------------------------------------------------------------------
// The opaque casters in the Embree scene, its origin kept at the volumes'
// centre (the eye handed to it), so only a caster's change commits.
void vtkShadowVolumeReceiver::UpdateScene(const vtkshadow::ShadowFrame& frame)
{
  std::vector<vtkShadowEmbreeScene::Actor> actors;
  for (const vtkshadow::ShadowActor& a : frame.Actors)
  {
    vtkShadowEmbreeScene::Actor actor{ a.Actor,
      vtkshadow::CastsAsSurface(a, vtkShadowPassBase::NO_CAST()), {} };
    std::copy_n(a.Matrix, 16, actor.Matrix);
    actor.CastsImpostors = !vtkshadow::HasFlag(a, vtkShadowPassBase::NO_CAST());
    actors.push_back(actor);
  }
  vtkShadowEmbreeScene::Camera camera;
  std::copy_n(frame.Projection, 16, camera.Projection);
  std::copy_n(frame.View, 16, camera.View);
  camera.Width = frame.Size[0];
  this->Scene.Update(actors, this->Origin, 1.0, camera);
  this->SceneVersion = this->Scene.GetMeshBuilds() + this->Scene.GetTopLevelCommits();
}

//------------------------------------------------------------------------------
void vtkShadowVolumeReceiver::Update(
  const vtkshadow::ShadowFrame& frame, vtkOpenGLRenderWindow* window)
{
  this->FrameComputed = 0;
  this->Shown = frame.ShowsVolumes && this->GatherVolumes(frame);
  const int count = std::min(static_cast<int>(frame.Lights.size()), MaxLights);
  this->Lights.resize(static_cast<size_t>(count));
  bool any = false;
  for (int l = 0; l < count; ++l)
  {
    LightMap& map = this->Lights[static_cast<size_t>(l)];
    map.Casts = this->Shown && frame.Lights[static_cast<size_t>(l)].Casts;
    any = any || map.Casts;
  }
  // A shaded volume's shader always has a map to sample (every light off
  // without a casting one).
  this->Texels.resize(static_cast<size_t>(Size) * Size * std::max(count, 1), Miss);
  if (!any)
  {
    this->Upload(this->Shown ? window : nullptr);
    return;
  }
  this->UpdateScene(frame);
  for (int l = 0; l < count; ++l)
  {
    LightMap& map = this->Lights[static_cast<size_t>(l)];
    if (!map.Casts)
    {
      continue;
    }
    double h[4];
    vsh_volume_opacity_map_light(frame.Lights[static_cast<size_t>(l)].Homogeneous, this->Origin, h);
    std::vector<double> key(h, h + 4);
    key.insert(key.end(), this->Origin, this->Origin + 3);
    key.push_back(static_cast<double>(this->SceneVersion));
    key.push_back(static_cast<double>(count));
    for (const vsh_volume_map_volume& box : this->Boxes)
    {
      key.insert(key.end(), box.grid.origin, box.grid.origin + 3);
      key.insert(key.end(), box.grid.spacing, box.grid.spacing + 3);
    }
    if (key != map.Key)
    {
      map.Key.swap(key);
      this->Compute(map, h, l);
      this->Dirty = true;
    }
  }
  this->Upload(window);
}

//------------------------------------------------------------------------------
// One light's rows of the atlas: the light distance of the first opaque
// caster along every texel's ray (Miss where none).
void vtkShadowVolumeReceiver::Compute(LightMap& map, const double light[4], int row)
{
  const auto start = std::chrono::steady_clock::now();
  ++this->Computed;
  ++this->FrameComputed;
  float* texels = this->Texels.data() + static_cast<size_t>(row) * Size * Size;
  std::fill(texels, texels + static_cast<size_t>(Size) * Size, Miss);
  vsh_volume_opacity_map_plan(
    this->Boxes.data(), static_cast<int>(this->Boxes.size()), light, Size, &map.Plan);
  RTCScene casters = this->Scene.GetCasters();
  if (map.Plan.status != VSH_VOLUME_MAP_OK || this->Scene.IsEmpty() || !casters)
  {
    return;
  }
  const double* centre = this->Scene.GetCentre();
  // A directional light's rays start upstream of every caster: `back`
  // before the map's plane along the light.
  double back = 0.0;
  if (!map.Plan.perspective)
  {
    RTCBounds b;
    rtcGetSceneBounds(casters, &b);
    const double* w = map.Plan.axes + 6;
    for (int c = 0; c < 8; ++c)
    {
      const double p[3] = { ((c & 1) ? b.upper_x : b.lower_x) + centre[0] - this->Origin[0],
        ((c & 2) ? b.upper_y : b.lower_y) + centre[1] - this->Origin[1],
        ((c & 4) ? b.upper_z : b.lower_z) + centre[2] - this->Origin[2] };
      const double along = w[0] * (p[0] - map.Plan.eye[0]) + w[1] * (p[1] - map.Plan.eye[1]) +
        w[2] * (p[2] - map.Plan.eye[2]);
      back = std::max(back, -along);
    }
    back += 1.0;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  for (int j = 0; j < Size; ++j)
  {
    for (int i = 0; i < Size; ++i)
    {
      double o[3], d[3];
      vsh_volume_opacity_map_texel_ray(&map.Plan, i, j, o, d);
      RTCRayHit hit{};
      hit.ray.org_x = static_cast<float>(o[0] - back * d[0] + this->Origin[0] - centre[0]);
      hit.ray.org_y = static_cast<float>(o[1] - back * d[1] + this->Origin[1] - centre[1]);
      hit.ray.org_z = static_cast<float>(o[2] - back * d[2] + this->Origin[2] - centre[2]);
      hit.ray.dir_x = static_cast<float>(d[0]);
      hit.ray.dir_y = static_cast<float>(d[1]);
      hit.ray.dir_z = static_cast<float>(d[2]);
      hit.ray.tnear = 0.0f;
      hit.ray.tfar = INFINITY;
      hit.ray.mask = 0xFFFFFFFFu;
      hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
      hit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      rtcIntersect1(casters, &context, &hit);
      if (hit.hit.geomID != RTC_INVALID_GEOMETRY_ID)
      {
        texels[static_cast<size_t>(j) * Size + i] = static_cast<float>(hit.ray.tfar - back);
      }
    }
  }
  this->LastSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

//------------------------------------------------------------------------------
void vtkShadowVolumeReceiver::Upload(vtkOpenGLRenderWindow* window)
{
  if (!window || (!this->Dirty && this->Texture))
  {
    return;
  }
  if (!this->Texture)
  {
    this->Texture = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->Texture->SetContext(window);
  this->Texture->SetInternalFormat(GL_R32F);
  this->Texture->SetFormat(GL_RED);
  this->Texture->SetDataType(GL_FLOAT);
  this->Texture->SetMinificationFilter(vtkTextureObject::Nearest);
  this->Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  const int rows = static_cast<int>(this->Texels.size() / Size);
  this->Dirty = !this->Texture->Create2DFromRaw(Size, rows, 1, VTK_FLOAT, this->Texels.data());
}

//------------------------------------------------------------------------------
bool vtkShadowVolumeReceiver::Covers(int light) const
{
  if (light < 0 || light >= static_cast<int>(this->Lights.size()) || !this->Texture)
  {
    return false;
  }
  const LightMap& map = this->Lights[static_cast<size_t>(light)];
  return map.Casts && map.Plan.status == VSH_VOLUME_MAP_OK;
}

//------------------------------------------------------------------------------
std::string vtkShadowVolumeReceiver::GetLightNote(int light, bool casts) const
{
  if (!this->Shown || !casts || this->Covers(light))
  {
    return std::string();
  }
  if (light >= MaxLights)
  {
    return "shaded volumes receive no shadow from a light past the volume shader's 6";
  }
  return "shaded volumes receive no shadow under this light (inside or at a volume's box)";
}

//------------------------------------------------------------------------------
bool vtkShadowVolumeReceiver::ShowsShadedVolume(vtkRenderer* renderer)
{
  vtkVolumeCollection* volumes = renderer ? renderer->GetVolumes() : nullptr;
  vtkCollectionSimpleIterator it;
  if (volumes)
  {
    volumes->InitTraversal(it);
  }
  while (vtkVolume* v = volumes ? volumes->GetNextVolume(it) : nullptr)
  {
    if (v->GetVisibility() && v->GetProperty() && v->GetProperty()->GetShade())
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkShadowVolumeReceiver::PostReplaceShaderValues(
  std::string& fragmentShader, vtkProp* prop) const
{
  auto* volume = vtkVolume::SafeDownCast(prop);
  const std::string function = "vec4 computeLighting(";
  const size_t at = fragmentShader.find(function);
  const size_t loop = fragmentShader.find(LoopHead);
  if (!volume || !volume->GetProperty() || !volume->GetProperty()->GetShade() ||
    at == std::string::npos || loop == std::string::npos)
  {
    return; // unshaded, or the headlight's lighting alone (no light loop)
  }
  // The first receiver opens the factor in the loop; each adds its test.
  if (fragmentShader.find(More) == std::string::npos)
  {
    const size_t brace = fragmentShader.find('{', loop);
    fragmentShader.insert(brace + 1, std::string("\n  float vshVolumeLit = 1.0") + More + ";");
    for (const std::string colour :
      { "in_lightDiffuseColor[lightNum]", "in_lightSpecularColor[lightNum]" })
    {
      vtkShaderProgram::Substitute(fragmentShader, colour, "(vshVolumeLit * " + colour + ")", true);
    }
  }
  vtkShaderProgram::Substitute(
    fragmentShader, More, Named(" * vshVR@Lit(lightNum, g_dataPos)", this->Id) + More, false);
  fragmentShader.insert(fragmentShader.find(function), Named(LitCode, this->Id));
}

//------------------------------------------------------------------------------
void vtkShadowVolumeReceiver::SetShaderParameters(vtkShaderProgram* program, double residual)
{
  const std::string map = Named("vshVR@Map", this->Id);
  if (!program->IsUniformUsed(map.c_str()))
  {
    return;
  }
  auto name = [this](const char* n) { return Named(n, this->Id); };
  if (!this->Texture)
  {
    return; // no shaded volume in the frame: the shader is not drawn
  }
  if (this->Texture->GetTextureUnit() < 0)
  {
    this->Texture->Activate();
  }
  const bool bound = this->Shown;
  program->SetUniformi(map.c_str(), this->Texture->GetTextureUnit());
  int on[MaxLights] = { 0 }, persp[MaxLights] = { 0 };
  float toMap[MaxLights][16] = { { 0 } }, window[MaxLights][4] = { { 0 } };
  const int count = bound ? static_cast<int>(this->Lights.size()) : 0;
  for (int l = 0; l < count; ++l)
  {
    const vsh_volume_map_plan& plan = this->Lights[static_cast<size_t>(l)].Plan;
    on[l] = this->Covers(l) ? 1 : 0;
    if (on[l])
    {
      WorldToMap(plan, this->Origin, toMap[l]);
      persp[l] = plan.perspective;
      const float w[4] = { static_cast<float>(plan.lo[0]), static_cast<float>(plan.lo[1]),
        static_cast<float>(plan.hi[0]), static_cast<float>(plan.hi[1]) };
      std::copy_n(w, 4, window[l]);
    }
  }
  program->SetUniformi(name("vshVR@Lights").c_str(), count);
  program->SetUniform1iv(name("vshVR@On").c_str(), MaxLights, on);
  program->SetUniform1iv(name("vshVR@Persp").c_str(), MaxLights, persp);
  program->SetUniformMatrix4x4v(name("vshVR@ToMap").c_str(), MaxLights, toMap[0]);
  program->SetUniform4fv(name("vshVR@Window").c_str(), MaxLights, window);
  program->SetUniformf(name("vshVR@Bias").c_str(), static_cast<float>(this->Bias));
  program->SetUniformf(name("vshVR@Residual").c_str(), static_cast<float>(residual));
}

//------------------------------------------------------------------------------
void vtkShadowVolumeReceiver::EndDraw()
{
  if (this->Texture && this->Texture->GetTextureUnit() >= 0)
  {
    this->Texture->Deactivate();
  }
}

//------------------------------------------------------------------------------
std::string vtkShadowVolumeReceiver::StatsJSON() const
{
  int maps = 0;
  for (int l = 0; l < static_cast<int>(this->Lights.size()); ++l)
  {
    maps += this->Covers(l) ? 1 : 0;
  }
  std::ostringstream out;
  out << "\"volume_receiver_maps\": " << maps
      << ", \"volume_receiver_maps_computed\": " << this->Computed
      << ", \"volume_receiver_maps_computed_last_frame\": " << this->FrameComputed
      << ", \"volume_receiver_map_ms\": " << 1000.0 * this->LastSeconds;
  return out.str();
}

//------------------------------------------------------------------------------
long long vtkShadowVolumeReceiver::GetMemoryBytes() const
{
  // The texture (GPU memory, as the passes count it): 4 bytes a texel.
  return this->Texture ? static_cast<long long>(this->Texels.size() * sizeof(float)) : 0;
}

//------------------------------------------------------------------------------
void vtkShadowVolumeReceiver::ReleaseGraphicsResources(vtkWindow* w)
{
  if (this->Texture)
  {
    this->Texture->ReleaseGraphicsResources(w);
    this->Texture = nullptr;
  }
  this->Dirty = true;
}
