// vtkShadowScenePrimitives.h - what vtkShadowScene draws for the scene
// format's objects without a surface: "points" as VTK's sphere impostors,
// "polyline" as its tube impostor, "volume" as a volume-rendered blob
// (docs/scene-format.md). The ray tracers get the solids these show
// (vsh_object_tessellate); VTK gets the primitives a user's program has.
#ifndef vtkShadowScenePrimitives_h
#define vtkShadowScenePrimitives_h

#include "vtkSmartPointer.h"

class vtkActor;
class vtkPolyData;
class vtkVolume;
struct vsh_object;

namespace vtkshadow
{
// The vertices (points) or the one polyline cell (polyline) of the object.
vtkSmartPointer<vtkPolyData> NewImpostorPolyData(const vsh_object& object);

// An actor drawing `data` with RenderPointsAsSpheres or RenderLinesAsTubes
// at the object's pixel size times `pixelScale` (the window's height over
// the scene's: the impostors keep the world size the scene gives them).
vtkSmartPointer<vtkActor> NewImpostorActor(
  const vsh_object& object, vtkPolyData* data, double pixelScale);

// The blob as a vtkVolume: extinction density * max(0, 1 - d / radius)
// sampled on samples^3 points over its box, a scalar opacity transfer
// function that keeps exp(-extinction * step) per step (VTK's opacity
// correction at unit distance `radius`), colour `color` (black: the
// visibility renders, where it must add nothing of its own), no shading.
vtkSmartPointer<vtkVolume> NewBlobVolume(const vsh_object& object, const double color[3]);
}

#endif
