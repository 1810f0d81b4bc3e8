// vtkShadowActorFlags.h - read and set the integer shadow flags that
// actors carry in their property keys (vtkPlanarShadowPass::RECEIVER(),
// NO_CAST()); shared by every pass and the C API.
#ifndef vtkShadowActorFlags_h
#define vtkShadowActorFlags_h

#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkNew.h"
#include "vtkProp.h"

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
}

#endif
