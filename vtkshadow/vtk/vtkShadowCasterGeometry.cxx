#include "vtkShadowCasterGeometry.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataSet.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkGlyph3DMapper.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiPieceDataSet.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkShaderProgram.h"
#include "vtkTimeStamp.h"
#include "vtkTransform.h"
#include "vtk_glew.h"

#include "vsh_mat4.h"
#include "vsh_mesh_topology.h"
#include "vsh_silhouette.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace
{
// Fan-triangulate polygons and split strips: the mask needs only coverage.
void AppendTriangles(vtkPolyData* poly, const double transform[16], const double shift[3],
  std::vector<float>& vertices, std::vector<unsigned int>& indices)
{
  vtkPoints* points = poly->GetPoints();
  if (!points)
  {
    return;
  }
  const size_t base = vertices.size() / 3;
  const vtkIdType n = points->GetNumberOfPoints();
  if (base + static_cast<size_t>(n) > std::numeric_limits<unsigned int>::max())
  {
    return;
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3];
    points->GetPoint(i, p);
    double q[3] = { p[0], p[1], p[2] };
    if (transform)
    {
      for (int r = 0; r < 3; ++r)
      {
        q[r] = transform[4 * r] * p[0] + transform[4 * r + 1] * p[1] + transform[4 * r + 2] * p[2] +
          transform[4 * r + 3];
      }
    }
    for (int r = 0; r < 3; ++r)
    {
      vertices.push_back(static_cast<float>(q[r] - shift[r]));
    }
  }
  const vtkIdType* ids = nullptr;
  vtkIdType count = 0;
  auto polys = vtk::TakeSmartPointer(poly->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(count, ids);
    for (vtkIdType k = 1; k + 1 < count; ++k)
    {
      indices.push_back(static_cast<unsigned int>(base + ids[0]));
      indices.push_back(static_cast<unsigned int>(base + ids[k]));
      indices.push_back(static_cast<unsigned int>(base + ids[k + 1]));
    }
  }
  auto strips = vtk::TakeSmartPointer(poly->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    strips->GetCurrentCell(count, ids);
    for (vtkIdType k = 0; k + 2 < count; ++k)
    {
      indices.push_back(static_cast<unsigned int>(base + ids[k]));
      indices.push_back(static_cast<unsigned int>(base + ids[k + 1]));
      indices.push_back(static_cast<unsigned int>(base + ids[k + 2]));
    }
  }
}

vtkDataArray* MapperArray(vtkGlyph3DMapper* mapper, int index, vtkDataSet* input)
{
  vtkInformation* info = mapper->GetInputArrayInformation(index);
  if (!info || !input)
  {
    return nullptr;
  }
  if (info->Has(vtkDataObject::FIELD_NAME()))
  {
    return input->GetPointData()->GetArray(info->Get(vtkDataObject::FIELD_NAME()));
  }
  if (info->Has(vtkDataObject::FIELD_ATTRIBUTE_TYPE()))
  {
    return input->GetPointData()->GetAttribute(info->Get(vtkDataObject::FIELD_ATTRIBUTE_TYPE()));
  }
  return nullptr;
}

