#include "vtkCascadedShadowMapPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPlanarShadowPass.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowCasterGeometry.h"
#include "vtkShadowLightingHook.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vsh_bounds.h"
#include "vsh_camera.h"
#include "vsh_vec3.h"
#include "vsh_csm.h"
#include "vsh_mat4.h"

#include "vtkShadowMapDepthFS.h"
#include "vtkShadowMapDepthVS.h"
#include "vtkShadowMapLightFS.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkCascadedShadowMapPass);

namespace
{
constexpr int MaxLights = 8;
constexpr int MaxTiles = 24;

enum LightKind
{
  NoShadow = 0,
  Cascades = 1,
  Spot = 2,
  Point = 3
};


void ToFloatTransposed(const double m[16], float out[16])
{
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      out[c * 4 + r] = static_cast<float>(m[r * 4 + c]);
    }
  }
}

// One shadow map of the atlas.
struct Tile
{
  vsh_shadow_view View;      // camera-relative world -> clip
  double Absolute[16];       // world -> clip (for caching)
  double Near = 0.0;         // cascade near depth
  double Far = 0.0;          // cascade far depth
  double TexelPixels = 0.0;  // on-screen size of a texel at the cascade's near end
  double Bias[2] = { 0, 0 }; // depth bias, normal offset
  int Light = -1;
};

// Half angle of a positional light's map: the spot's cone a little wider
// (so its edge is inside the map), or a cube face, a little over 45 degrees
// (so the face a direction's major axis picks always contains it).
const double CubeFaceHalfAngle = 45.5;
double MapHalfAngle(vtkLight* light)
{
  return light->GetConeAngle() < 90.0 ? std::min(light->GetConeAngle() * 1.02 + 0.5, 89.0)
                                      : CubeFaceHalfAngle;
}

// Depth bias and normal offset from the map's texel size and depth range,
// and the absolute world -> clip matrix (for caching).
void ComputeBiasAndAbsolute(Tile& tile, const double eye[3], double biasScale)
{
  // A perspective map's texels grow with the distance from the light, and
  // its depth is not linear: both biases are per unit of distance there, and
  // the shader scales them by the fragment's distance and applies the depth
  // bias in linear depth (a constant offset in the map's depth would swamp
  // the depth differences far from a light whose near plane is close).
  vsh_csm_bias(tile.View.texel_world, tile.View.perspective ? 1.0 : tile.View.depth_extent,
    biasScale, &tile.Bias[0], &tile.Bias[1]);
  double toRelative[16];
  const double negEye[3] = { -eye[0], -eye[1], -eye[2] };
  vsh_mat4_translation(negEye, toRelative);
  vsh_mat4_multiply(tile.View.world_to_clip, toRelative, tile.Absolute);
}
}

