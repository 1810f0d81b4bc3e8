#include "vtkAutoShadowPass.h"

#include "vtkCamera.h"

#include "vtkActor.h"
#include "vtkDataObject.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkCascadedShadowMapPass.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPlanarShadowPass.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowCasterGeometry.h"
#include "vtkShadowLightingHook.h"
#include "vtkShadowReceiverPlane.h"
#include "vtkRenderer.h"

#include "vsh_auto.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkAutoShadowPass);

struct vtkAutoShadowPass::Internals
{
  struct Caster
  {
    vtkShadowCasterGeometry Geometry;
    vtkMTimeType MeshTime = 0;
    bool Convex = false;
    // Silhouette length (data units) per light, with the light (data
    // coordinates) it was computed for.
    std::map<int, std::pair<std::vector<double>, double>> Silhouette;
  };
  std::map<vtkProp*, std::unique_ptr<Caster>> Casters;

  // The caster's mesh analysis, redone only when the mesh changes: its
  // convexity and silhouettes survive every affine placement, so the
  // actor's own MTime (which VTK's pass machinery bumps) does not count.
  Caster& For(vtkActor* actor)
  {
    auto& caster = this->Casters[actor];
    if (!caster)
    {
      caster.reset(new Caster);
    }
    const vtkMTimeType t = vtkshadow::MeshTime(actor);
    if (caster->MeshTime != t || t == 0)
    {
      caster->MeshTime = t;
      caster->Convex = caster->Geometry.Update(actor) && caster->Geometry.IsConvex();
      caster->Silhouette.clear();
    }
    return *caster;
  }
};

namespace
{

struct Sphere
{
  vtkActor* Actor;
  double Center[3];
  double Radius;
  bool Receiver;
  bool Casts;
  double Bounds[6];
  bool Flat;       // a receiver with a plane
  double Plane[4];
  bool InView;     // its bounding sphere meets the view frustum
};

std::string Centre(const char* what, const Sphere& o)
{
  std::ostringstream out;
  out << what << " (bounds centre " << o.Center[0] << ", " << o.Center[1] << ", " << o.Center[2]
      << ")";
  return out.str();
}
}

//------------------------------------------------------------------------------
vtkAutoShadowPass::vtkAutoShadowPass()
  : PlanarPass(vtkPlanarShadowPass::New())
  , CascadedPass(vtkCascadedShadowMapPass::New())
  , Choice("none")
  , Reason("not rendered yet")
  , MaxError(0.5)
  , MaxTexelPixels(0.0)
  , UsedTexelTarget(0.0)
  , UsedStretch(1.0)
  , UsedEdgeLength(0.0)
  , Impl(new Internals)
{
}

