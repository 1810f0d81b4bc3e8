// vtkShadowActorFlags.cxx - the one traversal of a renderer's props into
// the actors that cast and receive (see the header).
#include "vtkShadowActorFlags.h"

#include "vsh_transmit.h"

#include "vtkProperty.h"

#include "vtkAssemblyNode.h"
#include "vtkAssemblyPath.h"
#include "vtkBoundingBox.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShadowPassBase.h"
#include "vtkVolume.h"

#include "vsh_mat4.h"

#include <map>

namespace
{
// World bounds of an actor drawn with `matrix`: its mapper's bounds through
// the matrix, as vtkActor::GetBounds does with the actor's own matrix (a
// part's own GetBounds would use its matrix relative to the assembly).
void PathBounds(vtkActor* actor, const double matrix[16], double out[6])
{
  const double* b = actor->GetMapper()->GetBounds();
  vtkMath::UninitializeBounds(out);
  if (!b || !vtkMath::AreBoundsInitialized(b))
  {
    return;
  }
  vtkBoundingBox box;
  for (int corner = 0; corner < 8; ++corner)
  {
    const double p[3] = { b[corner & 1], b[2 + ((corner >> 1) & 1)], b[4 + ((corner >> 2) & 1)] };
    double w[3];
    vsh_mat4_transform_point(matrix, p, w);
    box.AddPoint(w);
  }
  box.GetBounds(out);
}

// Appends the opaque actors `root` draws to `out` (`translucent`: the
// translucent ones whose property's opacity is below 1 instead), numbering
// repeated actors in `seen`.
void AppendShadowActors(vtkProp* root, std::vector<vtkshadow::ShadowActor>& out,
  std::map<vtkActor*, int>& seen, bool translucent = false)
{
  vtkshadow::ForEachPathActor(root,
    [&](vtkActor* actor, const double* matrix)
    {
      if (actor->HasTranslucentPolygonalGeometry() != translucent ||
        (translucent && vtkshadow::CasterOpacity(actor) >= 1.0))
      {
        return;
      }
      vtkshadow::ShadowActor a{ actor, root, {}, {}, 0 };
      std::copy_n(matrix, 16, a.Matrix);
      if (actor == root)
      {
        actor->GetBounds(a.Bounds);
      }
      else
      {
        PathBounds(actor, matrix, a.Bounds);
      }
      if (vtkMath::AreBoundsInitialized(a.Bounds))
      {
        a.Instance = seen[actor]++;
        out.push_back(a);
      }
    });
}
}

namespace vtkshadow
{
//------------------------------------------------------------------------------
void ForEachPathActor(vtkProp* root, const std::function<void(vtkActor*, const double*)>& visit)
{
  if (!root || !root->GetVisibility())
  {
    return;
  }
  double matrix[16];
  if (auto* actor = vtkActor::SafeDownCast(root))
  {
    // A plain actor's own path is built once and keeps the matrix of that
    // moment: its live matrix is the one VTK draws with.
    if (actor->GetMapper())
    {
      vtkMatrix4x4::DeepCopy(matrix, actor->GetMatrix());
      visit(actor, matrix);
    }
    return;
  }
  root->InitPathTraversal();
  while (vtkAssemblyPath* path = root->GetNextPath())
  {
    vtkAssemblyNode* node = path->GetLastNode();
    auto* actor = node ? vtkActor::SafeDownCast(node->GetViewProp()) : nullptr;
    if (!actor || !actor->GetVisibility() || !actor->GetMapper())
    {
      continue;
    }
    // A node without a matrix is drawn unpoked, with the part's own.
    vtkMatrix4x4::DeepCopy(matrix, node->GetMatrix() ? node->GetMatrix() : actor->GetMatrix());
    visit(actor, matrix);
  }
}

//------------------------------------------------------------------------------
std::vector<ShadowActor> ShadowActors(const vtkRenderState* s)
{
  std::vector<ShadowActor> out;
  std::map<vtkActor*, int> seen;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    AppendShadowActors(s->GetPropArray()[i], out, seen);
  }
  return out;
}

//------------------------------------------------------------------------------
// The actors of the renderer's props (opaque, or the translucent ones).
std::vector<ShadowActor> RendererActors(vtkRenderer* renderer, bool translucent)
{
  std::vector<ShadowActor> out;
  std::map<vtkActor*, int> seen;
  vtkPropCollection* props = renderer ? renderer->GetViewProps() : nullptr;
  if (!props)
  {
    return out;
  }
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    AppendShadowActors(prop, out, seen, translucent);
  }
  return out;
}

//------------------------------------------------------------------------------
std::vector<ShadowActor> ShadowActors(vtkRenderer* renderer)
{
  return RendererActors(renderer, false);
}

//------------------------------------------------------------------------------
double CasterOpacity(vtkActor* actor)
{
  vtkProperty* property = actor ? actor->GetProperty() : nullptr;
  const double opacity = property ? property->GetOpacity() : 1.0;
  return opacity == opacity ? std::min(std::max(opacity, 0.0), 1.0) : 1.0;
}

//------------------------------------------------------------------------------
bool CasterTransmit(const ShadowActor& a, double transmit[3])
{
  double filter = 0.0;
  for (vtkProp* prop : { static_cast<vtkProp*>(a.Actor), a.Root })
  {
    vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
    if (keys && keys->Has(vtkShadowPassBase::FILTER()))
    {
      filter = keys->Get(vtkShadowPassBase::FILTER());
      break;
    }
  }
  filter = filter == filter ? std::min(std::max(filter, 0.0), 1.0) : 0.0;
  double colour[3] = { 1.0, 1.0, 1.0 };
  if (vtkProperty* property = a.Actor ? a.Actor->GetProperty() : nullptr)
  {
    property->GetDiffuseColor(colour);
  }
  vsh_transmit_crossing(colour, CasterOpacity(a.Actor), filter, transmit);
  return filter > 0.0 && (transmit[0] != transmit[1] || transmit[1] != transmit[2]);
}

//------------------------------------------------------------------------------
std::vector<ShadowActor> TranslucentShadowActors(vtkRenderer* renderer)
{
  return RendererActors(renderer, true);
}

//------------------------------------------------------------------------------
bool HasVisibleVolumes(vtkRenderer* renderer)
{
  vtkPropCollection* props = renderer ? renderer->GetViewProps() : nullptr;
  if (!props)
  {
    return false;
  }
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    if (prop->GetVisibility() && vtkVolume::SafeDownCast(prop))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
bool HasTintingCaster(const std::vector<ShadowActor>& translucent, vtkInformationIntegerKey* noCast)
{
  for (const ShadowActor& a : translucent)
  {
    double transmit[3];
    if (CastsAsSurface(a, noCast) && CasterTransmit(a, transmit))
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
vtkInformation* FlagKeys(const ShadowActor& a, vtkInformationIntegerKey* key)
{
  for (vtkProp* prop : { static_cast<vtkProp*>(a.Actor), a.Root })
  {
    vtkInformation* keys = prop ? prop->GetPropertyKeys() : nullptr;
    if (keys && keys->Has(key))
    {
      return keys;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
bool CastsAsSurface(const ShadowActor& a, vtkInformationIntegerKey* noCast)
{
  vtkProperty* property = a.Actor->GetProperty();
  return !HasFlag(a, noCast) && (!property || property->GetRepresentation() == VTK_SURFACE);
}
}
