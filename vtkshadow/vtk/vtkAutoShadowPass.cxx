#include "vtkAutoShadowPass.h"

#include "vtkActor.h"
#include "vtkDataObject.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
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
#include "vtkShadowReceiverPlane.h"
#include "vtkRenderer.h"

#include "vsh_auto.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkAutoShadowPass);

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
};
}

//------------------------------------------------------------------------------
vtkAutoShadowPass::vtkAutoShadowPass()
  : PlanarPass(vtkPlanarShadowPass::New())
  , CascadedPass(vtkCascadedShadowMapPass::New())
  , PlainPass(vtkRenderStepsPass::New())
  , Choice("none")
  , Reason("not rendered yet")
{
  // One scene pipeline for all three, so switching keeps VTK's passes.
  this->PlanarPass->SetDelegatePass(this->PlainPass);
  this->CascadedPass->SetDelegatePass(this->PlainPass);
}

//------------------------------------------------------------------------------
vtkAutoShadowPass::~vtkAutoShadowPass()
{
  this->PlanarPass->Delete();
  this->CascadedPass->Delete();
  this->PlainPass->Delete();
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::Decide(const vtkRenderState* s)
{
  vtkRenderer* renderer = s->GetRenderer();
  std::vector<Sphere> objects;
  bool anyReceiver = false, anyCaster = false;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    auto* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    if (!actor || !actor->GetVisibility() || !actor->GetMapper() ||
      actor->HasTranslucentPolygonalGeometry())
    {
      continue;
    }
    double b[6];
    actor->GetBounds(b);
    if (!vtkMath::AreBoundsInitialized(b))
    {
      continue;
    }
    Sphere sphere{ actor, { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) },
      0.5 * std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
              (b[5] - b[4]) * (b[5] - b[4])),
      vtkshadow::HasFlag(actor, vtkPlanarShadowPass::RECEIVER()), !vtkshadow::HasFlag(actor, vtkPlanarShadowPass::NO_CAST()),
      { b[0], b[1], b[2], b[3], b[4], b[5] }, false, { 0, 0, 0, 0 } };
    if (sphere.Receiver)
    {
      // Planes are recomputed only when the actor, its mapper or data change.
      CachedPlane& cached = this->Planes[actor];
      vtkMTimeType t = std::max(actor->GetMatrix()->GetMTime(), actor->GetMapper()->GetMTime());
      if (vtkDataObject* data = actor->GetMapper()->GetInputDataObject(0, 0))
      {
        t = std::max(t, data->GetMTime());
      }
      if (t > cached.Time || cached.Time == 0)
      {
        cached.Time = t;
        cached.Flat = vtkshadow::ReceiverPlane(actor, cached.Plane);
      }
      sphere.Flat = cached.Flat;
      std::copy_n(cached.Plane, 4, sphere.Plane);
    }
    anyReceiver = anyReceiver || sphere.Receiver;
    anyCaster = anyCaster || sphere.Casts;
    objects.push_back(sphere);
  }
  std::vector<std::vector<double>> lights;
  vtkLightCollection* collection = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  collection->InitTraversal(it);
  int index = -1;
  std::vector<int> lightIndex;
  while (vtkLight* light = collection->GetNextLight(it))
  {
    if (!light->GetSwitch())
    {
      continue;
    }
    ++index;
    if (light->LightTypeIsHeadlight())
    {
      continue; // its shadows hide behind the casters
    }
    double p[3], f[3];
    light->GetTransformedPosition(p);
    light->GetTransformedFocalPoint(f);
    lights.push_back(light->GetPositional()
        ? std::vector<double>{ p[0], p[1], p[2], 1.0 }
        : std::vector<double>{ p[0] - f[0], p[1] - f[1], p[2] - f[2], 0.0 });
    lightIndex.push_back(index);
  }
  if (lights.empty() || !anyCaster)
  {
    this->Choice = "none";
    this->Reason = lights.empty() ? "no light casts shadows" : "nothing casts shadows";
    return;
  }
  if (!anyReceiver)
  {
    this->Choice = "csm";
    this->Reason = "no plane receivers: shadows may fall on any surface";
    return;
  }
  // Self-shadowing: planar puts nothing on casters themselves, which is only
  // right for convex ones (their own shadow is the lighting's terminator).
  for (const Sphere& o : objects)
  {
    if (o.Receiver || !o.Casts)
    {
      continue;
    }
    vtkMTimeType t = std::max(o.Actor->GetMapper()->GetMTime(), o.Actor->GetMTime());
    if (vtkDataObject* data = o.Actor->GetMapper()->GetInputDataObject(0, 0))
    {
      t = std::max(t, data->GetMTime());
    }
    auto& cached = this->Convex[o.Actor];
    if (cached.first != t || t == 0)
    {
      vtkShadowCasterGeometry geometry;
      cached.first = t;
      cached.second = geometry.Update(o.Actor) && geometry.IsConvex();
    }
    if (!cached.second)
    {
      std::ostringstream why;
      why << "an object that is not convex (bounds centre " << o.Center[0] << ", " << o.Center[1]
          << ", " << o.Center[2] << ") may shadow itself";
      this->Choice = "csm";
      this->Reason = why.str();
      return;
    }
  }
  for (size_t l = 0; l < lights.size(); ++l)
  {
    for (const Sphere& a : objects)
    {
      if (!a.Casts)
      {
        continue;
      }
      for (const Sphere& b : objects)
      {
        if (&a == &b || b.Receiver)
        {
          continue;
        }
        const double* light = lights[l].data();
        // A plane receiver only blocks light from what lies behind it.
        if (a.Flat && vsh_auto_on_lit_side(a.Plane, light, b.Center, b.Radius))
        {
          continue;
        }
        bool may;
        if (light[3] == 0.0)
        {
          const double amin[3] = { a.Bounds[0], a.Bounds[2], a.Bounds[4] };
          const double amax[3] = { a.Bounds[1], a.Bounds[3], a.Bounds[5] };
          const double bmin[3] = { b.Bounds[0], b.Bounds[2], b.Bounds[4] };
          const double bmax[3] = { b.Bounds[1], b.Bounds[3], b.Bounds[5] };
          may = vsh_auto_box_may_shadow(amin, amax, bmin, bmax, light) != 0;
        }
        else
        {
          may = vsh_auto_may_shadow(a.Center, a.Radius, b.Center, b.Radius, light) != 0;
        }
        if (may)
        {
          std::ostringstream why;
          why << "light " << lightIndex[l] << ": an object (bounds centre " << a.Center[0] << ", "
              << a.Center[1] << ", " << a.Center[2] << ") may shadow a non-receiver (centre "
              << b.Center[0] << ", " << b.Center[1] << ", " << b.Center[2] << ")";
          this->Choice = "csm";
          this->Reason = why.str();
          return;
        }
      }
    }
  }
  this->Choice = "planar";
  this->Reason = "every shadow falls on plane receivers: planar is exact and cheapest";
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  const std::string previous = this->Choice;
  this->Decide(s);
  if (!previous.empty() && previous != this->Choice)
  {
    // The pass no longer used keeps no GL memory.
    vtkWindow* window = s->GetRenderer()->GetRenderWindow();
    if (previous == "planar")
    {
      this->PlanarPass->ReleaseGraphicsResources(window);
    }
    else if (previous == "csm")
    {
      this->CascadedPass->ReleaseGraphicsResources(window);
    }
  }
  vtkRenderPass* chosen = this->Choice == "planar" ? static_cast<vtkRenderPass*>(this->PlanarPass)
    : this->Choice == "csm"                        ? static_cast<vtkRenderPass*>(this->CascadedPass)
                                                   : static_cast<vtkRenderPass*>(this->PlainPass);
  chosen->Render(s);
  this->NumberOfRenderedProps = chosen->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->PlanarPass->ReleaseGraphicsResources(w);
  this->CascadedPass->ReleaseGraphicsResources(w);
  this->PlainPass->ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkAutoShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Choice: " << this->Choice << "\n";
  os << indent << "Reason: " << this->Reason << "\n";
}