//------------------------------------------------------------------------------
vtkAutoShadowPass::~vtkAutoShadowPass()
{
  this->PlanarPass->Delete();
  this->CascadedPass->Delete();
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::Decide(const vtkRenderState* s)
{
  vtkRenderer* renderer = s->GetRenderer();
  double frustum[24];
  renderer->GetActiveCamera()->GetFrustumPlanes(renderer->GetTiledAspectRatio(), frustum);
  std::vector<Sphere> objects;
  bool anyCaster = false;
  for (const vtkshadow::ShadowActor& shadowActor : vtkshadow::ShadowActors(s))
  {
    vtkActor* actor = shadowActor.Actor;
    const double* b = shadowActor.Bounds;
    Sphere sphere{ actor, { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) },
      0.5 * std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
              (b[5] - b[4]) * (b[5] - b[4])),
      vtkshadow::HasFlag(actor, vtkShadowPassBase::RECEIVER()),
      !vtkshadow::HasFlag(actor, vtkShadowPassBase::NO_CAST()),
      { b[0], b[1], b[2], b[3], b[4], b[5] }, false, { 0, 0, 0, 0 }, true };
    // Frustum planes point inwards: a sphere wholly outside one is not seen.
    for (int p = 0; p < 6 && sphere.InView; ++p)
    {
      const double* plane = frustum + 4 * p;
      const double n = std::sqrt(plane[0] * plane[0] + plane[1] * plane[1] + plane[2] * plane[2]);
      sphere.InView = plane[0] * sphere.Center[0] + plane[1] * sphere.Center[1] +
          plane[2] * sphere.Center[2] + plane[3] >=
        -sphere.Radius * n;
    }
    if (sphere.Receiver)
    {
      // Planes are recomputed only when the actor, its mapper or data change.
      CachedPlane& cached = this->Planes[actor];
      const vtkMTimeType t = std::max(actor->GetMatrix()->GetMTime(), vtkshadow::MeshTime(actor));
      if (t > cached.Time || cached.Time == 0)
      {
        cached.Time = t;
        cached.Flat = vtkshadow::ReceiverPlane(actor, cached.Plane);
      }
      sphere.Flat = cached.Flat;
      std::copy_n(cached.Plane, 4, sphere.Plane);
    }
    anyCaster = anyCaster || sphere.Casts;
    objects.push_back(sphere);
  }

  // Self-shadowing: planar puts nothing on casters themselves, which is only
  // right for convex ones (their own shadow is the lighting's terminator).
  const Sphere* concave = nullptr;
  for (const Sphere& o : objects)
  {
    if (o.Receiver || !o.Casts || !o.InView)
    {
      continue;
    }
    if (!this->Impl->For(o.Actor).Convex)
    {
      concave = &o;
      break;
    }
  }

  // Each switched-on light, in the mapper's numbering.
  this->LightChoices.clear();
  this->LightReasons.clear();
  double stretch = 1.0, edgeLength = 0.0;
  for (vtkLight* light : vtkshadow::SwitchedOnLights(renderer))
  {
    std::string choice = "none", reason;
    double homogeneous[4];
    vtkshadow::LightHomogeneous(light, homogeneous);
    if (light->LightTypeIsHeadlight())
    {
      reason = "the headlight: its shadows hide behind the casters";
    }
    else if (!anyCaster)
    {
      reason = "nothing casts shadows";
    }
    else if (concave)
    {
      choice = "csm";
      reason = Centre("an object that is not convex", *concave) + " may shadow itself";
    }
    else
    {
      bool anyShadow = false;
      for (const Sphere& a : objects)
      {
        for (const Sphere& b : objects)
        {
          if (!a.Casts || &a == &b || !b.InView ||
            (a.Flat && vsh_auto_on_lit_side(a.Plane, homogeneous, b.Center, b.Radius)))
          {
            continue; // a plane receiver only blocks light from what lies behind it
          }
          bool may;
          if (homogeneous[3] == 0.0)
          {
            const double amin[3] = { a.Bounds[0], a.Bounds[2], a.Bounds[4] };
            const double amax[3] = { a.Bounds[1], a.Bounds[3], a.Bounds[5] };
            const double bmin[3] = { b.Bounds[0], b.Bounds[2], b.Bounds[4] };
            const double bmax[3] = { b.Bounds[1], b.Bounds[3], b.Bounds[5] };
            may = vsh_auto_box_may_shadow(amin, amax, bmin, bmax, homogeneous) != 0;
          }
          else
          {
            may = vsh_auto_may_shadow(a.Center, a.Radius, b.Center, b.Radius, homogeneous) != 0;
          }
          if (!may)
          {
            continue;
          }
          anyShadow = true;
          if (!(b.Receiver && b.Flat))
          {
            choice = "csm";
            reason = Centre("an object", a) + " may shadow " +
              Centre(b.Receiver ? "a receiver that is not a plane" : "a non-receiver", b);
            break;
          }
        }
        if (choice == "csm")
        {
          break;
        }
      }
      if (choice != "csm")
      {
        choice = anyShadow ? "planar" : "none";
        reason = anyShadow ? "every shadow falls on plane receivers: planar is exact and cheapest"
                           : "no caster can shadow a visible object";
      }
    }
    if (choice == "csm" && !light->LightTypeIsHeadlight())
    {
      // The outline of every shadow this light's map must draw: the
      // silhouettes of the (non-receiver) casters in view, in pixels.
      double outline = 0.0;
      const int index = static_cast<int>(this->LightChoices.size());
      for (const Sphere& o : objects)
      {
        if (o.Casts && !o.Receiver && o.InView)
        {
          outline +=
            this->OutlinePixels(o.Actor, homogeneous, index, o.Center, o.Radius, renderer);
        }
      }
      edgeLength = std::max(edgeLength, outline);
      // Light at a grazing angle to a plane receiver stretches shadows, and
      // their boundaries, by 1 / cos(incidence) (at the receiver's centre).
      for (const Sphere& r : objects)
      {
        if (!r.Flat || !r.InView)
        {
          continue;
        }
        double towards[3];
        for (int k = 0; k < 3; ++k)
        {
          towards[k] = homogeneous[k] - homogeneous[3] * r.Center[k];
        }
        const double len = vtkMath::Norm(towards), n = vtkMath::Norm(r.Plane);
        if (len > 0.0 && n > 0.0)
        {
          const double c = std::abs(vtkMath::Dot(towards, r.Plane)) / (len * n);
          stretch = std::max(stretch, 1.0 / std::max(c, 1.0 / 64.0));
        }
      }
    }
    this->LightChoices.push_back(choice);
    this->LightReasons.push_back(reason);
  }

  // One frame for all lights: each pass skips the lights the other one has.
  unsigned int planarLights = 0, csmLights = 0;
  for (size_t l = 0; l < this->LightChoices.size() && l < 32; ++l)
  {
    planarLights |= (this->LightChoices[l] == "planar" ? 1u : 0u) << l;
    csmLights |= (this->LightChoices[l] == "csm" ? 1u : 0u) << l;
  }
  this->PlanarPass->SetSkippedLights(~planarLights);
  this->CascadedPass->SetSkippedLights(~csmLights);
  const int* size = renderer->GetSize();
  this->UsedTexelTarget = this->MaxTexelPixels > 0.0
    ? this->MaxTexelPixels
    // A shadow boundary as long as the viewport's perimeter, one-pixel band.
    : vsh_auto_texel_target(this->MaxError, static_cast<double>(size[0]) * size[1],
        std::max(edgeLength, 1.0), stretch, 1.0);
  this->UsedStretch = stretch;
  this->UsedEdgeLength = edgeLength;
  this->CascadedPass->SetMaxTexelPixels(this->UsedTexelTarget);
  this->Choice = planarLights && csmLights ? "planar+csm"
    : planarLights                         ? "planar"
    : csmLights                            ? "csm"
                                           : "none";
  if (this->LightChoices.empty())
  {
    this->Reason = "no light is switched on";
    return;
  }
  std::ostringstream why;
  for (size_t l = 0; l < this->LightChoices.size(); ++l)
  {
    why << (l ? "; " : "") << "light " << l << ": " << this->LightChoices[l] << " ("
        << this->LightReasons[l] << ")";
  }
  this->Reason = why.str();
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  const std::string previous = this->Choice;
  this->Decide(s);
  const bool planar = this->Choice.find("planar") != std::string::npos;
  const bool csm = this->Choice.find("csm") != std::string::npos;
  // A pass no longer used keeps no GL memory.
  vtkWindow* window = s->GetRenderer()->GetRenderWindow();
  if (!planar && previous.find("planar") != std::string::npos)
  {
    this->PlanarPass->ReleaseGraphicsResources(window);
  }
  if (!csm && previous.find("csm") != std::string::npos)
  {
    this->CascadedPass->ReleaseGraphicsResources(window);
  }
  // The chosen passes in a chain in front of the one scene pipeline (this
  // pass's delegate), so switching keeps VTK's passes: each does its shadow
  // work for its lights, then renders through the next.
  vtkRenderPass* next = this->EnsureDelegatePass();
  vtkShadowPassBase* const candidates[] = { this->PlanarPass, this->CascadedPass };
  const bool used[] = { planar, csm };
  for (int i = 0; i < 2; ++i)
  {
    if (used[i])
    {
      candidates[i]->SetDelegatePass(next);
      next = candidates[i];
    }
  }
  next->Render(s);
  this->NumberOfRenderedProps = next->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
