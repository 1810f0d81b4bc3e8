// vtkShadowCasterGeometry.h - the triangles of one caster actor on the
// GPU, for the shadow passes' own draws (planar masks, shadow maps).
//
// The passes draw every caster once per (receiver, light) pair or per shadow
// map with a trivial shader, so they keep a compact copy of each caster's triangles
// (positions only, relative to the data's centre so float keeps precision far
// from the origin) instead of re-running VTK's mappers with another shader,
// which would rebuild their shaders every frame. The copy is rebuilt only when
// the mapper or its input changed.
#ifndef vtkShadowCasterGeometry_h
#define vtkShadowCasterGeometry_h

#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <memory>
#include <vector>

class vtkActor;
class vtkMapper;
class vtkOpenGLBufferObject;
class vtkOpenGLVertexArrayObject;
class vtkPolyData;
class vtkShaderProgram;
class vtkWindow;
struct vsh_mesh_topology;
namespace vtkshadow
{
struct CasterTriangles;
}

class vtkShadowCasterGeometry
{
public:
  vtkShadowCasterGeometry();
  ~vtkShadowCasterGeometry();

  // Refresh the triangles from the actor's mapper if it changed. Supports
  // vtkPolyDataMapper, vtkCompositePolyDataMapper(2) and vtkGlyph3DMapper.
  // Returns false when the mapper's data has no triangles to cast.
  bool Update(vtkActor* actor);

  // Take `triangles` (emptied) as the copy: triangles no mapper holds, the
  // world-space proxies of spheres and tubes (vtkShadowImpostorProxies).
  // Returns false when there are none.
  bool Load(vtkshadow::CasterTriangles& triangles);

  // The shift applied to the stored positions: stored = data - Shift.
  const double* GetShift() const { return this->Shift; }

  // The stored positions -> world (`model`, the data -> world matrix the
  // actor is drawn with, row major) -> relative to `eye`, composed in
  // double: the matrix the passes' draws start from.
  void GetModelRelativeMatrix(const double model[16], const double eye[3], double out[16]) const;

  // Draw all triangles with `program` (attribute "vertexMC"); the caller
  // binds the program and sets its uniforms.
  void Draw(vtkShaderProgram* program);

  vtkIdType GetNumberOfTriangles() const { return this->TriangleCount; }
  // GPU bytes of the copy (12 a vertex, 12 a triangle).
  vtkIdType GetNumberOfBytes() const { return 12 * (this->VertexCount + this->TriangleCount); }
  // The time of the last geometry rebuild.
  vtkMTimeType GetBuildTime() const { return this->BuildTime; }

  /**
   * Silhouette fans for closed casters (planar shadows). When the caster is
   * a closed, consistently oriented triangle mesh (vertices welded by exact
   * position; the topology and silhouettes are vtkshadow_core's
   * vsh_mesh_topology and vsh_silhouette), the shadow it casts from a light is the region where the
   * winding number of its projected silhouette loops is non-zero: every
   * point of the shadow is covered by the light-facing triangles as many
   * times as the silhouette winds around it. DrawSilhouetteFans() draws one
   * triangle (fan centre, a, b) per silhouette edge a->b; counting them in
   * the stencil buffer (front +1, back -1) gives that winding number with a
   * few thousand triangles instead of the whole mesh.
   * `lightInData` is the light in the data's own (unshifted) coordinates,
   * homogeneous: (x, y, z, 1) positional or (towards the light, 0).
   * Returns false (nothing drawn) for casters that are not closed.
   */
  bool IsClosed();
  /**
   * Closed, one connected component of a sphere's topology, and convex
   * along every edge (the neighbouring triangle's far vertex never in front
   * of a triangle's plane): such a surface is convex, so it cannot shadow
   * itself (vsh_mesh_is_convex).
   */
  bool IsConvex();
  bool DrawSilhouetteFans(vtkShaderProgram* program, const double lightInData[4]);
  /**
   * Total length (data units) of the silhouette edges as the light sees
   * them (each edge without its component along the ray to the light; same
   * light convention as DrawSilhouetteFans): the length of the outline of
   * the shadow this caster throws on a surface facing the light. -1 for
   * casters that are not closed.
   */
  double GetSilhouetteLength(const double lightInData[4]);
  vtkIdType GetNumberOfSilhouetteTriangles() const { return this->FanTriangles; }