struct vtkCascadedShadowMapPass::Internals
{
  double SplitFractions[VSH_CSM_MAX_CASCADES] = { 0 };
  std::map<vtkActor*, std::unique_ptr<vtkShadowCasterGeometry>> Casters;
  vtkTextureObject* Atlas = nullptr;
  vtkOpenGLFramebufferObject* FBO = nullptr;
  int AtlasSize[2] = { 0, 0 };
  int TileGrid[2] = { 1, 1 };
  int RenderedResolution = 0; // texels per tile edge of the held maps
  std::vector<Tile> Tiles;
  // What each atlas slot last held, to skip re-rendering unchanged maps.
  // What each atlas tile holds: the view it was rendered with (relative to
  // the camera position then), so a later frame can reuse it.
  struct RenderedTile
  {
    bool Valid = false;
    Tile Map;
    double Origin[3] = { 0, 0, 0 };
    vtkMTimeType CasterTime = 0;
  };
  std::vector<RenderedTile> Rendered;
  // Per-light shader data in the mapper's numbering.
  int LightCount = 0;
  int Kind[MaxLights] = { 0 };
  int First[MaxLights] = { 0 };
  int Count[MaxLights] = { 0 };
  float LightVC[MaxLights][3] = { { 0 } };
  float ViewToWorld[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
  float FadeStart = 0.0f;
  float MaxDistance = 0.0f;
  std::string ShaderSignature; // kinds, filter: what the generated code depends on

};

//------------------------------------------------------------------------------
vtkCascadedShadowMapPass::vtkCascadedShadowMapPass()
  : CascadeCount(0)
  , RatioPerCascade(8.0)
  , SplitScheme(PRACTICAL)
  , SplitLambda(0.75)
  , Stable(true)
  , MapResolution(2048)
  , MaxTexelPixels(0.0)
  , MemoryBudget(256LL << 20)
  , BiasScale(1.0)
  , Filter(HARDWARE_2X2)
  , PCFSize(3)
  , PoissonRadius(1.5)
  , BlendBand(0.1)
  , MaxShadowDistance(0.0)
  , FadeFraction(0.1)
  , DebugCascades(false)
  , UsedResolution(0)
  , NumberOfMapsRendered(0)
  , NumberOfMapsReused(0)
  , TotalMapsRendered(0)
  , Impl(new Internals)
{
}

//------------------------------------------------------------------------------
vtkCascadedShadowMapPass::~vtkCascadedShadowMapPass()
{
  if (this->Impl->Atlas)
  {
    this->Impl->Atlas->Delete();
  }
  if (this->Impl->FBO)
  {
    this->Impl->FBO->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::CopySettings(vtkCascadedShadowMapPass* o)
{
  if (!o || o == this)
  {
    return;
  }
  this->CascadeCount = o->CascadeCount;
  this->RatioPerCascade = o->RatioPerCascade;
  this->SplitScheme = o->SplitScheme;
  this->SplitLambda = o->SplitLambda;
  std::copy_n(o->Impl->SplitFractions, VSH_CSM_MAX_CASCADES, this->Impl->SplitFractions);
  this->Stable = o->Stable;
  this->MapResolution = o->MapResolution;
  this->MaxTexelPixels = o->MaxTexelPixels;
  this->MemoryBudget = o->MemoryBudget;
  this->BiasScale = o->BiasScale;
  this->Filter = o->Filter;
  this->PCFSize = o->PCFSize;
  this->PoissonRadius = o->PoissonRadius;
  this->BlendBand = o->BlendBand;
  this->MaxShadowDistance = o->MaxShadowDistance;
  this->FadeFraction = o->FadeFraction;
  this->DebugCascades = o->DebugCascades;
  this->CastHeadlightShadows = o->CastHeadlightShadows;
  this->SkippedLights = o->SkippedLights;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::SetSplitFraction(int i, double fraction)
{
  if (i >= 0 && i < VSH_CSM_MAX_CASCADES && this->Impl->SplitFractions[i] != fraction)
  {
    this->Impl->SplitFractions[i] = fraction;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
double vtkCascadedShadowMapPass::GetSplitFraction(int i) const
{
  return (i >= 0 && i < VSH_CSM_MAX_CASCADES) ? this->Impl->SplitFractions[i] : 0.0;
}

//------------------------------------------------------------------------------
int vtkCascadedShadowMapPass::GetNumberOfCascades(int light) const
{
  return (light >= 0 && light < this->Impl->LightCount && this->Impl->Kind[light] == Cascades)
    ? this->Impl->Count[light]
    : 0;
}

//------------------------------------------------------------------------------
double vtkCascadedShadowMapPass::GetCascadeFar(int light, int cascade) const
{
  if (cascade < 0 || cascade >= this->GetNumberOfCascades(light))
  {
    return 0.0;
  }
  return this->Impl->Tiles[this->Impl->First[light] + cascade].Far;
}

//------------------------------------------------------------------------------
double vtkCascadedShadowMapPass::GetCascadeTexelPixels(int light, int cascade) const
{
  if (cascade < 0 || cascade >= this->GetNumberOfCascades(light))
  {
    return 0.0;
  }
  return this->Impl->Tiles[this->Impl->First[light] + cascade].TexelPixels;
}

//------------------------------------------------------------------------------
long long vtkCascadedShadowMapPass::GetMemoryBytes() const
{
  return static_cast<long long>(this->Impl->AtlasSize[0]) * this->Impl->AtlasSize[1] * 4;
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->NumberOfMapsRendered = 0;
  vtkRenderer* renderer = s->GetRenderer();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro("vtkCascadedShadowMapPass needs an OpenGL render window");
    return;
  }
  Internals& impl = *this->Impl;

  int size[2], origin[2];
  GetViewport(s, size, origin);
  const double aspect = size[1] > 0 ? static_cast<double>(size[0]) / size[1] : 1.0;

  // Casters and receivers (every visible opaque actor receives).
  std::vector<vtkActor*> casters;
  vsh_bounds casterBounds, receiverBounds;
  vsh_bounds_init_empty(&casterBounds);
  vsh_bounds_init_empty(&receiverBounds);
  vtkMTimeType casterTime = 0;
  for (const vtkshadow::ShadowActor& shadowActor : vtkshadow::ShadowActors(s))
  {
    vtkActor* actor = shadowActor.Actor;
    vsh_bounds ab;
    vsh_bounds_from_vtk(&ab, shadowActor.Bounds);
    vsh_bounds_merge(&receiverBounds, &ab);
    if (!vtkshadow::HasFlag(actor, vtkShadowPassBase::NO_CAST()))
    {
      casters.push_back(actor);
      vsh_bounds_merge(&casterBounds, &ab);
      // The actor's placement, not its own MTime: VTK's pass machinery gives
      // actors property keys during the first frame, which bumps it.
      casterTime =
        std::max({ casterTime, actor->GetMatrix()->GetMTime(), vtkshadow::MeshTime(actor) });
    }
  }
  casterTime += casters.size(); // a caster leaving the scene changes it too

  // Camera, in double, relative to its own position.
  vtkCamera* camera = renderer->GetActiveCamera();
  vsh_camera cam;
  camera->GetPosition(cam.position);
  camera->GetFocalPoint(cam.focal_point);
  camera->GetViewUp(cam.view_up);
  cam.view_angle = camera->GetViewAngle();
  double clip[2];
  camera->GetClippingRange(clip);
  double viewRotation[16];
  vtkMatrix4x4::DeepCopy(viewRotation, camera->GetViewTransformMatrix());
  viewRotation[3] = viewRotation[7] = viewRotation[11] = 0.0;
  double viewToRelative[16]; // view coordinates -> camera-relative world
  vsh_mat4_transpose(viewRotation, viewToRelative);
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      impl.ViewToWorld[c * 3 + r] = static_cast<float>(viewToRelative[r * 4 + c]);
    }
  }

  // Visible depth range of the receivers, and the shadow distance.
  double depthRange[2] = { clip[0], clip[1] };
  const bool haveScene = !vsh_bounds_is_empty(&receiverBounds) && !casters.empty();
  if (haveScene &&
    vsh_csm_visible_depth_range(&cam, aspect, clip[0], clip[1], &receiverBounds, depthRange) != 0)
  {
    depthRange[0] = clip[0];
    depthRange[1] = clip[1];
  }
  if (this->MaxShadowDistance > 0.0)
  {
    depthRange[1] = std::max(std::min(depthRange[1], this->MaxShadowDistance), depthRange[0] * 1.001);
  }
  impl.MaxDistance = static_cast<float>(depthRange[1]);
  impl.FadeStart = static_cast<float>(depthRange[1] - this->FadeFraction * (depthRange[1] - depthRange[0]));
  if (this->MaxShadowDistance <= 0.0 && this->FadeFraction <= 0.0)
  {
    impl.MaxDistance = 0.0f;
  }

  // Lights that follow the camera (and the automatic headlight) are updated
  // by VTK's lights pass inside the delegate, after our shadow work: bring
  // them up to date now, or their shadows (and the resolution they ask
  // for) lag one frame behind.
  vtkshadow::UpdateLights(renderer);
  // Light `l` (mapper numbering) gets maps in this frame.
  auto castsShadows = [&](vtkLight* light, int l) {
    return haveScene && this->LightCasts(light, l);
  };
  // Perspective maps are fitted to everything that casts or receives.
  vsh_bounds everything = casterBounds;
  vsh_bounds_merge(&everything, &receiverBounds);

  // Resolution and cascade count.
  int resolution = this->MapResolution;
  int count = this->CascadeCount > 0
    ? this->CascadeCount
    : vsh_csm_default_count(depthRange[0], depthRange[1], this->RatioPerCascade);
  if (this->MaxTexelPixels > 0.0)
  {
    // Fewest cascades first: every cascade re-renders every caster, so on
    // any renderer a second cascade costs more than a larger map. Then the
    // least memory for that count.
    const int maxCount = this->CascadeCount > 0 ? this->CascadeCount : 8;
    double predicted = 0.0;
    for (int k = this->CascadeCount > 0 ? maxCount : 1; k <= maxCount; ++k)
    {
      if (vsh_csm_choose(depthRange[0], depthRange[1], cam.view_angle, aspect, size[1],
            this->MaxTexelPixels, this->MemoryBudget, 256, 8192, k, &resolution, &count,
            &predicted) == 0)
      {
        break;
      }
    }
    // Spot and point-light maps share the atlas resolution: raise it to what
    // they need where the scene's centre is seen.
    double centre[3];
    if (haveScene && vsh_bounds_center(&everything, centre) == 0)
    {
      double forward[3], r[3], u[3];
      vsh_camera_basis(&cam, r, u, forward);
      const double rel[3] = { centre[0] - cam.position[0], centre[1] - cam.position[1],
        centre[2] - cam.position[2] };
      const double depth = std::max(vsh_vec3_dot(rel, forward), depthRange[0]);
      int l = 0;
      for (vtkLight* light : vtkshadow::SwitchedOnLights(renderer))
      {
        if (!castsShadows(light, l++) || !light->GetPositional())
        {
          continue;
        }
        double p[3];
        light->GetTransformedPosition(p);
        const double half = MapHalfAngle(light);
        const double toCentre[3] = { centre[0] - p[0], centre[1] - p[1], centre[2] - p[2] };
        resolution = std::max(resolution,
          vsh_csm_perspective_resolution(half, vsh_vec3_length(toCentre), depth, cam.view_angle,
            size[1], this->MaxTexelPixels, 256, 8192));
      }
    }
  }
  double splits[VSH_CSM_MAX_CASCADES + 1];
  if (vsh_csm_splits(static_cast<vsh_split_scheme>(this->SplitScheme), count, depthRange[0],
        depthRange[1], this->SplitLambda, impl.SplitFractions, splits) != 0)
  {
    if (this->SplitScheme == EXPLICIT)
    {
      vtkWarningMacro("explicit split fractions are invalid for " << count
                                                                  << " cascades: using practical splits");
    }
    vsh_csm_splits(VSH_SPLIT_PRACTICAL, count, depthRange[0], depthRange[1], 0.75, nullptr, splits);
  }

  // Lights in the mapper's numbering and their maps.
  impl.Tiles.clear();
  impl.LightCount = 0;
  {
    for (vtkLight* light : vtkshadow::SwitchedOnLights(renderer))
    {
      const int l = impl.LightCount++;
      if (l >= MaxLights)
      {
        continue;
      }
      impl.Kind[l] = NoShadow;
      impl.First[l] = static_cast<int>(impl.Tiles.size());
      impl.Count[l] = 0;
      if (!castsShadows(light, l))
      {
        continue;
      }
      double p[3], f[3];
      light->GetTransformedPosition(p);
      light->GetTransformedFocalPoint(f);
      const double travel[3] = { f[0] - p[0], f[1] - p[1], f[2] - p[2] };
      if (!light->GetPositional())
      {
        int made = 0;
        for (int c = 0; c < count && impl.Tiles.size() < MaxTiles; ++c)
        {
          Tile tile;
          const int status = vsh_csm_fit_directional(&cam, aspect, splits[c], splits[c + 1], travel,
            &receiverBounds, &casterBounds, this->Stable ? 1 : 0, resolution, &tile.View);
          if (status == 2)
          {
            break;
          }
          if (status == 1)
          {
            // The slice sees no receiver: an empty map that nothing samples.
            vsh_mat4_identity(tile.View.world_to_clip);
            tile.View.world_to_clip[10] = 0.0;
            tile.View.texel_world = 0.0;
            tile.View.depth_extent = 1.0;
          }
          tile.Near = splits[c];
          tile.Far = splits[c + 1];
          tile.TexelPixels =
            vsh_csm_texel_pixels(tile.View.texel_world, splits[c], cam.view_angle, size[1]);
          tile.Light = l;
          impl.Tiles.push_back(tile);
          ++made;
        }
        if (made > 0)
        {
          impl.Kind[l] = Cascades;
          impl.Count[l] = made;
        }
      }
      else if (light->GetConeAngle() < 90.0)
      {
        Tile tile;
        const double half = MapHalfAngle(light);
        if (impl.Tiles.size() < MaxTiles &&
          vsh_csm_fit_perspective(p, travel, half, &everything, cam.position, resolution, &tile.View) == 0)
        {
          tile.Light = l;
          impl.Tiles.push_back(tile);
          impl.Kind[l] = Spot;
          impl.Count[l] = 1;
        }
      }
      else if (impl.Tiles.size() + 6 <= MaxTiles)
      {
        // Point light: six 90-degree faces (a little wider, so the face a
        // direction's major axis picks always contains it).
        int made = 0;
        for (int face = 0; face < 6; ++face)
        {
          Tile tile;
          double axis[3];
          vsh_csm_cube_face_direction(face, axis);
          if (vsh_csm_fit_perspective(p, axis, CubeFaceHalfAngle, &everything, cam.position, resolution, &tile.View) != 0)
          {
            // Nothing in front of this face: a map that covers nothing.
            vsh_mat4_identity(tile.View.world_to_clip);
            tile.View.world_to_clip[15] = -1.0; // w < 0: every lookup is lit
            tile.View.texel_world = 0.0;
            tile.View.depth_extent = 1.0;
          }
          tile.Light = l;
          impl.Tiles.push_back(tile);
          ++made;
        }
        impl.Kind[l] = Point;
        impl.Count[l] = made;
        const double rel[3] = { p[0] - cam.position[0], p[1] - cam.position[1], p[2] - cam.position[2] };
        double vc[3];
        vsh_mat4_transform_direction(viewRotation, rel, vc);
        for (int k = 0; k < 3; ++k)
        {
          impl.LightVC[l][k] = static_cast<float>(vc[k]);
        }
      }
    }
  }
  if (impl.LightCount > MaxLights)
  {
    vtkWarningMacro("only the first " << MaxLights << " lights cast shadows");
    impl.LightCount = MaxLights;
  }
  // The lights' kinds and the filter are compiled into the receivers'
  // shaders: rebuild them when those change.
  {
    std::string signature = std::to_string(this->Filter) + "/" + std::to_string(this->PCFSize) + ":";
    for (int l = 0; l < impl.LightCount; ++l)
    {
      signature += std::to_string(impl.Kind[l]);
    }
    if (signature != impl.ShaderSignature)
    {
      impl.ShaderSignature = signature;
      this->BumpShaderTime();
    }
  }

  // Bias and absolute matrices per tile.
  for (Tile& tile : impl.Tiles)
  {
    ComputeBiasAndAbsolute(tile, cam.position, this->BiasScale);
  }

  // The atlas: a grid of resolution^2 tiles, clamped to the GL's limit.
  const int tiles = static_cast<int>(impl.Tiles.size());
  GLint maxSize = 4096;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  const int columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(std::max(tiles, 1))))));
  const int rows = std::max(1, (std::max(tiles, 1) + columns - 1) / columns);
  if (resolution * std::max(columns, rows) > maxSize)
  {
    const int clamped = maxSize / std::max(columns, rows);
    vtkWarningMacro("shadow map resolution " << resolution << " x " << columns << " x " << rows
                                             << " exceeds the GL limit " << maxSize
                                             << ": using " << clamped);
    resolution = clamped;
  }
  this->UsedResolution = resolution;
  vtkOpenGLState* state = window->GetState();
  if (!impl.Atlas)
  {
    impl.Atlas = vtkTextureObject::New();
    impl.FBO = vtkOpenGLFramebufferObject::New();
  }
  impl.Atlas->SetContext(window);
  impl.FBO->SetContext(window);
  const int atlasW = columns * resolution, atlasH = rows * resolution;
  if (!impl.Atlas->GetHandle() || impl.AtlasSize[0] != atlasW || impl.AtlasSize[1] != atlasH)
  {
    impl.Atlas->ReleaseGraphicsResources(window);
    impl.Atlas->SetWrapS(vtkTextureObject::ClampToEdge);
    impl.Atlas->SetWrapT(vtkTextureObject::ClampToEdge);
    impl.Atlas->SetMinificationFilter(vtkTextureObject::Linear);
    impl.Atlas->SetMagnificationFilter(vtkTextureObject::Linear);
    impl.Atlas->SetDepthTextureCompare(true);
    impl.Atlas->SetDepthTextureCompareFunction(vtkTextureObject::Lequal);
    impl.Atlas->AllocateDepth(atlasW, atlasH, vtkTextureObject::Float32);
    // The setters above change nothing the second time, so the texture
    // object's time is older than its last SendParameters and the new GL
    // texture would never get the depth compare mode: every lookup would
    // then read as shadowed (found by the robustness suite: auto re-sizing
    // its maps after a window resize).
    impl.Atlas->Modified();
    impl.AtlasSize[0] = atlasW;
    impl.AtlasSize[1] = atlasH;
    impl.Rendered.clear();
  }
  // A held map is only reusable in the slot and at the texel size it was
  // rendered with: a new grid or resolution (auto's texel target follows the
  // window size and the casters) can keep the atlas size but not its layout.
  if (impl.TileGrid[0] != columns || impl.TileGrid[1] != rows ||
    impl.RenderedResolution != resolution)
  {
    impl.Rendered.clear();
  }
  impl.TileGrid[0] = columns;
  impl.TileGrid[1] = rows;
  impl.RenderedResolution = resolution;
  impl.Rendered.resize(tiles);

  // Render the maps that changed. A cascade whose map from an earlier frame
  // still covers every lookup of this frame keeps that map (and its matrix
  // and bias): a stable cascade is a square around its slice's bounding
  // sphere, so small camera moves rarely leave it.
  std::vector<int> dirty;
  this->NumberOfMapsReused = 0;
  const double reach = 2.0 + this->BiasScale * 2.0 +
    (this->Filter == PCF ? 0.5 * this->PCFSize + 1.0
                         : this->Filter == POISSON ? this->PoissonRadius + 1.0 : 1.0);
  for (int t = 0; t < tiles; ++t)
  {
    Tile& tile = impl.Tiles[t];
    Internals::RenderedTile& held = impl.Rendered[t];
    // A map of the same light and casters: the same one, or perhaps reusable.
    const bool comparable =
      held.Valid && held.CasterTime == casterTime && held.Map.Light == tile.Light;
    bool same = comparable && held.Map.View.perspective == tile.View.perspective;
    // Two empty maps (nothing in front of a cube face, no receiver in a
    // slice) are the same whatever their placeholder matrices say.
    const bool empty = tile.View.texel_world <= 0.0;
    if (same && empty)
    {
      same = held.Map.View.texel_world <= 0.0;
    }
    for (int k = 0; same && !empty && k < 16; ++k)
    {
      const double a = tile.Absolute[k], b = held.Map.Absolute[k];
      same = std::abs(a - b) <= 1e-12 * std::max(1.0, std::max(std::abs(a), std::abs(b)));
    }
    // (The core refuses perspective and empty maps itself.)
    if (!same && comparable && this->Stable && tile.Near > 0.0)
    {
      double region[6];
      const double lookupNear = tile.Near * (1.0 - (tile.Near > depthRange[0] ? this->BlendBand : 0.0));
      if (vsh_csm_lookup_region(&cam, aspect, lookupNear, tile.Far, &receiverBounds, &casterBounds,
            &tile.View, region) == 0 &&
        vsh_csm_view_covers(&held.Map.View, held.Origin, &tile.View, cam.position, region, resolution,
          reach))
      {
        // Sample the held map: its view, re-expressed relative to this
        // frame's camera position (a small shift, exact enough in double).
        const double shift[3] = { cam.position[0] - held.Origin[0],
          cam.position[1] - held.Origin[1], cam.position[2] - held.Origin[2] };
        double toHeld[16];
        vsh_mat4_translation(shift, toHeld);
        const double far = tile.Far, near = tile.Near, pixels = tile.TexelPixels;
        tile = held.Map;
        vsh_mat4_multiply(held.Map.View.world_to_clip, toHeld, tile.View.world_to_clip);
        tile.Near = near;
        tile.Far = far;
        tile.TexelPixels = pixels;
        ++this->NumberOfMapsReused;
        same = true;
      }
    }
    if (!same)
    {
      dirty.push_back(t);
      held.Valid = true;
      held.Map = tile;
      std::copy_n(cam.position, 3, held.Origin);
      held.CasterTime = casterTime;
    }
  }
  if (!dirty.empty())
  {
    vtkShaderProgram* program =
      window->GetShaderCache()->ReadyShaderProgram(vtkShadowMapDepthVS, vtkShadowMapDepthFS, "");
    state->PushFramebufferBindings();
    impl.FBO->Bind();
    impl.FBO->AddDepthAttachment(impl.Atlas);
    impl.FBO->DeactivateDrawBuffers();
    {
      vtkOpenGLState::ScopedglViewport viewport(state);
      vtkOpenGLState::ScopedglScissor scissor(state);
      vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
      vtkOpenGLState::ScopedglEnableDisable scissorTest(state, GL_SCISSOR_TEST);
      vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
      vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
      vtkOpenGLState::ScopedglDepthMask depthMask(state);
      vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
      state->vtkglEnable(GL_DEPTH_TEST);
      state->vtkglEnable(GL_SCISSOR_TEST);
      state->vtkglDisable(GL_BLEND);
      state->vtkglDisable(GL_CULL_FACE);
      state->vtkglDepthMask(GL_TRUE);
      state->vtkglDepthFunc(GL_LEQUAL);
      // Slope-scaled offset while baking: steep receivers need more.
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(1.5f * static_cast<float>(this->BiasScale), 2.0f * static_cast<float>(this->BiasScale));
      for (vtkActor* actor : casters)
      {
        auto& geometry = impl.Casters[actor];
        if (!geometry)
        {
          geometry.reset(new vtkShadowCasterGeometry);
        }
        geometry->Update(actor);
      }
      for (int t : dirty)
      {
        const Tile& tile = impl.Tiles[t];
        const int x = (t % columns) * resolution, y = (t / columns) * resolution;
        state->vtkglViewport(x, y, resolution, resolution);
        state->vtkglScissor(x, y, resolution, resolution);
        state->vtkglClearDepth(1.0);
        state->vtkglClear(GL_DEPTH_BUFFER_BIT);
        ++this->NumberOfMapsRendered;
        if (tile.View.texel_world <= 0.0)
        {
          continue; // an empty map
        }
        for (vtkActor* actor : casters)
        {
          vtkShadowCasterGeometry* geometry = impl.Casters[actor].get();
          if (geometry->GetNumberOfTriangles() == 0)
          {
            continue;
          }
          double modelRelative[16];
          geometry->GetModelRelativeMatrix(actor, cam.position, modelRelative);
          double mcdc[16];
          vsh_mat4_multiply(tile.View.world_to_clip, modelRelative, mcdc);
          float mcdcF[16];
          ToFloatTransposed(mcdc, mcdcF);
          program->SetUniformMatrix4x4("mapMCDC", mcdcF);
          geometry->Draw(program);
        }
      }
      glDisable(GL_POLYGON_OFFSET_FILL);
    }
    impl.FBO->RemoveDepthAttachment();
    state->PopFramebufferBindings();
    this->TotalMapsRendered += this->NumberOfMapsRendered;
  }
  for (auto it = impl.Casters.begin(); it != impl.Casters.end();)
  {
    if (std::find(casters.begin(), casters.end(), it->first) == casters.end())
    {
      it->second->ReleaseGraphicsResources(window);
      it = impl.Casters.erase(it);
    }
    else
    {
      ++it;
    }
  }

  // The scene, with every receiver's lighting reading the maps.
  impl.Atlas->Activate();
  this->RenderDelegateWithShaderHooks(s);
  impl.Atlas->Deactivate();
}

