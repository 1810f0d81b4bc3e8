// vtkShadowImpostors.h - the points and lines an actor's mapper draws as
// screen-space shapes, on the CPU, for the ray tracer (vtkShadowEmbreeScene)
// and the other techniques' triangle proxies (vtkShadowImpostorProxies):
//
// - RenderPointsAsSpheres' sphere impostors and RenderLinesAsTubes' tube
//   impostors: spheres and round tubes;
// - vtkPointGaussianMapper's splats: a sphere per splat of the splat's
//   radius (world units, from ScaleFactor and the ScaleArray): the Gaussian
//   is drawn on a camera-facing triangle with no thickness, and its
//   standard deviation is that radius, where SplatShaderCode's usual
//   discard (offset length above 1) cuts the disc too; the sphere is the
//   solid that shows that disc from every side;
// - plain points and lines wider than a pixel: the square sprites and
//   bands VTK draws, flat quads facing the camera.
//
// Pixel sizes are not in the data: they are a width on screen, so those
// shapes are sized per frame (vsh_rt_impostor_radius); splats are not.
//
// What does not cast (docs/enable-shadows.md, "Points, lines and splats"):
// points and lines one pixel wide or less (VTK's default, that of
// outlines, grids and hairline wireframes: their shadow would be under a
// pixel wide and break up into dots), surface edges (EdgeVisibility: they
// lie on the surface, which casts, and a band there would shadow that
// surface) and splats whose opacity (OpacityArray through
// ScalarOpacityFunction) is below 0.5 (one splat casts all or nothing).
// vtkShadowPassBase::NO_CAST turns any of them off.
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
  // vtkPointGaussianMapper's splats: the centres, x y z, and each one's
  // radius in world units (VTK adds the splat's offsets in view
  // coordinates: the actor's scale does not size it).
  std::vector<double> Splats;
  std::vector<double> SplatRadii;
  // Plain points (squares PointSize wide) and lines (bands LineWidth wide),
  // laid out as Points and LineVertices / Segments.
  std::vector<double> FlatPoints;
  std::vector<double> FlatLineVertices;
  std::vector<unsigned int> FlatSegments;

  bool Empty() const
  {
    return this->Points.empty() && this->Segments.empty() && this->Splats.empty() &&
      this->FlatPoints.empty() && this->FlatSegments.empty();
  }
};

// The kinds of shapes an actor draws, from its property, its mapper and
// its data's cell counts alone (no pass over the data): ExtractImpostors
// finds nothing when this is 0.
enum ImpostorKind
{
  SPHERES = 1,
  TUBES = 2,
  SPLATS = 4,
  FLAT_POINTS = 8,
  FLAT_LINES = 16
};
int ImpostorKinds(vtkActor* actor);

// The smallest and largest splat radius the actor's vtkPointGaussianMapper
// can draw (world units; from the scale array's range through the scale
// function): false when it draws no splats.
bool SplatRadiusRange(vtkActor* actor, double range[2]);

// The world quads (4 corners, x y z each, counter-clockwise from the
// camera) of the flat points and lines in `drawn`, placed by `matrix`
// (data -> world, row major), for the camera (projection eye -> clip, view
// world -> eye, row major; the viewport `width` pixels wide).
void AppendFlatQuads(const Impostors& drawn, const double matrix[16], const double projection[16],
  const double view[16], int width, std::vector<double>& corners);

// What the actor's mapper draws as points and lines, as VTK 9.1 decides
// (vtkOpenGLPolyDataMapper::DrawingSpheres / DrawingTubes, its
// GetOpenGLMode): verts cells always and every point of its cells with
// Representation Points, as spheres with RenderPointsAsSpheres, else as
// squares when PointSize is above 1; line cells with Representation Surface
// or Wireframe, and with Wireframe the polygons' edges too (each edge
// once), as tubes with RenderLinesAsTubes, as bands without, when
// LineWidth is above 1. A vtkPointGaussianMapper
// (vtkOpenGLPointGaussianMapper) draws the verts' points (all points
// without verts) and nothing else: splats, or squares PointSize wide when
// ScaleFactor is 0. Only a vtkPolyData input (not composite data or glyph
// mappers: their points and lines are left out). False when there is
// nothing.
bool ExtractImpostors(vtkActor* actor, Impostors& out);

// When what ExtractImpostors gives last changed: the mapper's data
// (CasterDataTime) and the actor's property (representation, sizes).
vtkMTimeType ImpostorTime(vtkActor* actor);
}

#endif
