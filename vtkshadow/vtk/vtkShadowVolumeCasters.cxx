#include "vtkShadowVolumeCasters.h"

#include "vtkAbstractMapper.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkMultiVolume.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPlaneCollection.h"
#include "vtkPointData.h"
#include "vtkPropCollection.h"
#include "vtkRenderer.h"
#include "vtkVolume.h"
#include "vtkVolumeMapper.h"
#include "vtkVolumeProperty.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace
{
// Under this the ray counts as blocked: below what an 8-bit mask channel
// holds (the translucent casters' rule in vtkShadowRayTracer).
constexpr double Cutoff = 1.0 / 1024;
// The opacity function's table: as many values as VTK's GPU mapper's
// opacity table, linear in between.
constexpr int TableSize = 1024;

// Why `mapper` draws `volume` in a way the march does not follow; empty
// when it does.
std::string MapperRefusal(vtkVolume* volume, vtkVolumeMapper* mapper)
{
  if (vtkMultiVolume::SafeDownCast(volume))
  {
    return "a vtkMultiVolume (one vtkVolume per input only)";
  }
  if (!mapper)
  {
    return volume->GetMapper() ? "its mapper is not a vtkVolumeMapper" : "no mapper";
  }
  if (mapper->GetBlendMode() != vtkVolumeMapper::COMPOSITE_BLEND)
  {
    return "blend mode " + std::to_string(mapper->GetBlendMode()) + " (composite only)";
  }
  if (mapper->GetCropping())
  {
    return "cropping (not supported)";
  }
  vtkPlaneCollection* planes = mapper->GetClippingPlanes();
  if (planes && planes->GetNumberOfItems() > 0)
  {
    return "clipping planes (not supported)";
  }
  return std::string();
}

// Why the mapper's input is not a grid the march reads; empty when it is,
// with `scalars` the array the mapper draws.
std::string DataRefusal(vtkVolumeMapper* mapper, vtkImageData* image, vtkDataArray*& scalars)
{
  if (!image)
  {
    return "its input is not a vtkImageData";
  }
  vtkMatrix3x3* direction = image->GetDirectionMatrix();
  if (direction && !direction->IsIdentity())
  {
    return "a direction matrix (identity only)";
  }
  int cellFlag = 0;
  scalars = vtkAbstractMapper::GetScalars(image, mapper->GetScalarMode(),
    mapper->GetArrayAccessMode(), mapper->GetArrayId(), mapper->GetArrayName(), cellFlag);
  if (!scalars)
  {
    return "no scalars";
  }
  if (cellFlag != 0)
  {
    return "cell scalars (point scalars only)";
  }
  if (scalars->GetNumberOfComponents() != 1)
  {
    return std::to_string(scalars->GetNumberOfComponents()) +
      "-component scalars (single component only)";
  }
  if (scalars->GetNumberOfTuples() != image->GetNumberOfPoints())
  {
    return "scalars of another size than the grid";
  }
  return std::string();
}

// The grid of `image` in its data coordinates: point (i, j, k) of the
// extent at origin + (extent min + (i, j, k)) * spacing.
vsh_volume_grid ImageGrid(vtkImageData* image)
{
  vsh_volume_grid grid;
  const int* extent = image->GetExtent();
  const double* origin = image->GetOrigin();
  const double* spacing = image->GetSpacing();
  for (int a = 0; a < 3; ++a)
  {
    grid.spacing[a] = spacing[a];
    grid.origin[a] = origin[a] + extent[2 * a] * spacing[a];
    grid.dims[a] = extent[2 * a + 1] - extent[2 * a] + 1;
  }
  return grid;
}

// The world -> data matrix (row major 3x4) of a volume drawn with `m`
// (data -> world); false for a singular or projective one.
bool WorldToData(vtkMatrix4x4* m, double out[12])
{
  const double* e = m->GetData();
  const double det = vtkMatrix4x4::Determinant(e);
  if (!std::isfinite(det) || det == 0.0 || e[12] != 0.0 || e[13] != 0.0 || e[14] != 0.0)
  {
    return false;
  }
  double inverse[16];
  vtkMatrix4x4::Invert(e, inverse);
  std::copy_n(inverse, 12, out);
  return true;
}

// The world -> data matrix `toData` for points relative to `centre`:
// data = A (p + centre) + b = A p + (A centre + b).
void OffsetToData(const double toData[12], const double centre[3], double out[12])
{
  std::copy_n(toData, 12, out);
  for (int r = 0; r < 3; ++r)
  {
    const double* row = toData + 4 * r;
    out[4 * r + 3] = row[0] * centre[0] + row[1] * centre[1] + row[2] * centre[2] + row[3];
  }
}
}