double vtkAutoShadowPass::OutlinePixels(vtkActor* actor, const double light[4], int index,
  const double center[3], double radius, vtkRenderer* renderer)
{
  // One pixel's world size at the caster's distance from the camera.
  vtkCamera* camera = renderer->GetActiveCamera();
  double eye[3], focal[3], clip[2];
  camera->GetPosition(eye);
  camera->GetFocalPoint(focal);
  camera->GetClippingRange(clip);
  double forward[3] = { focal[0] - eye[0], focal[1] - eye[1], focal[2] - eye[2] };
  vtkMath::Normalize(forward);
  const double toCenter[3] = { center[0] - eye[0], center[1] - eye[1], center[2] - eye[2] };
  const double depth = std::max(vtkMath::Dot(toCenter, forward), clip[0]);
  const int height = std::max(renderer->GetSize()[1], 1);
  const double pixel =
    2.0 * depth * std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2.0) / height;
  if (!(pixel > 0.0))
  {
    return 0.0;
  }
  // The silhouette seen from the light, in the mesh's own coordinates
  // (cached per light while the light and mesh stay put), then to world
  // units by the actor's scale. A mesh that is not closed has no defined
  // silhouette: its bounding sphere's great circle stands in.
  double world = 2.0 * vtkMath::Pi() * radius;
  Internals::Caster& caster = this->Impl->For(actor);
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(actor->GetMatrix(), inverse);
  double inData[4];
  inverse->MultiplyPoint(light, inData);
  auto& cached = caster.Silhouette[index];
  const std::vector<double> key(inData, inData + 4);
  if (cached.first != key)
  {
    cached.first = key;
    cached.second = caster.Geometry.GetSilhouetteLength(inData);
  }
  if (cached.second >= 0.0)
  {
    double linear[3][3];
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        linear[r][c] = actor->GetMatrix()->GetElement(r, c);
      }
    }
    world = cached.second * std::cbrt(std::abs(vtkMath::Determinant3x3(linear)));
  }
  return world / pixel;
}

