// vtkShadowCasterTriangles.cxx - CPU triangles of a caster actor (see the
// header); moved here from vtkShadowCasterGeometry unchanged so that the
// GPU copy and the ray tracer share one extraction.
#include "vtkShadowCasterTriangles.h"

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
#include "vtkPointData.h"
#include "vtkPointGaussianMapper.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkTransform.h"

#include <algorithm>
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
vtkMTimeType vtkshadow::CasterDataTime(vtkActor* actor)
{
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  vtkDataObject* data = mapper ? mapper->GetInputDataObject(0, 0) : nullptr;
  if (!data)
  {
    return 0;
  }
  vtkMTimeType dataTime = std::max(mapper->GetMTime(), data->GetMTime());
  auto* glyphs = vtkGlyph3DMapper::SafeDownCast(mapper);
  if (vtkPolyData* source = glyphs ? glyphs->GetSource(0) : nullptr)
  {
    dataTime = std::max(dataTime, source->GetMTime());
  }
  return dataTime;
}

namespace
{
// Composite data: visibility is inherited down the block tree, as the
// mapper draws it.
void AppendComposite(vtkMapper* mapper, vtkDataObject* data, const double shift[3],
  std::vector<float>& vertices, std::vector<unsigned int>& indices)
{
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
        AppendTriangles(leaf, nullptr, shift, vertices, indices);
      }
    }
  };
  visit(data, true);
}
}

//------------------------------------------------------------------------------
bool vtkshadow::ExtractCasterTriangles(vtkActor* actor, CasterTriangles& out)
{
  out.Vertices.clear();
  out.Indices.clear();
  vtkMapper* mapper = actor ? actor->GetMapper() : nullptr;
  vtkDataObject* data = mapper ? mapper->GetInputDataObject(0, 0) : nullptr;
  // A vtkPointGaussianMapper draws its points only, whatever cells its
  // input has (its splats cast as vtkShadowImpostors).
  if (!data || vtkPointGaussianMapper::SafeDownCast(mapper))
  {
    return false;
  }
  double bounds[6];
  mapper->GetBounds(bounds);
  if (!vtkMath::AreBoundsInitialized(bounds))
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    out.Shift[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
  }
  if (auto* glyphs = vtkGlyph3DMapper::SafeDownCast(mapper))
  {
    auto* input = vtkDataSet::SafeDownCast(data);
    vtkPolyData* source = glyphs->GetSource(0);
    if (!input || !source)
    {
      return false;
    }
    vtkDataArray* scale = MapperArray(glyphs, vtkGlyph3DMapper::SCALE, input);
    vtkDataArray* orient = MapperArray(glyphs, vtkGlyph3DMapper::ORIENTATION, input);
    out.Instances = input->GetNumberOfPoints();
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
    {
      double matrix[16];
      GlyphMatrix(glyphs, input, i, scale, orient, matrix);
      AppendTriangles(source, matrix, out.Shift, out.Vertices, out.Indices);
    }
  }
  else if (vtkCompositeDataSet::SafeDownCast(data))
  {
    AppendComposite(mapper, data, out.Shift, out.Vertices, out.Indices);
  }
  else if (auto* poly = vtkPolyData::SafeDownCast(data))
  {
    AppendTriangles(poly, nullptr, out.Shift, out.Vertices, out.Indices);
  }
  return true;
}