struct vtkShadowVolumeCasters::Volume
{
  vsh_volume_grid Grid;
  // The scalars as float, x fastest (VTK's point order), and what they
  // were read from.
  std::vector<float> Values;
  vtkDataArray* ValuesArray = nullptr;
  vtkMTimeType ValuesTime = 0;
  // The opacity function over Range, and what it was read from.
  std::vector<float> Table;
  double Range[2] = { 0, 0 };
  bool Clamp = true;
  vtkPiecewiseFunction* TableFunction = nullptr;
  vtkMTimeType TableTime = 0;
  double Unit = 1.0;
  double ToData[12]; // world -> data
  double Placed[12]; // the tracer's frame (relative to the centre) -> data
  bool Seen = false; // in this frame

  void UpdateValues(vtkDataArray* scalars);
  void UpdateTable(vtkPiecewiseFunction* function);

  // The opacity at data point p: the scalar interpolated trilinearly, then
  // looked up in the function (VTK's order: interpolate, then classify).
  static double Sample(void* user, const double p[3])
  {
    const Volume* v = static_cast<const Volume*>(user);
    const double s = vsh_volume_trilinear(&v->Grid, v->Values.data(), p);
    return vsh_volume_table(v->Table.data(), static_cast<int>(v->Table.size()), v->Range[0],
      v->Range[1], v->Clamp ? 1 : 0, s);
  }
};

void vtkShadowVolumeCasters::Volume::UpdateValues(vtkDataArray* scalars)
{
  if (scalars == this->ValuesArray && scalars->GetMTime() == this->ValuesTime)
  {
    return;
  }
  const vtkIdType n = scalars->GetNumberOfTuples();
  this->Values.resize(static_cast<size_t>(n));
  if (auto* floats = vtkFloatArray::SafeDownCast(scalars))
  {
    std::copy_n(floats->GetPointer(0), n, this->Values.data());
  }
  else
  {
    for (vtkIdType i = 0; i < n; ++i)
    {
      this->Values[static_cast<size_t>(i)] = static_cast<float>(scalars->GetComponent(i, 0));
    }
  }
  this->ValuesArray = scalars;
  this->ValuesTime = scalars->GetMTime();
}

void vtkShadowVolumeCasters::Volume::UpdateTable(vtkPiecewiseFunction* function)
{
  if (function == this->TableFunction && function->GetMTime() == this->TableTime)
  {
    return;
  }
  function->GetRange(this->Range);
  this->Table.assign(TableSize, 0.0f);
  if (function->GetSize() > 0)
  {
    function->GetTable(this->Range[0], this->Range[1], TableSize, this->Table.data());
  }
  this->Clamp = function->GetClamping() != 0;
  this->TableFunction = function;
  this->TableTime = function->GetMTime();
}

//------------------------------------------------------------------------------
vtkShadowVolumeCasters::vtkShadowVolumeCasters() = default;

//------------------------------------------------------------------------------
vtkShadowVolumeCasters::~vtkShadowVolumeCasters() = default;