// The per-glyph matrix of vtkGlyph3DMapper: translate to the point, orient
// the glyph's x axis along the orientation vector, scale (clamped to Range).
void GlyphMatrix(vtkGlyph3DMapper* m, vtkDataSet* input, vtkIdType i, vtkDataArray* scale,
  vtkDataArray* orient, double out[16])
{
  vtkNew<vtkTransform> t;
  t->PostMultiply();
  double s[3] = { 1, 1, 1 };
  if (m->GetScaling() && scale)
  {
    const double* range = m->GetRange();
    const double den = range[1] - range[0] != 0 ? range[1] - range[0] : 1.0;
    auto clamp = [&](double v)
    { return m->GetClamping() ? (std::min(std::max(v, range[0]), range[1]) - range[0]) / den : v; };
    if (m->GetScaleMode() == vtkGlyph3DMapper::SCALE_BY_MAGNITUDE)
    {
      s[0] = s[1] = s[2] = clamp(vtkMath::Norm(scale->GetTuple(i), scale->GetNumberOfComponents()));
    }
    else if (m->GetScaleMode() == vtkGlyph3DMapper::SCALE_BY_COMPONENTS &&
      scale->GetNumberOfComponents() == 3)
    {
      const double* c = scale->GetTuple3(i);
      s[0] = clamp(c[0]);
      s[1] = clamp(c[1]);
      s[2] = clamp(c[2]);
    }
  }
  const double f = m->GetScaleFactor();
  t->Scale(s[0] * f, s[1] * f, s[2] * f);
  if (m->GetOrient() && orient)
  {
    const int nc = orient->GetNumberOfComponents();
    if (m->GetOrientationMode() == vtkGlyph3DMapper::DIRECTION && nc == 3)
    {
      double v[3];
      orient->GetTuple(i, v);
      const double len = vtkMath::Norm(v);
      if (len > 0)
      {
        // Rotate x onto v by 180 degrees about the bisector of x and v.
        if (v[1] == 0.0 && v[2] == 0.0 && v[0] < 0)
        {
          t->RotateWXYZ(180.0, 0, 1, 0);
        }
        else
        {
          t->RotateWXYZ(180.0, (v[0] + len) / 2.0, v[1] / 2.0, v[2] / 2.0);
        }
      }
    }
    else if (m->GetOrientationMode() == vtkGlyph3DMapper::ROTATION && nc == 3)
    {
      double r[3];
      orient->GetTuple(i, r);
      t->RotateZ(r[2]);
      t->RotateX(r[0]);
      t->RotateY(r[1]);
    }
    else if (m->GetOrientationMode() == vtkGlyph3DMapper::QUATERNION && nc == 4)
    {
      double q[4], rot[3][3];
      orient->GetTuple(i, q);
      vtkMath::QuaternionToMatrix3x3(q, rot);
      vtkNew<vtkMatrix4x4> r;
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
          r->SetElement(a, b, rot[a][b]);
      t->Concatenate(r);
    }
  }
  double p[3];
  input->GetPoint(i, p);
  t->Translate(p);
  vtkMatrix4x4::DeepCopy(out, t->GetMatrix());
}
}

//------------------------------------------------------------------------------
vtkShadowCasterGeometry::vtkShadowCasterGeometry() = default;

//------------------------------------------------------------------------------
vtkShadowCasterGeometry::~vtkShadowCasterGeometry() = default;

