// vtkShadowActorFlags.h - which actors take part in shadows, and the
// integer shadow flags they carry in their property keys
// (vtkShadowPassBase::RECEIVER(), NO_CAST()); shared by every pass and the
// C API.
#ifndef vtkShadowActorFlags_h
#define vtkShadowActorFlags_h

#include "vtkActor.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkProp.h"
#include "vtkPropCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <vector>

namespace vtkshadow
{
// True when `prop` carries `key` with a non-zero value.
inline bool HasFlag(vtkProp* prop, vtkInformationIntegerKey* key)
{
  vtkInformation* info = prop->GetPropertyKeys();
  return info && info->Has(key) && info->Get(key) != 0;
}

// Set `key` on an actor, creating its property keys when it has none.
inline void SetFlag(vtkActor* actor, vtkInformationIntegerKey* key, int value)
{
  if (!actor->GetPropertyKeys())
  {
    vtkNew<vtkInformation> keys;
    actor->SetPropertyKeys(keys);
  }
  actor->GetPropertyKeys()->Set(key, value);
  actor->Modified();
}

// When the actor's mesh last changed: its mapper or the mapper's input.
// (Not the actor's own MTime: VTK's pass machinery bumps it when it gives
// actors property keys. The placement is actor->GetMatrix()->GetMTime().)
inline vtkMTimeType MeshTime(vtkActor* actor)
{
  vtkMTimeType t = actor->GetMapper()->GetMTime();
  if (vtkDataObject* data = actor->GetMapper()->GetInputDataObject(0, 0))
  {
    t = std::max(t, data->GetMTime());
  }
  return t;
}

// An actor that takes part in the shadows of a frame, with its world bounds
// (VTK order).
struct ShadowActor
{
  vtkActor* Actor;
  double Bounds[6];
};

// Appends `prop` to `out` when it can cast or receive: an actor, visible,
// with a mapper, opaque (translucent geometry neither blocks nor shows
// shadows here) and with initialised bounds.
inline void AppendShadowActor(vtkProp* prop, std::vector<ShadowActor>& out)
{
  auto* actor = vtkActor::SafeDownCast(prop);
  if (!actor || !actor->GetVisibility() || !actor->GetMapper() ||
    actor->HasTranslucentPolygonalGeometry())
  {
    return;
  }
  ShadowActor a{ actor, { 0, 0, 0, 0, 0, 0 } };
  actor->GetBounds(a.Bounds);
  if (vtkMath::AreBoundsInitialized(a.Bounds))
  {
    out.push_back(a);
  }
}

// The render state's actors that can cast or receive. VTK's frustum culler
// has dropped the props outside the view from this list: right for what the
// frame draws, wrong for casters (see the overload below).
inline std::vector<ShadowActor> ShadowActors(const vtkRenderState* s)
{
  std::vector<ShadowActor> out;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    AppendShadowActor(s->GetPropArray()[i], out);
  }
  return out;
}

// The renderer's actors that can cast or receive, from its props rather than
// the render state's frustum-culled ones: a caster behind the camera (or
// beside the view) still throws its shadow into the view.
inline std::vector<ShadowActor> ShadowActors(vtkRenderer* renderer)
{
  std::vector<ShadowActor> out;
  vtkPropCollection* props = renderer ? renderer->GetViewProps() : nullptr;
  if (!props)
  {
    return out;
  }
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* prop = props->GetNextProp(it))
  {
    AppendShadowActor(prop, out);
  }
  return out;
}
}

#endif