//------------------------------------------------------------------------------
bool vtkCascadedShadowMapPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  if (fragmentShader.find("//VTK::Light::Dec") == std::string::npos)
  {
    return true;
  }
  const Internals& impl = *this->Impl;
  // Compile-time filter, then the lookup functions, then one prologue that
  // calls the right lookup for each light that casts.
  std::string code = "#define VSH_FILTER " + std::to_string(this->Filter) +
    "\n#define VSH_PCF_HALF " + std::to_string(this->PCFSize / 2) + "\n" + vtkShadowMapLightFS +
    "void vshShadowPrepare(vec3 posVC, vec3 normalVC)\n{\n"
    "  float depth = -posVC.z;\n  float fade = vshShadowFade(depth);\n";
  for (int l = 0; l < MaxLights; ++l)
  {
    const std::string n = std::to_string(l);
    const int kind = l < impl.LightCount ? impl.Kind[l] : NoShadow;
    if (kind == Cascades)
    {
      code += "  vshShadowFactor[" + n + "] = mix(1.0, vshShadowCascades(" + n +
        ", depth, posVC, normalVC), fade);\n";
    }
    else if (kind == Spot)
    {
      code += "  vshShadowFactor[" + n + "] = mix(1.0, vshShadowSpot(" + n + ", posVC, normalVC), fade);\n";
    }
    else if (kind == Point)
    {
      code += "  vshShadowFactor[" + n + "] = mix(1.0, vshShadowPoint(" + n + ", posVC, normalVC), fade);\n";
    }
    else
    {
      code += "  vshShadowFactor[" + n + "] = 1.0;\n";
    }
  }
  code += "}\n";
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Dec", std::string("//VTK::Light::Dec\n") + code, false);
  return true;
}