//------------------------------------------------------------------------------
bool vtkShadowCasterGeometry::Update(vtkActor* actor)
{
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  if (!mapper)
  {
    return false;
  }
  vtkDataObject* data = mapper->GetInputDataObject(0, 0);
  if (!data)
  {
    return false;
  }
  vtkMTimeType dataTime = std::max(mapper->GetMTime(), data->GetMTime());
  auto* glyphs = vtkGlyph3DMapper::SafeDownCast(mapper);
  vtkPolyData* source = glyphs ? glyphs->GetSource(0) : nullptr;
  if (source)
  {
    dataTime = std::max(dataTime, source->GetMTime());
  }
  if (dataTime <= this->DataTime && this->TriangleCount > 0)
  {
    return true;
  }
  this->DataTime = dataTime;

  std::vector<float> vertices;
  std::vector<unsigned int> indices;
  this->Instances = 1;
  double bounds[6];
  mapper->GetBounds(bounds);
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    this->Shift[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
  }

  if (glyphs)
  {
    auto* input = vtkDataSet::SafeDownCast(data);
    if (!input || !source)
    {
      return false;
    }
    vtkDataArray* scale = MapperArray(glyphs, vtkGlyph3DMapper::SCALE, input);
    vtkDataArray* orient = MapperArray(glyphs, vtkGlyph3DMapper::ORIENTATION, input);
    this->Instances = input->GetNumberOfPoints();
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      double matrix[16];
      GlyphMatrix(glyphs, input, i, scale, orient, matrix);
      AppendTriangles(source, matrix, this->Shift, vertices, indices);
    }
  }
  else if (vtkCompositeDataSet::SafeDownCast(data))
  {
    // Visibility is inherited down the block tree, as the mapper draws it.
    auto* cpdm = vtkCompositePolyDataMapper2::SafeDownCast(mapper);
    vtkCompositeDataDisplayAttributes* attributes =
      cpdm ? cpdm->GetCompositeDataDisplayAttributes() : nullptr;
    std::function<void(vtkDataObject*, bool)> visit = [&](vtkDataObject* node, bool visible)
    {
      if (!node)
      {
        return;
      }
      if (attributes && attributes->HasBlockVisibility(node))
      {
        visible = attributes->GetBlockVisibility(node);
      }
      if (auto* mb = vtkMultiBlockDataSet::SafeDownCast(node))
      {
        for (unsigned int b = 0; b < mb->GetNumberOfBlocks(); ++b)
        {
          visit(mb->GetBlock(b), visible);
        }
      }
      else if (auto* mp = vtkMultiPieceDataSet::SafeDownCast(node))
      {
        for (unsigned int b = 0; b < mp->GetNumberOfPieces(); ++b)
        {
          visit(mp->GetPiece(b), visible);
        }
      }
      else if (auto* leaf = vtkPolyData::SafeDownCast(node))
      {
        if (visible)
        {
          AppendTriangles(leaf, nullptr, this->Shift, vertices, indices);
        }
      }
    };
    visit(data, true);
  }
  else if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    AppendTriangles(poly, nullptr, this->Shift, vertices, indices);
  }
  this->TriangleCount = static_cast<vtkIdType>(indices.size() / 3);
  this->VertexCount = static_cast<vtkIdType>(vertices.size() / 3);
  // Kept for silhouettes (analysed lazily, only when a planar pass asks).
  this->Positions = vertices;
  this->Triangles = indices;
  this->Topology.reset();
  this->Closed = -1;
  this->Convex = -1;
  this->FanValid = false;
  this->PendingVertices.swap(vertices);
  this->PendingIndices.swap(indices);
  this->NeedsUpload = true;
  vtkTimeStamp now;
  now.Modified();
  this->BuildTime = now.GetMTime();
  return this->TriangleCount > 0;
}

//------------------------------------------------------------------------------
void vtkShadowCasterGeometry::Draw(vtkShaderProgram* program)
{
  if (this->TriangleCount == 0)
  {
    return;
  }
  if (!this->Vertices)
  {
    this->Vertices = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Vertices->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    this->Indices = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->Indices->SetType(vtkOpenGLBufferObject::ElementArrayBuffer);
    this->VAO = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    this->NeedsUpload = true;
  }
  if (this->NeedsUpload)
  {
    this->Vertices->Upload(this->PendingVertices, vtkOpenGLBufferObject::ArrayBuffer);
    this->Indices->Upload(this->PendingIndices, vtkOpenGLBufferObject::ElementArrayBuffer);
    // Keep no CPU copy of what the GPU holds.
    std::vector<float>().swap(this->PendingVertices);
    std::vector<unsigned int>().swap(this->PendingIndices);
    this->NeedsUpload = false;
    this->LastProgram = nullptr;
  }
  if (this->LastProgram != program)
  {
    // Forgets the old bindings (and the VAO handle): bind again after it.
    this->VAO->ShaderProgramChanged();
    this->VAO->Bind();
    this->VAO->AddAttributeArray(
      program, this->Vertices, "vertexMC", 0, 3 * sizeof(float), VTK_FLOAT, 3, false);
    this->LastProgram = program;
  }
  this->VAO->Bind();
  this->Indices->Bind();
  glDrawElements(
    GL_TRIANGLES, static_cast<GLsizei>(3 * this->TriangleCount), GL_UNSIGNED_INT, nullptr);
  this->Indices->Release();
  this->VAO->Release();
}