  /**
   * The narrowest shadow a part of the caster throws from a generic
   * direction, in data units: over its connected components, the middle one
   * of their principal extents (vsh_mesh_thinnest_width). +inf without
   * triangles. Computed once per mesh.
   */
  double GetThinnestWidth();

  /**
   * The cross-section widths of every connected component along its longest
   * extent, VSH_MESH_TAPER_SLICES slices each, and the slices' lengths, in
   * data units (vsh_mesh_taper_profile): where tapered parts (cone tips)
   * become narrower than a map resolves. Empty without triangles. Computed
   * once per mesh.
   */
  const std::vector<double>& GetTaperWidths();
  const std::vector<double>& GetTaperLengths();

  /**
   * The mesh topology of the stored triangles (positions relative to
   * GetShift(), vertices welded by exact position), analysed on first use;
   * nullptr when the mesh cannot be analysed. Shadow volumes build their
   * silhouettes and caps from it (vsh_volume.h).
   */
  const vsh_mesh_topology* GetTopology();
  // The light relative to the stored positions (which are data - Shift):
  // `lightInData` homogeneous in the data's own coordinates.
  void ShiftLight(const double lightInData[4], double light[4]) const;
  // A homogeneous world point (a light, the eye) relative to the stored
  // positions of a caster drawn with `model` (data -> world, row major):
  // through the inverse of `model`, then ShiftLight. False (out untouched)
  // when `model` is singular.
  bool WorldToStored(const double model[16], const double world[4], double stored[4]) const;
  // Glyph instances baked into the copy (vtkGlyph3DMapper: one per input
  // point, each its own connected component), 1 for other mappers.
  vtkIdType GetNumberOfInstances() const { return this->Instances; }

  void ReleaseGraphicsResources(vtkWindow* window);

private:
  vtkShadowCasterGeometry(const vtkShadowCasterGeometry&) = delete;
  void operator=(const vtkShadowCasterGeometry&) = delete;

  void Upload(const std::vector<vtkPolyData*>& pieces);

  vtkSmartPointer<vtkOpenGLBufferObject> Vertices;
  vtkSmartPointer<vtkOpenGLBufferObject> Indices;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> VAO;
  vtkShaderProgram* LastProgram = nullptr;
  double Shift[3] = { 0, 0, 0 };
  vtkIdType TriangleCount = 0;
  vtkIdType VertexCount = 0;
  vtkMTimeType DataTime = 0;
  vtkMTimeType BuildTime = 0;
  bool NeedsUpload = false;
  std::vector<float> PendingVertices;
  std::vector<unsigned int> PendingIndices;
  // CPU copies for silhouettes, kept only until the topology is analysed
  // (lazily, when a pass first asks): positions relative to Shift, triangles.
  std::vector<float> Positions;
  std::vector<unsigned int> Triangles;
  // The mesh topology from vtkshadow_core (welded vertices, edges with the
  // faces using them, components): silhouettes, closedness and convexity
  // are computed there; this class only adapts VTK data and draws.
  struct TopologyDeleter
  {
    void operator()(vsh_mesh_topology* topology) const;
  };
  std::unique_ptr<vsh_mesh_topology, TopologyDeleter> Topology;
  int Closed = -1;
  int Convex = -1;
  double Thinnest = -1.0;
  bool TaperValid = false;
  std::vector<double> TaperWidths;
  std::vector<double> TaperLengths;
  void ComputeTaper();
  double FanLight[4] = { 0, 0, 0, 0 };
  bool FanValid = false;
  vtkIdType FanTriangles = 0;
  vtkSmartPointer<vtkOpenGLBufferObject> FanVertices;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> FanVAO;
  vtkShaderProgram* FanProgram = nullptr;
  bool FanNeedsUpload = false;
  std::vector<float> FanData;
  void Analyse();
  vtkIdType Instances = 1;
  // Rebuilds FanData (fan triangles, positions) for `light` (shifted).
  void BuildFans(const double light[4]);
};

#endif
