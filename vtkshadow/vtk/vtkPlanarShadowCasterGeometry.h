// vtkPlanarShadowCasterGeometry.h - the triangles of one caster actor on the
// GPU, for vtkPlanarShadowPass's mask draws.
//
// The planar pass draws every caster once per (receiver, light) pair with a
// trivial shader, so it keeps its own compact copy of each caster's triangles
// (positions only, relative to the data's centre so float keeps precision far
// from the origin) instead of re-running VTK's mappers with another shader,
// which would rebuild their shaders every frame. The copy is rebuilt only when
// the mapper or its input changed.
#ifndef vtkPlanarShadowCasterGeometry_h
#define vtkPlanarShadowCasterGeometry_h

#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <vector>

class vtkActor;
class vtkMapper;
class vtkOpenGLBufferObject;
class vtkOpenGLVertexArrayObject;
class vtkPolyData;
class vtkShaderProgram;
class vtkWindow;

class vtkPlanarShadowCasterGeometry
{
public:
  vtkPlanarShadowCasterGeometry();
  ~vtkPlanarShadowCasterGeometry();

  // Refresh the triangles from the actor's mapper if it changed. Supports
  // vtkPolyDataMapper, vtkCompositePolyDataMapper(2) and vtkGlyph3DMapper.
  // Returns false when the mapper's data has no triangles to cast.
  bool Update(vtkActor* actor);

  // The shift applied to the stored positions: stored = data - Shift.
  const double* GetShift() const { return this->Shift; }

  // Draw all triangles with `program` (attribute "vertexMC"); the caller
  // binds the program and sets its uniforms.
  void Draw(vtkShaderProgram* program);

  vtkIdType GetNumberOfTriangles() const { return this->TriangleCount; }
  // The time of the last geometry rebuild.
  vtkMTimeType GetBuildTime() const { return this->BuildTime; }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkPlanarShadowCasterGeometry(const vtkPlanarShadowCasterGeometry&) = delete;
  void operator=(const vtkPlanarShadowCasterGeometry&) = delete;

  void Upload(const std::vector<vtkPolyData*>& pieces);

  vtkSmartPointer<vtkOpenGLBufferObject> Vertices;
  vtkSmartPointer<vtkOpenGLBufferObject> Indices;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> VAO;
  vtkShaderProgram* LastProgram = nullptr;
  double Shift[3] = { 0, 0, 0 };
  vtkIdType TriangleCount = 0;
  vtkMTimeType DataTime = 0;
  vtkMTimeType BuildTime = 0;
  bool NeedsUpload = false;
  std::vector<float> PendingVertices;
  std::vector<unsigned int> PendingIndices;
};

#endif