//------------------------------------------------------------------------------
void vtkShadowCasterGeometry::TopologyDeleter::operator()(vsh_mesh_topology* topology) const
{
  vsh_mesh_topology_free(topology);
  delete topology;
}

//------------------------------------------------------------------------------
void vtkShadowCasterGeometry::Analyse()
{
  // Exact welding (tolerance 0): seams duplicate points at the same float
  // position; a tolerance could join distinct vertices of fine meshes.
  const std::vector<double> positions(this->Positions.begin(), this->Positions.end());
  static_assert(sizeof(unsigned int) == sizeof(uint32_t), "triangle indices are 32-bit");
  this->Topology.reset(new vsh_mesh_topology());
  const vsh_mesh_status status = vsh_mesh_topology_build(positions.data(), positions.size() / 3,
    reinterpret_cast<const uint32_t*>(this->Triangles.data()), this->Triangles.size() / 3, 0.0,
    this->Topology.get());
  // A mesh that cannot be analysed is treated as not closed: the passes then
  // draw its triangles, which is always right.
  this->Closed = status == VSH_MESH_OK && this->Topology->closed ? 1 : 0;
  // The topology holds what silhouettes need from here on.
  std::vector<float>().swap(this->Positions);
  std::vector<unsigned int>().swap(this->Triangles);
}

//------------------------------------------------------------------------------
const vsh_mesh_topology* vtkShadowCasterGeometry::GetTopology()
{
  if (this->Closed < 0)
  {
    this->Analyse();
  }
  return this->Topology && this->Topology->triangles ? this->Topology.get() : nullptr;
}

//------------------------------------------------------------------------------
bool vtkShadowCasterGeometry::IsClosed()
{
  if (this->Closed < 0)
  {
    this->Analyse();
  }
  return this->Closed == 1;
}

//------------------------------------------------------------------------------
bool vtkShadowCasterGeometry::IsConvex()
{
  if (this->Convex >= 0)
  {
    return this->Convex == 1;
  }
  this->Convex = 0;
  if (!this->IsClosed())
  {
    return false;
  }
  const vsh_mesh_topology& topology = *this->Topology;
  double size = 0.0;
  for (size_t i = 0; i < 3 * topology.vertex_count; ++i)
  {
    size = std::max(size, std::abs(topology.positions[i]));
  }
  // Float positions: allow their rounding (relative 1e-5 of the size).
  int convex = 0;
  vsh_mesh_is_convex(&topology, 1e-5 * size, &convex);
  this->Convex = convex;
  return convex == 1;
}

//------------------------------------------------------------------------------
void vtkShadowCasterGeometry::ShiftLight(const double lightInData[4], double light[4]) const
{
  for (int k = 0; k < 3; ++k)
  {
    light[k] = lightInData[k] - lightInData[3] * this->Shift[k];
  }
  light[3] = lightInData[3];
}

//------------------------------------------------------------------------------
double vtkShadowCasterGeometry::GetSilhouetteLength(const double lightInData[4])
{
  if (!this->IsClosed())
  {
    return -1.0;
  }
  double light[4];
  this->ShiftLight(lightInData, light);
  vsh_silhouette silhouette;
  double length = 0.0;
  if (vsh_silhouette_build(this->Topology.get(), light, VSH_SILHOUETTE_LIT_FACES, &silhouette) ==
    VSH_MESH_OK)
  {
    vsh_silhouette_length(this->Topology.get(), &silhouette, light, &length);
  }
  vsh_silhouette_free(&silhouette);
  return length;
}