//------------------------------------------------------------------------------
const char* vtkAutoShadowPass::GetLightChoice(int light) const
{
  return light >= 0 && light < this->GetNumberOfLightChoices() ? this->LightChoices[light].c_str()
                                                                : nullptr;
}

//------------------------------------------------------------------------------
const char* vtkAutoShadowPass::GetLightReason(int light) const
{
  return light >= 0 && light < this->GetNumberOfLightChoices() ? this->LightReasons[light].c_str()
                                                                : nullptr;
}

//------------------------------------------------------------------------------
long long vtkAutoShadowPass::GetMemoryBytes() const
{
  long long bytes = 0;
  if (this->Choice.find("planar") != std::string::npos)
  {
    bytes += this->PlanarPass->GetMemoryBytes();
  }
  if (this->Choice.find("csm") != std::string::npos)
  {
    bytes += this->CascadedPass->GetMemoryBytes();
  }
  return bytes;
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->PlanarPass->ReleaseGraphicsResources(w);
  this->CascadedPass->ReleaseGraphicsResources(w);
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaxError: " << this->MaxError << "\n";
  os << indent << "MaxTexelPixels: " << this->MaxTexelPixels << "\n";
  os << indent << "UsedTexelTarget: " << this->UsedTexelTarget << "\n";
  os << indent << "UsedStretch: " << this->UsedStretch << "\n";
  os << indent << "UsedEdgeLength: " << this->UsedEdgeLength << "\n";
  os << indent << "Choice: " << this->Choice << "\n";
  os << indent << "Reason: " << this->Reason << "\n";
}

//------------------------------------------------------------------------------
bool vtkAutoShadowPass::SetOption(const char* key, double value)
{
  if (!key || !std::isfinite(value))
  {
    return false;
  }
  const std::string k = key;
  if (k == "max_error" && value >= 0.0 && value <= 100.0)
  {
    this->SetMaxError(value);
    return true;
  }
  if (k == "max_texel_px" && value >= 0.0 && value <= 1e6)
  {
    this->SetMaxTexelPixels(value);
    return true;
  }
  if (k == "max_error" || k == "max_texel_px")
  {
    return false;
  }
  return this->CascadedPass->SetOption(key, value) || this->PlanarPass->SetOption(key, value);
}

//------------------------------------------------------------------------------
std::string vtkAutoShadowPass::GetStatsJSON(vtkRenderer* renderer) const
{
  std::string reason = this->Reason;
  for (size_t at = reason.find('"'); at != std::string::npos; at = reason.find('"', at + 2))
  {
    reason.insert(at, "\\");
  }
  std::ostringstream out;
  out.precision(6);
  out << "\"choice\": \"" << this->Choice << "\", \"reason\": \"" << reason << "\""
      << ", \"texel_target_px\": " << this->UsedTexelTarget
      << ", \"texel_stretch\": " << this->UsedStretch
      << ", \"edge_length_px\": " << this->UsedEdgeLength << ", \"light_choices\": [";
  for (size_t l = 0; l < this->LightChoices.size(); ++l)
  {
    out << (l ? ", " : "") << "\"" << this->LightChoices[l] << "\"";
  }
  out << "]";
  // Details of the map pass when there is one, else of the planar pass.
  const vtkShadowPassBase* details = this->Choice.find("csm") != std::string::npos
    ? static_cast<vtkShadowPassBase*>(this->CascadedPass)
    : this->Choice == "planar" ? static_cast<vtkShadowPassBase*>(this->PlanarPass)
                               : nullptr;
  if (details)
  {
    out << ", " << details->GetStatsJSON(renderer);
  }
  return out.str();
}
