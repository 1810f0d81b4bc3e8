// vtkShadowCasterTriangles.h - the triangles of one caster actor on the CPU,
// as its mapper draws them (vtkPolyDataMapper, vtkCompositePolyDataMapper(2)
// with block visibility, vtkGlyph3DMapper with its per-glyph matrices).
//
// Shared by the GPU copy the map and planar passes draw
// (vtkShadowCasterGeometry) and the ray tracer's acceleration structure
// (vtkShadowEmbreeScene), so every technique casts exactly the same
// triangles.
#ifndef vtkShadowCasterTriangles_h
#define vtkShadowCasterTriangles_h

#include "vtkType.h"

#include <vector>

class vtkActor;

namespace vtkshadow
{
// Positions in the mapper's data coordinates minus Shift (the centre of the
// mapper's bounds), so float keeps precision far from the origin; three
// indices per triangle (polygons fanned, strips split).
struct CasterTriangles
{
  double Shift[3] = { 0, 0, 0 };
  std::vector<float> Vertices;
  std::vector<unsigned int> Indices;
  // Glyph instances baked in (vtkGlyph3DMapper: one per input point, each
  // its own connected component), 1 for other mappers.
  vtkIdType Instances = 1;
};

// When the caster's triangles last changed: its mapper, the mapper's input
// and a glyph mapper's source (not the actor: moving it changes no
// triangle). 0 when the actor has no mapper or no input.
vtkMTimeType CasterDataTime(vtkActor* actor);

// The triangles of the actor's mapper, in data coordinates (the actor's
// matrix is not applied). False when there is no mapper, no input or the
// bounds are empty; `out` may then hold nothing.
bool ExtractCasterTriangles(vtkActor* actor, CasterTriangles& out);
}

#endif