//------------------------------------------------------------------------------
bool vtkCascadedShadowMapPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  if (fragmentShader.find("vshShadowPrepare") == std::string::npos)
  {
    return true;
  }
  if (vtkshadow::InjectLightFactors(fragmentShader, "vshShadowFactor[%d]",
        "vshShadowPrepare(vertexVC.xyz, normalize(normalVCVSOutput));", MaxLights))
  {
    // The debug view tints the final colour by cascade.
    const std::string output = "gl_FragData[0] = vec4(ambientColor + diffuse + specular, opacity);";
    vtkShaderProgram::Substitute(fragmentShader, output,
      output + "\n  if (vshDebugCascades != 0 && vshShadowCascadeShown >= 0) "
               "{ gl_FragData[0].rgb *= vshCascadeTint(vshShadowCascadeShown); }",
      false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkCascadedShadowMapPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp*, vtkOpenGLVertexArrayObject*)
{
  Internals& impl = *this->Impl;
  if (!impl.Atlas || !program->IsUniformUsed("vshShadowAtlas"))
  {
    return true;
  }
  const int tiles = std::min<int>(static_cast<int>(impl.Tiles.size()), MaxTiles);
  program->SetUniformi("vshShadowAtlas", impl.Atlas->GetTextureUnit());
  const float texel[2] = { 1.0f / std::max(impl.AtlasSize[0], 1), 1.0f / std::max(impl.AtlasSize[1], 1) };
  program->SetUniform2f("vshAtlasTexel", texel);
  program->SetUniformi("vshShadowLightCount", std::min(impl.LightCount, MaxLights));
  program->SetUniform1iv("vshShadowKind", MaxLights, impl.Kind);
  program->SetUniform1iv("vshShadowFirst", MaxLights, impl.First);
  program->SetUniform1iv("vshShadowCount", MaxLights, impl.Count);
  program->SetUniform3fv("vshShadowLightVC", MaxLights, impl.LightVC);
  program->SetUniformMatrix3x3("vshViewToWorld", impl.ViewToWorld);
  program->SetUniformf("vshPoissonRadius", static_cast<float>(this->PoissonRadius));
  program->SetUniformf("vshBlendBand", static_cast<float>(this->BlendBand));
  program->SetUniformf("vshShadowMaxDistance", impl.MaxDistance);
  program->SetUniformf("vshShadowFadeStart", impl.FadeStart);
  program->SetUniformi("vshDebugCascades", this->DebugCascades ? 1 : 0);
  if (tiles == 0)
  {
    return true;
  }
  // Per map: view coordinates -> map clip space (camera-relative, double),
  // its atlas rectangle, bias and far depth.
  std::vector<float> matrices(16 * tiles), rects(4 * tiles), bias(2 * tiles), fars(tiles),
    depth(2 * tiles, 0.0f);
  double viewToRelative[16];
  {
    // vshViewToWorld holds the transposed view rotation as floats; rebuild
    // the double version from the same numbers for the product.
    vsh_mat4_identity(viewToRelative);
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        viewToRelative[r * 4 + c] = impl.ViewToWorld[c * 3 + r];
      }
    }
  }
  for (int t = 0; t < tiles; ++t)
  {
    const Tile& tile = impl.Tiles[t];
    double m[16];
    vsh_mat4_multiply(tile.View.world_to_clip, viewToRelative, m);
    ToFloatTransposed(m, &matrices[16 * t]);
    const int columns = impl.TileGrid[0];
    const double w = static_cast<double>(this->UsedResolution) / impl.AtlasSize[0];
    const double h = static_cast<double>(this->UsedResolution) / impl.AtlasSize[1];
    rects[4 * t + 0] = static_cast<float>((t % columns) * w);
    rects[4 * t + 1] = static_cast<float>((t / columns) * h);
    rects[4 * t + 2] = static_cast<float>(w);
    rects[4 * t + 3] = static_cast<float>(h);
    bias[2 * t + 0] = static_cast<float>(tile.Bias[0]);
    bias[2 * t + 1] = static_cast<float>(tile.Bias[1]);
    fars[t] = static_cast<float>(tile.Far);
    if (tile.View.perspective)
    {
      double terms[2];
      vsh_csm_perspective_depth_terms(&tile.View, terms);
      depth[2 * t + 0] = static_cast<float>(terms[0]);
      depth[2 * t + 1] = static_cast<float>(terms[1]);
    }
  }
  program->SetUniformMatrix4x4v("vshTileMatrix", tiles, matrices.data());
  program->SetUniform4fv("vshTileRect", tiles, rects.data());
  program->SetUniform2fv("vshTileBias", tiles, bias.data());
  program->SetUniform1fv("vshTileFar", tiles, fars.data());
  program->SetUniform2fv("vshTileDepth", tiles, depth.data());
  return true;
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::ReleaseGraphicsResources(vtkWindow* w)
{
  Internals& impl = *this->Impl;
  if (impl.Atlas)
  {
    impl.Atlas->ReleaseGraphicsResources(w);
  }
  if (impl.FBO)
  {
    impl.FBO->ReleaseGraphicsResources(w);
  }
  impl.AtlasSize[0] = impl.AtlasSize[1] = 0;
  impl.Rendered.clear();
  for (auto& entry : impl.Casters)
  {
    entry.second->ReleaseGraphicsResources(w);
  }
  impl.Casters.clear();
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkCascadedShadowMapPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CascadeCount: " << this->CascadeCount << "\n";
  os << indent << "RatioPerCascade: " << this->RatioPerCascade << "\n";
  os << indent << "SplitScheme: " << this->SplitScheme << "\n";
  os << indent << "SplitLambda: " << this->SplitLambda << "\n";
  os << indent << "Stable: " << this->Stable << "\n";
  os << indent << "MapResolution: " << this->MapResolution << "\n";
  os << indent << "MaxTexelPixels: " << this->MaxTexelPixels << "\n";
  os << indent << "MemoryBudget: " << this->MemoryBudget << "\n";
  os << indent << "BiasScale: " << this->BiasScale << "\n";
  os << indent << "Filter: " << this->Filter << "\n";
  os << indent << "PCFSize: " << this->PCFSize << "\n";
  os << indent << "PoissonRadius: " << this->PoissonRadius << "\n";
  os << indent << "BlendBand: " << this->BlendBand << "\n";
  os << indent << "MaxShadowDistance: " << this->MaxShadowDistance << "\n";
  os << indent << "FadeFraction: " << this->FadeFraction << "\n";
  os << indent << "DebugCascades: " << this->DebugCascades << "\n";
  os << indent << "UsedResolution: " << this->UsedResolution << "\n";
  os << indent << "NumberOfMapsRendered: " << this->NumberOfMapsRendered << "\n";
  os << indent << "NumberOfMapsReused: " << this->NumberOfMapsReused << "\n";
  os << indent << "TotalMapsRendered: " << this->TotalMapsRendered << "\n";
}

