#include "vtkShadowCasterGeometry.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCompositeDataIterator.h"
#include "vtkCompositeDataDisplayAttributes.h"
#include "vtkCompositeDataSet.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkMultiPieceDataSet.h"
#include "vtkCompositePolyDataMapper2.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkGlyph3DMapper.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
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
    auto clamp = [&](double v) {
      return m->GetClamping() ? (std::min(std::max(v, range[0]), range[1]) - range[0]) / den : v;
    };
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
    std::function<void(vtkDataObject*, bool)> visit = [&](vtkDataObject* node, bool visible) {
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
  this->Welded = indices;
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
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(3 * this->TriangleCount), GL_UNSIGNED_INT,
    nullptr);
  this->Indices->Release();
  this->VAO->Release();
}

//------------------------------------------------------------------------------
void vtkShadowCasterGeometry::Analyse()
{
  // Weld vertices that share an exact position (seams duplicate points).
  const size_t n = this->Positions.size() / 3;
  std::vector<unsigned int> order(n), canonical(n);
  for (size_t i = 0; i < n; ++i)
  {
    order[i] = static_cast<unsigned int>(i);
  }
  const float* p = this->Positions.data();
  std::sort(order.begin(), order.end(), [p](unsigned int a, unsigned int b) {
    return std::lexicographical_compare(p + 3 * a, p + 3 * a + 3, p + 3 * b, p + 3 * b + 3);
  });
  for (size_t k = 0; k < n; ++k)
  {
    const unsigned int i = order[k];
    canonical[i] = (k > 0 && std::equal(p + 3 * i, p + 3 * i + 3, p + 3 * order[k - 1]))
      ? canonical[order[k - 1]]
      : i;
  }
  for (unsigned int& v : this->Welded)
  {
    v = canonical[v];
  }
  // Every directed edge must appear once, and its reverse once: a closed,
  // consistently oriented 2-manifold (degenerate triangles excluded).
  struct DirectedEdge
  {
    unsigned int From, To, Triangle;
  };
  std::vector<DirectedEdge> edges;
  edges.reserve(this->Welded.size());
  const size_t triangles = this->Welded.size() / 3;
  for (size_t t = 0; t < triangles; ++t)
  {
    const unsigned int* v = &this->Welded[3 * t];
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
    {
      this->Closed = 0; // a degenerate triangle: do not trust the topology
      return;
    }
    for (int k = 0; k < 3; ++k)
    {
      edges.push_back({ v[k], v[(k + 1) % 3], static_cast<unsigned int>(t) });
    }
  }
  auto key = [](const DirectedEdge& e) {
    return std::make_pair(std::min(e.From, e.To), std::max(e.From, e.To));
  };
  std::sort(edges.begin(), edges.end(),
    [&](const DirectedEdge& a, const DirectedEdge& b) { return key(a) < key(b); });
  this->EdgeA.clear();
  this->EdgeB.clear();
  this->EdgeLeft.clear();
  this->EdgeRight.clear();
  for (size_t k = 0; k < edges.size(); k += 2)
  {
    if (k + 1 >= edges.size() || key(edges[k]) != key(edges[k + 1]) ||
      (k + 2 < edges.size() && key(edges[k + 2]) == key(edges[k])) ||
      edges[k].From != edges[k + 1].To)
    {
      this->Closed = 0;
      return;
    }
    this->EdgeA.push_back(edges[k].From);
    this->EdgeB.push_back(edges[k].To);
    this->EdgeLeft.push_back(edges[k].Triangle);
    this->EdgeRight.push_back(edges[k + 1].Triangle);
  }
  // Connected components (union-find over the welded triangles).
  std::vector<unsigned int> parent(n);
  for (size_t i = 0; i < n; ++i)
  {
    parent[i] = static_cast<unsigned int>(i);
  }
  std::function<unsigned int(unsigned int)> find = [&](unsigned int x) {
    while (parent[x] != x)
    {
      parent[x] = parent[parent[x]];
      x = parent[x];
    }
    return x;
  };
  for (size_t t = 0; t < triangles; ++t)
  {
    const unsigned int* v = &this->Welded[3 * t];
    parent[find(v[1])] = find(v[0]);
    parent[find(v[2])] = find(v[0]);
  }
  // Only vertices the welded triangles use count: a point welded into
  // another (a box's corner repeated per face) is not a component.
  std::vector<char> used(n, 0);
  for (unsigned int v : this->Welded)
  {
    used[v] = 1;
  }
  this->Component.assign(n, 0);
  std::vector<unsigned int> label(n, ~0u);
  this->ComponentCount = 0;
  for (size_t i = 0; i < n; ++i)
  {
    if (!used[canonical[i]])
    {
      continue;
    }
    const unsigned int root = find(canonical[i]);
    if (label[root] == ~0u)
    {
      label[root] = this->ComponentCount++;
    }
    this->Component[i] = label[root];
  }
  this->Closed = edges.empty() ? 0 : 1;
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
  if (!this->IsClosed() || this->ComponentCount != 1)
  {
    return false;
  }
  const float* p = this->Positions.data();
  double size = 0.0;
  for (size_t i = 0; i + 2 < this->Positions.size(); i += 3)
  {
    size = std::max({ size, std::abs(static_cast<double>(p[i])),
      std::abs(static_cast<double>(p[i + 1])), std::abs(static_cast<double>(p[i + 2])) });
  }
  // Float positions: allow their rounding (relative 1e-5 of the size).
  const double tolerance = 1e-5 * size;
  // Which way the triangles face: a closed mesh wound inwards has a negative
  // signed volume, and then every edge of a convex body looks reflex.
  double volume = 0.0;
  for (size_t t = 0; t + 2 < this->Welded.size(); t += 3)
  {
    const float* a = p + 3 * this->Welded[t];
    const float* b = p + 3 * this->Welded[t + 1];
    const float* c = p + 3 * this->Welded[t + 2];
    volume += static_cast<double>(a[0]) * (static_cast<double>(b[1]) * c[2] - static_cast<double>(b[2]) * c[1]) +
      static_cast<double>(a[1]) * (static_cast<double>(b[2]) * c[0] - static_cast<double>(b[0]) * c[2]) +
      static_cast<double>(a[2]) * (static_cast<double>(b[0]) * c[1] - static_cast<double>(b[1]) * c[0]);
  }
  const double outwards = volume < 0.0 ? -1.0 : 1.0;
  for (size_t e = 0; e < this->EdgeA.size(); ++e)
  {
    const unsigned int* t = &this->Welded[3 * this->EdgeLeft[e]];
    const unsigned int* u = &this->Welded[3 * this->EdgeRight[e]];
    unsigned int far = u[0];
    for (int k = 0; k < 3; ++k)
    {
      if (u[k] != this->EdgeA[e] && u[k] != this->EdgeB[e])
      {
        far = u[k];
      }
    }
    double a[3], e1[3], e2[3], d[3];
    for (int k = 0; k < 3; ++k)
    {
      a[k] = p[3 * t[0] + k];
      e1[k] = p[3 * t[1] + k] - a[k];
      e2[k] = p[3 * t[2] + k] - a[k];
      d[k] = p[3 * far + k] - a[k];
    }
    const double n[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
      e1[0] * e2[1] - e1[1] * e2[0] };
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length > 0.0 && outwards * (n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / length > tolerance)
    {
      return false; // a reflex edge: the surface folds back on itself
    }
  }
  this->Convex = 1;
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowCasterGeometry::ComputeFacing(const double light[4], std::vector<char>& facing) const
{
  const float* p = this->Positions.data();
  const size_t triangles = this->Welded.size() / 3;
  facing.assign(triangles, 0);
  for (size_t t = 0; t < triangles; ++t)
  {
    const unsigned int* v = &this->Welded[3 * t];
    double a[3], e1[3], e2[3];
    for (int k = 0; k < 3; ++k)
    {
      a[k] = p[3 * v[0] + k];
      e1[k] = p[3 * v[1] + k] - a[k];
      e2[k] = p[3 * v[2] + k] - a[k];
    }
    const double nrm[3] = { e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
      e1[0] * e2[1] - e1[1] * e2[0] };
    const double to[3] = { light[0] - light[3] * a[0], light[1] - light[3] * a[1],
      light[2] - light[3] * a[2] };
    facing[t] = (nrm[0] * to[0] + nrm[1] * to[1] + nrm[2] * to[2]) > 0.0;
  }
}

//------------------------------------------------------------------------------
double vtkShadowCasterGeometry::GetSilhouetteLength(const double lightInData[4])
{
  if (!this->IsClosed())
  {
    return -1.0;
  }
  const double light[4] = { lightInData[0] - lightInData[3] * this->Shift[0],
    lightInData[1] - lightInData[3] * this->Shift[1],
    lightInData[2] - lightInData[3] * this->Shift[2], lightInData[3] };
  std::vector<char> facing;
  this->ComputeFacing(light, facing);
  const float* p = this->Positions.data();
  double length = 0.0;
  for (size_t e = 0; e < this->EdgeA.size(); ++e)
  {
    if ((facing[this->EdgeLeft[e]] != 0) != (facing[this->EdgeRight[e]] != 0))
    {
      const float* a = p + 3 * this->EdgeA[e];
      const float* b = p + 3 * this->EdgeB[e];
      double d[3], u[3];
      for (int k = 0; k < 3; ++k)
      {
        d[k] = static_cast<double>(b[k]) - a[k];
        // Towards the light from the edge's middle.
        u[k] = light[k] - light[3] * 0.5 * (static_cast<double>(a[k]) + b[k]);
      }
      // As the light sees it: a mesh's silhouette zig-zags along the light
      // direction across the smooth terminator, and that part of each edge
      // does not lengthen the shadow's outline.
      const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
      const double along = uu > 0.0 ? (d[0] * u[0] + d[1] * u[1] + d[2] * u[2]) / uu : 0.0;
      for (int k = 0; k < 3; ++k)
      {
        d[k] -= along * u[k];
      }
      length += std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
  }
  return length;
}

//------------------------------------------------------------------------------
bool vtkShadowCasterGeometry::DrawSilhouetteFans(
  vtkShaderProgram* program, const double lightInData[4])
{
  if (!this->IsClosed())
  {
    return false;
  }
  // The light relative to the stored positions (which are data - Shift).
  const double light[4] = { lightInData[0] - lightInData[3] * this->Shift[0],
    lightInData[1] - lightInData[3] * this->Shift[1],
    lightInData[2] - lightInData[3] * this->Shift[2], lightInData[3] };
  if (!this->FanValid || !std::equal(light, light + 4, this->FanLight))
  {
    std::copy_n(light, 4, this->FanLight);
    const float* p = this->Positions.data();
    std::vector<char> facing;
    this->ComputeFacing(light, facing);
    // Silhouette edges, oriented as in their light-facing triangle, fanned
    // from one silhouette vertex: the fan's winding number is the coverage.
    this->FanData.clear();
    // One centre per connected component: any point works for a closed
    // loop, and a local one keeps the fan triangles small.
    std::vector<unsigned int> centreOf(this->ComponentCount, ~0u);
    for (size_t e = 0; e < this->EdgeA.size(); ++e)
    {
      const bool left = facing[this->EdgeLeft[e]] != 0;
      if (left == (facing[this->EdgeRight[e]] != 0))
      {
        continue;
      }
      // EdgeA -> EdgeB runs along the left triangle's orientation.
      const unsigned int from = left ? this->EdgeA[e] : this->EdgeB[e];
      const unsigned int to = left ? this->EdgeB[e] : this->EdgeA[e];
      unsigned int& centre = centreOf[this->Component[from]];
      if (centre == ~0u)
      {
        centre = from;
      }
      this->FanData.insert(this->FanData.end(), p + 3 * centre, p + 3 * centre + 3);
      this->FanData.insert(this->FanData.end(), p + 3 * from, p + 3 * from + 3);
      this->FanData.insert(this->FanData.end(), p + 3 * to, p + 3 * to + 3);
    }
    this->FanTriangles = static_cast<vtkIdType>(this->FanData.size() / 9);
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