//------------------------------------------------------------------------------
bool vtkShadowVolumeCasters::Collect(vtkVolume* volume, int index, std::vector<double>& key)
{
  auto* mapper = vtkVolumeMapper::SafeDownCast(volume->GetMapper());
  if (mapper && mapper->GetNumberOfInputConnections(0) > 0)
  {
    mapper->GetInputAlgorithm()->Update(); // the pass runs before the mapper updates it
  }
  vtkImageData* image = mapper ? vtkImageData::SafeDownCast(mapper->GetDataSetInput()) : nullptr;
  vtkDataArray* scalars = nullptr;
  std::string why = MapperRefusal(volume, mapper);
  why = why.empty() ? DataRefusal(mapper, image, scalars) : why;
  vtkVolumeProperty* property = volume->GetProperty();
  vtkPiecewiseFunction* function = property->GetScalarOpacity(0);
  // What the shadow depends on, also for a skipped volume (it may become
  // supported). Not the vtkVolume's own time: its first render modifies it
  // (a still second frame would trace again); its matrix and property are
  // here instead.
  key.insert(key.end(),
    { static_cast<double>(reinterpret_cast<std::uintptr_t>(volume)),
      mapper ? double(mapper->GetMTime()) : 0.0, image ? double(image->GetMTime()) : 0.0,
      scalars ? double(scalars->GetMTime()) : 0.0, double(property->GetMTime()),
      function ? double(function->GetMTime()) : 0.0, property->GetScalarOpacityUnitDistance(0) });
  vtkMatrix4x4* matrix = volume->GetMatrix();
  key.insert(key.end(), matrix->GetData(), matrix->GetData() + 16);
  const vsh_volume_grid grid = image ? ImageGrid(image) : vsh_volume_grid{};
  double toData[12];
  if (why.empty() && !vsh_volume_grid_valid(&grid))
  {
    why = "a degenerate grid (fewer than 2 points on an axis, or spacing not > 0)";
  }
  if (why.empty() && !WorldToData(matrix, toData))
  {
    why = "a singular or projective matrix";
  }
  if (!why.empty())
  {
    this->Skipped.push_back("vtkVolume " + std::to_string(index) + ": " + why);
    return false;
  }
  std::unique_ptr<Volume>& cached = this->Cache[volume];
  if (!cached)
  {
    cached.reset(new Volume);
  }
  Volume& v = *cached;
  v.Grid = grid;
  std::copy_n(toData, 12, v.ToData);
  v.UpdateValues(scalars);
  v.UpdateTable(function);
  v.Unit = property->GetScalarOpacityUnitDistance(0);
  v.Seen = true;
  this->Active.push_back(&v);
  double bounds[6];
  volume->GetBounds(bounds);
  for (int a = 0; a < 3; ++a)
  {
    this->Bounds[2 * a] = std::min(this->Bounds[2 * a], bounds[2 * a]);
    this->Bounds[2 * a + 1] = std::max(this->Bounds[2 * a + 1], bounds[2 * a + 1]);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkShadowVolumeCasters::Gather(vtkRenderer* renderer, std::vector<double>& key)
{
  this->Active.clear();
  this->Skipped.clear();
  for (int a = 0; a < 3; ++a)
  {
    this->Bounds[2 * a] = VTK_DOUBLE_MAX;
    this->Bounds[2 * a + 1] = -VTK_DOUBLE_MAX;
  }
  for (auto& entry : this->Cache)
  {
    entry.second->Seen = false;
  }
  vtkPropCollection* props = renderer ? renderer->GetViewProps() : nullptr;
  int index = 0;
  vtkCollectionSimpleIterator it;
  if (props)
  {
    props->InitTraversal(it);
  }
  while (vtkProp* prop = props ? props->GetNextProp(it) : nullptr)
  {
    auto* volume = vtkVolume::SafeDownCast(prop);
    if (volume && volume->GetVisibility())
    {
      this->Collect(volume, index, key);
    }
    index += volume ? 1 : 0;
  }
  if (index > 0)
  {
    key.push_back(static_cast<double>(this->Active.size())); // which of them cast
  }
  // Volumes gone from the renderer (or no longer casting) free their copies.
  for (auto it2 = this->Cache.begin(); it2 != this->Cache.end();)
  {
    it2 = it2->second->Seen ? std::next(it2) : this->Cache.erase(it2);
  }
}

//------------------------------------------------------------------------------
void vtkShadowVolumeCasters::Place(const double centre[3])
{
  for (auto& entry : this->Cache)
  {
    Volume& v = *entry.second;
    OffsetToData(v.ToData, centre, v.Placed);
  }
}

//------------------------------------------------------------------------------
double vtkShadowVolumeCasters::Transmittance(
  const double origin[3], const double dir[3], double tmax, double start, long long& samples) const
{
  double kept = start;
  for (const Volume* v : this->Active)
  {
    if (kept < Cutoff)
    {
      return 0.0;
    }
    vsh_volume_ray ray;
    for (int r = 0; r < 3; ++r)
    {
      const double* row = v->Placed + 4 * r;
      ray.origin[r] = row[0] * origin[0] + row[1] * origin[1] + row[2] * origin[2] + row[3];
      ray.direction[r] = row[0] * dir[0] + row[1] * dir[1] + row[2] * dir[2];
    }
    ray.t_min = 0.0;
    ray.t_max = tmax;
    // The march stops where this volume takes the ray under the cutoff.
    const vsh_volume_march_input in = { &v->Grid, v->Unit, Cutoff / kept };
    int taken = 0;
    kept *= vsh_volume_march(&in, &ray, &Volume::Sample, const_cast<Volume*>(v), &taken);
    samples += taken;
  }
  return kept < Cutoff ? 0.0 : kept;
}

//------------------------------------------------------------------------------
void vtkShadowVolumeCasters::Describe(
  const double origin[3], std::vector<vsh_volume_map_volume>& out) const
{
  out.clear();
  for (const Volume* v : this->Active)
  {
    vsh_volume_map_volume d;
    d.grid = v->Grid;
    d.unit = v->Unit;
    OffsetToData(v->ToData, origin, d.to_data);
    d.sample = &Volume::Sample;
    d.user = const_cast<Volume*>(v);
    out.push_back(d);
  }
}

//------------------------------------------------------------------------------
bool vtkShadowVolumeCasters::GetBounds(double bounds[6]) const
{
  std::copy_n(this->Bounds, 6, bounds);
  return !this->Active.empty();
}