//------------------------------------------------------------------------------
bool vtkCascadedShadowMapPass::SetOption(const char* key, double v)
{
  if (!key || !std::isfinite(v))
  {
    return false;
  }
  const std::string k = key;
  auto in = [&](double lo, double hi) { return v >= lo && v <= hi; };
  auto integral = [&](double lo, double hi) { return in(lo, hi) && v == std::floor(v); };
  const bool splitFraction = k.rfind("split_fraction_", 0) == 0 && k.size() == 16 &&
    k[15] >= '0' && k[15] <= '6';
  if (k == "map_resolution" && integral(16, 16384))
  {
    this->SetMapResolution(static_cast<int>(v));
  }
  else if (k == "cascades" && integral(0, 8))
  {
    this->SetCascadeCount(static_cast<int>(v));
  }
  else if (k == "ratio_per_cascade" && in(1.5, 1e6))
  {
    this->SetRatioPerCascade(v);
  }
  else if (k == "split" && integral(0, 3))
  {
    this->SetSplitScheme(static_cast<int>(v));
  }
  else if (k == "lambda" && in(0, 1))
  {
    this->SetSplitLambda(v);
  }
  else if (splitFraction && v > 0 && v < 1)
  {
    this->SetSplitFraction(k[15] - '0', v);
  }
  else if (k == "stable" && integral(0, 1))
  {
    this->SetStable(v != 0);
  }
  else if (k == "max_texel_px" && in(0, 1e6))
  {
    this->SetMaxTexelPixels(v);
  }
  else if (k == "memory_budget" && in(1 << 16, 1e12))
  {
    this->SetMemoryBudget(static_cast<long long>(v));
  }
  else if (k == "bias_scale" && in(0, 100))
  {
    this->SetBiasScale(v);
  }
  else if (k == "filter" && integral(0, 2))
  {
    this->SetFilter(static_cast<int>(v));
  }
  else if (k == "pcf_size" && integral(1, 9))
  {
    this->SetPCFSize(static_cast<int>(v));
  }
  else if (k == "poisson_radius" && in(0, 16))
  {
    this->SetPoissonRadius(v);
  }
  else if (k == "blend_band" && in(0, 0.5))
  {
    this->SetBlendBand(v);
  }
  else if (k == "max_distance" && in(0, 1e300))
  {
    this->SetMaxShadowDistance(v);
  }
  else if (k == "fade" && in(0, 1))
  {
    this->SetFadeFraction(v);
  }
  else if (k == "debug_cascades" && integral(0, 1))
  {
    this->SetDebugCascades(v != 0);
  }
  else
  {
    return this->Superclass::SetOption(key, v);
  }
  return true;
}

//------------------------------------------------------------------------------
std::string vtkCascadedShadowMapPass::GetStatsJSON(vtkRenderer* renderer) const
{
  std::ostringstream out;
  out.precision(6);
  out << "\"resolution\": " << this->UsedResolution
      << ", \"maps_rendered_total\": " << this->TotalMapsRendered
      << ", \"maps_reused_last_frame\": " << this->NumberOfMapsReused << ", \"lights\": [";
  const int lights = renderer ? renderer->GetLights()->GetNumberOfItems() : 0;
  for (int l = 0; l < lights; ++l)
  {
    const int cascades = this->GetNumberOfCascades(l);
    out << (l ? ", " : "") << "{\"cascades\": " << cascades << ", \"far\": [";
    for (int c = 0; c < cascades; ++c)
    {
      out << (c ? ", " : "") << this->GetCascadeFar(l, c);
    }
    out << "], \"texel_px\": [";
    for (int c = 0; c < cascades; ++c)
    {
      out << (c ? ", " : "") << this->GetCascadeTexelPixels(l, c);
    }
    out << "]}";
  }
  out << "]";
  return out.str();
}
