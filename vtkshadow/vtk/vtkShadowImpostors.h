// vtkShadowImpostors.h - the points and lines an actor's mapper draws as
// screen-space solids, RenderPointsAsSpheres' sphere impostors and
// RenderLinesAsTubes' tube impostors, on the CPU, for the ray tracer's
// spheres and round curves (vtkShadowEmbreeScene) and the other
// techniques' triangle proxies (vtkShadowImpostorProxies). Their world size is not
// in the data: it is a width in pixels, so the tracer sizes them per frame
// (vsh_rt_impostor_radius).
//
// Plain points and lines (flat square sprites and bands, the default) cast
// nothing: VTK draws no solid there, they are mostly annotations (outlines,
// wireframe overlays) that every other technique but csm leaves out too, and
// a line a pixel wide would cast a shadow thinner than a pixel that breaks
// up into dots. Surface edges (EdgeVisibility) lie on the surface, which
// casts.
#ifndef vtkShadowImpostors_h
#define vtkShadowImpostors_h

#include "vtkType.h"

#include <vector>

class vtkActor;

namespace vtkshadow
{
// In the mapper's data coordinates (the actor's matrix is not applied).
struct Impostors
{
  // Points drawn as spheres: the centres, x y z.
  std::vector<double> Points;
  double PointSize = 1.0; // pixels across (vtkProperty::GetPointSize)
  // Lines drawn as tubes: each run of LineVertices (x y z) is one
  // polyline; Segments holds the first vertex of every segment (vertex s to
  // s + 1), Embree's index buffer for linear curves.
  std::vector<double> LineVertices;
  std::vector<unsigned int> Segments;
  double LineWidth = 1.0; // pixels across (vtkProperty::GetLineWidth)

  bool Empty() const { return this->Points.empty() && this->Segments.empty(); }
};

// What the actor's vtkPolyDataMapper draws as spheres and tubes, as VTK
// 9.1 decides (vtkOpenGLPolyDataMapper::DrawingSpheres / DrawingTubes, its
// GetOpenGLMode): with RenderPointsAsSpheres, verts cells always and every
// point of its cells with Representation Points; with RenderLinesAsTubes
// and a line width above 1, line cells with Representation Surface or
// Wireframe, and with Wireframe the polygons' edges too (each edge once). Only a vtkPolyData input
// (not composite data or glyph mappers: their points and lines are left out). False when there is
// nothing.
bool ExtractImpostors(vtkActor* actor, Impostors& out);

// When what ExtractImpostors gives last changed: the mapper's data
// (CasterDataTime) and the actor's property (representation, sizes).
vtkMTimeType ImpostorTime(vtkActor* actor);
}

#endif