//------------------------------------------------------------------------------
void vtkShadowCasterGeometry::BuildFans(const double light[4])
{
  // Silhouette edges, oriented as in their light-facing triangle, fanned
  // from one silhouette vertex per connected component: the fan's winding
  // number is the coverage, and a local centre keeps its triangles small.
  this->FanData.clear();
  const vsh_mesh_topology* topology = this->Topology.get();
  vsh_silhouette silhouette;
  if (vsh_silhouette_build(topology, light, VSH_SILHOUETTE_LIT_FACES, &silhouette) == VSH_MESH_OK)
  {
    std::vector<uint32_t> fans(3 * silhouette.total_multiplicity);
    if (vsh_silhouette_fans(topology, &silhouette, fans.data()) == VSH_MESH_OK)
    {
      this->FanData.reserve(3 * fans.size());
      for (uint32_t v : fans)
      {
        const double* p = topology->positions + 3 * static_cast<size_t>(v);
        // Exact: the positions were floats before the analysis.
        this->FanData.insert(this->FanData.end(),
          { static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]) });
      }
    }
  }
  vsh_silhouette_free(&silhouette);
  this->FanTriangles = static_cast<vtkIdType>(this->FanData.size() / 9);
}

//------------------------------------------------------------------------------
bool vtkShadowCasterGeometry::DrawSilhouetteFans(
  vtkShaderProgram* program, const double lightInData[4])
{
  if (!this->IsClosed())
  {
    return false;
  }
  double light[4];
  this->ShiftLight(lightInData, light);
  if (!this->FanValid || !std::equal(light, light + 4, this->FanLight))
  {
    std::copy_n(light, 4, this->FanLight);
    this->BuildFans(light);
    this->FanValid = true;
    this->FanNeedsUpload = true;
  }
  if (this->FanTriangles == 0)
  {
    return true; // nothing faces the light: no shadow
  }
  if (!this->FanVertices)
  {
    this->FanVertices = vtkSmartPointer<vtkOpenGLBufferObject>::New();
    this->FanVertices->SetType(vtkOpenGLBufferObject::ArrayBuffer);
    this->FanVAO = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
    this->FanNeedsUpload = true;
  }
  if (this->FanNeedsUpload)
  {
    this->FanVertices->Upload(this->FanData, vtkOpenGLBufferObject::ArrayBuffer);
    this->FanNeedsUpload = false;
    this->FanProgram = nullptr;
  }
  if (this->FanProgram != program)
  {
    this->FanVAO->ShaderProgramChanged();
    this->FanVAO->Bind();
    this->FanVAO->AddAttributeArray(
      program, this->FanVertices, "vertexMC", 0, 3 * sizeof(float), VTK_FLOAT, 3, false);
    this->FanProgram = program;
  }
  this->FanVAO->Bind();
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * this->FanTriangles));
  this->FanVAO->Release();
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowCasterGeometry::GetModelRelativeMatrix(
  vtkActor* actor, const double eye[3], double out[16]) const
{
  double model[16], toShifted[16], modelShifted[16], toRelative[16];
  vtkMatrix4x4::DeepCopy(model, actor->GetMatrix());
  vsh_mat4_translation(this->Shift, toShifted);
  vsh_mat4_multiply(model, toShifted, modelShifted);
  const double negEye[3] = { -eye[0], -eye[1], -eye[2] };
  vsh_mat4_translation(negEye, toRelative);
  vsh_mat4_multiply(toRelative, modelShifted, out);
}

//------------------------------------------------------------------------------
void vtkShadowCasterGeometry::ReleaseGraphicsResources(vtkWindow*)
{
  if (this->FanVAO)
  {
    this->FanVAO->ReleaseGraphicsResources();
    this->FanVertices->ReleaseGraphicsResources();
  }
  this->FanVAO = nullptr;
  this->FanVertices = nullptr;
  this->FanProgram = nullptr;
  this->FanValid = false;
  if (this->VAO)
  {
    this->VAO->ReleaseGraphicsResources();
    this->Vertices->ReleaseGraphicsResources();
    this->Indices->ReleaseGraphicsResources();
  }
  this->VAO = nullptr;
  this->Vertices = nullptr;
  this->Indices = nullptr;
  this->LastProgram = nullptr;
  // The GPU copy is gone: rebuild from the data next time.
  this->DataTime = 0;
  this->TriangleCount = 0;
  this->VertexCount = 0;
}
