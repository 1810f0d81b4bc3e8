#include "vtkShadowScene.h"

#include "vtkPlanarReflectionPass.h"
#include "vtkShadowClippingRange.h"
#include "vtkShadowDisplay.h"
#include "vtkShadowScenePrimitives.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkPLYReader.h"
#include "vtkPlanarShadowPass.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSTLReader.h"
#include "vtkShadowPassBase.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"
#include "vtkVolume.h"
#include "vtkXMLPolyDataReader.h"

#include "vsh_mesh_check.h"
#include "vsh_scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkShadowScene);

struct vtkShadowScene::Internals
{
  vsh_scene* Scene = nullptr;
  // The triangles of each object (the solid the ray tracers draw; none for a
  // volume) and, for points and polylines, the primitives VTK draws.
  std::vector<vtkSmartPointer<vtkPolyData>> Objects;
  std::vector<vtkSmartPointer<vtkPolyData>> Drawn;
  std::string Error;
  std::string FileName;

  ~Internals() { this->Clear(); }
  void Clear()
  {
    vsh_scene_free(this->Scene);
    this->Scene = nullptr;
    this->Objects.clear();
    this->Drawn.clear();
  }
};

namespace
{
// Copy a vsh_mesh (double precision) into a vtkPolyData with double points.
vtkSmartPointer<vtkPolyData> PolyDataFromMesh(const vsh_mesh& mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.point_count));
  vtkNew<vtkDoubleArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.point_count));
  for (size_t i = 0; i < mesh.point_count; ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), mesh.points + 3 * i);
    normals->SetTypedTuple(static_cast<vtkIdType>(i), mesh.normals + 3 * i);
  }
  vtkNew<vtkCellArray> triangles;
  triangles->AllocateExact(
    static_cast<vtkIdType>(mesh.triangle_count), static_cast<vtkIdType>(3 * mesh.triangle_count));
  for (size_t t = 0; t < mesh.triangle_count; ++t)
  {
    const vtkIdType ids[3] = { mesh.triangles[3 * t], mesh.triangles[3 * t + 1],
      mesh.triangles[3 * t + 2] };
    triangles->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(triangles);
  poly->GetPointData()->SetNormals(normals);
  return poly;
}

std::string LowerExtension(const std::string& path)
{
  const auto dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? "" : path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// VTK readers report problems through error events, not return values:
// collect them so that a broken mesh becomes our error, not console noise.
void CollectError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto* text = static_cast<std::string*>(clientData);
  if (text->empty() && callData)
  {
    // VTK's text is "ERROR: In FILE, line N\nCLASS (0xADDRESS): message":
    // keep the message, on one line.
    std::string message = static_cast<const char*>(callData);
    const auto address = message.rfind("): ");
    if (address != std::string::npos)
    {
      message = message.substr(address + 3);
    }
    for (char& c : message)
    {
      c = (c == '\n' || c == '\r') ? ' ' : c;
    }
    while (!message.empty() && std::isspace(static_cast<unsigned char>(message.back())))
    {
      message.pop_back();
    }
    *text = message;
  }
}

// The checker for a mesh file's format (vsh_mesh_check.h), run on its bytes
// before VTK's reader: VTK 9.1's readers crash on bad indices, truncated
// bodies and absurd counts. nullptr for an unsupported extension.
using MeshCheck = int (*)(const char*, char*, size_t);
MeshCheck CheckerFor(const std::string& ext)
{
  if (ext == ".ply")
  {
    return vsh_ply_check;
  }
  if (ext == ".obj")
  {
    return vsh_obj_check;
  }
  if (ext == ".stl")
  {
    return vsh_stl_check;
  }
  if (ext == ".vtp")
  {
    return vsh_vtp_check;
  }
  return nullptr;
}

vtkSmartPointer<vtkAlgorithm> ReaderFor(const std::string& ext, const std::string& path)
{
  if (ext == ".ply")
  {
    auto reader = vtkSmartPointer<vtkPLYReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (ext == ".obj")
  {
    auto reader = vtkSmartPointer<vtkOBJReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (ext == ".stl")
  {
    auto reader = vtkSmartPointer<vtkSTLReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(path.c_str());
  return reader;
}

// What the reader decoded, checked before any filter walks it: every cell
// array consistent and inside the points, points finite, under the limits.
// The byte checkers already guarantee this for OBJ, PLY and STL; for VTP
// (inline, appended, base64, compressed) this is the check.
bool CheckDecoded(vtkPolyData* poly, std::string& reason)
{
  char why[512] = "";
  const size_t pointCount = static_cast<size_t>(poly->GetNumberOfPoints());
  vtkDataArray* coords = poly->GetPoints() ? poly->GetPoints()->GetData() : nullptr;
  if (auto* d = vtkDoubleArray::SafeDownCast(coords))
  {
    if (vsh_points_check_double(d->GetPointer(0), pointCount, why, sizeof why) != 0)
    {
      reason = why;
      return false;
    }
  }
  else if (auto* f = vtkFloatArray::SafeDownCast(coords))
  {
    if (vsh_points_check_float(f->GetPointer(0), pointCount, why, sizeof why) != 0)
    {
      reason = why;
      return false;
    }
  }
  const struct
  {
    vtkCellArray* cells;
    const char* what;
  } arrays[] = { { poly->GetVerts(), "vertex cell" }, { poly->GetLines(), "line" },
    { poly->GetPolys(), "polygon" }, { poly->GetStrips(), "triangle strip" } };
  uint64_t triangles = 0;
  for (const auto& a : arrays)
  {
    if (!a.cells)
    {
      continue;
    }
    vsh_cell_arrays c = {};
    c.is_64bit = a.cells->IsStorage64Bit() ? 1 : 0;
    c.offsets = c.is_64bit ? static_cast<const void*>(a.cells->GetOffsetsArray64()->GetPointer(0))
                           : static_cast<const void*>(a.cells->GetOffsetsArray32()->GetPointer(0));
    c.connectivity = c.is_64bit
      ? static_cast<const void*>(a.cells->GetConnectivityArray64()->GetPointer(0))
      : static_cast<const void*>(a.cells->GetConnectivityArray32()->GetPointer(0));
    c.offset_count = static_cast<size_t>(a.cells->GetOffsetsArray()->GetNumberOfValues());
    c.connectivity_count =
      static_cast<size_t>(a.cells->GetConnectivityArray()->GetNumberOfValues());
    const bool counts = a.cells == poly->GetPolys() || a.cells == poly->GetStrips();
    if (vsh_cells_check(&c, a.what, pointCount, counts ? &triangles : nullptr, why, sizeof why))
    {
      reason = why;
      return false;
    }
  }
  return true;
}

// Check the file's bytes, read it with VTK's reader for its extension, check
// what was decoded and triangulate. Returns nullptr and sets `error` when the
// file is invalid, unreadable or has no triangles.
vtkSmartPointer<vtkPolyData> ReadTriangles(const vsh_object& object, std::string& error)
{
  const std::string path = object.mesh_resolved_path;
  const std::string ext = LowerExtension(path);
  const std::string got = "(got \"" + std::string(object.mesh_path) + "\"";
  const MeshCheck check = CheckerFor(ext);
  if (!check)
  {
    error = "unsupported mesh format " + got + "; expected .ply, .obj, .stl or .vtp)";
    return nullptr;
  }
  char reason[512] = "";
  if (check(path.c_str(), reason, sizeof(reason)) != 0)
  {
    error = "invalid mesh " + got + ": " + reason + ")";
    return nullptr;
  }
  vtkSmartPointer<vtkAlgorithm> reader = ReaderFor(ext, path);
  std::string readerError;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(CollectError);
  onError->SetClientData(&readerError);
  reader->AddObserver(vtkCommand::ErrorEvent, onError);
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, onError);
  // Last line of defence: VTK 9.1's readers size containers from header
  // fields; whatever the checkers missed must not take the process down.
  try
  {
    reader->Update();
  }
  catch (const std::exception& e)
  {
    error = "unreadable mesh " + got + ": the reader failed: " + e.what() + ")";
    return nullptr;
  }
  vtkPolyData* decoded = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!readerError.empty() || !decoded)
  {
    error =
      "unreadable mesh " + got + ": " + (readerError.empty() ? "no output" : readerError) + ")";
    return nullptr;
  }
  std::string why;
  if (!CheckDecoded(decoded, why))
  {
    error = "invalid mesh " + got + ": " + why + ")";
    return nullptr;
  }

  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(decoded);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->AddObserver(vtkCommand::ErrorEvent, onError);
  triangulate->Update();
  vtkPolyData* read = triangulate->GetOutput();
  if (!readerError.empty())
  {
    error = "unreadable mesh " + got + ": " + readerError + ")";
    return nullptr;
  }
  if (!read || read->GetNumberOfPoints() == 0 || read->GetNumberOfPolys() == 0)
  {
    error = "empty mesh, no triangles " + got + ")";
    return nullptr;
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(read);
  return out;
}

// Read a mesh file (ReadTriangles), apply the object's transform in double
// precision and compute normals.
vtkSmartPointer<vtkPolyData> ReadMesh(const vsh_object& object, std::string& error)
{
  vtkSmartPointer<vtkPolyData> read = ReadTriangles(object, error);
  if (!read)
  {
    return nullptr;
  }

  // Into our own double-precision mesh so the transform is applied exactly
  // like it is for primitives.
  vsh_mesh mesh = {};
  std::vector<double> points(3 * static_cast<size_t>(read->GetNumberOfPoints()));
  std::vector<double> normals(points.size(), 0.0);
  for (vtkIdType i = 0; i < read->GetNumberOfPoints(); ++i)
  {
    read->GetPoint(i, points.data() + 3 * i);
  }
  for (double v : points)
  {
    if (!std::isfinite(v))
    {
      error =
        "mesh has a non-finite point coordinate (got \"" + std::string(object.mesh_path) + "\")";
      return nullptr;
    }
  }
  mesh.points = points.data();
  mesh.normals = normals.data();
  mesh.point_count = static_cast<size_t>(read->GetNumberOfPoints());
  if (object.has_transform)
  {
    vsh_mesh_transform(&mesh, object.transform);
  }
  vtkNew<vtkPoints> transformed;
  transformed->SetDataTypeToDouble();
  transformed->SetNumberOfPoints(read->GetNumberOfPoints());
  for (vtkIdType i = 0; i < read->GetNumberOfPoints(); ++i)
  {
    transformed->SetPoint(i, points.data() + 3 * i);
  }
  vtkNew<vtkPolyData> world;
  world->SetPoints(transformed);
  world->SetPolys(read->GetPolys());

  // Smooth normals with feature edges split at 30 degrees (VTK's default),
  // so faceted CAD parts stay faceted and scanned surfaces stay smooth.
  vtkNew<vtkPolyDataNormals> withNormals;
  withNormals->SetInputData(world);
  withNormals->ComputePointNormalsOn();
  withNormals->ComputeCellNormalsOff();
  withNormals->SplittingOn();
  withNormals->ConsistencyOn();
  withNormals->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  withNormals->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(withNormals->GetOutput());
  return out;
}
} // namespace

//------------------------------------------------------------------------------
vtkShadowScene::vtkShadowScene()
  : Impl(new Internals)
{
}

//------------------------------------------------------------------------------
vtkShadowScene::~vtkShadowScene() = default;

//------------------------------------------------------------------------------
bool vtkShadowScene::Load(const char* path)
{
  this->Impl->Clear();
  this->Impl->Error.clear();
  this->Impl->FileName = path ? path : "";
  if (!path || !*path)
  {
    this->Impl->Error = "(no file): scene file name is empty";
    return false;
  }
  char err[VSH_SCENE_ERROR_MAX];
  vsh_scene* scene = nullptr;
  if (vsh_scene_load(path, &scene, err, sizeof(err)) != 0)
  {
    this->Impl->Error = err;
    return false;
  }
  return this->LoadParsed(scene, path);
}

//------------------------------------------------------------------------------
bool vtkShadowScene::LoadParsed(vsh_scene* scene, const char* path)
{
  this->Impl->Clear();
  this->Impl->Error.clear();
  this->Impl->FileName = path ? path : "";
  if (!scene)
  {
    this->Impl->Error = this->Impl->FileName + ": no parsed scene";
    return false;
  }
  path = this->Impl->FileName.c_str();
  std::vector<vtkSmartPointer<vtkPolyData>> objects, drawn(scene->object_count);
  for (size_t i = 0; i < scene->object_count; ++i)
  {
    const vsh_object& object = scene->objects[i];
    if (object.kind == VSH_OBJECT_POINTS || object.kind == VSH_OBJECT_POLYLINE)
    {
      drawn[i] = vtkshadow::NewImpostorPolyData(object);
    }
    if (object.kind == VSH_OBJECT_VOLUME)
    {
      objects.push_back(vtkSmartPointer<vtkPolyData>::New());
      continue;
    }
    if (object.kind == VSH_OBJECT_MESH)
    {
      std::string error;
      auto poly = ReadMesh(object, error);
      if (!poly)
      {
        this->Impl->Error =
          std::string(path) + ": objects[" + std::to_string(i) + "].mesh: " + error;
        vsh_scene_free(scene);
        return false;
      }
      objects.push_back(poly);
      continue;
    }
    vsh_mesh mesh = {};
    if (vsh_object_tessellate(&object, &mesh) != 0)
    {
      this->Impl->Error = std::string(path) + ": objects[" + std::to_string(i) + "]." +
        vsh_object_kind_name(object.kind) + ": tessellation failed";
      vsh_scene_free(scene);
      return false;
    }
    objects.push_back(PolyDataFromMesh(mesh));
    vsh_mesh_free(&mesh);
  }
  this->Impl->Scene = scene;
  this->Impl->Objects = std::move(objects);
  this->Impl->Drawn = std::move(drawn);
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
const vsh_scene* vtkShadowScene::GetParsedScene() const
{
  return this->Impl->Scene;
}

//------------------------------------------------------------------------------
const char* vtkShadowScene::GetErrorMessage() const
{
  return this->Impl->Error.c_str();
}

//------------------------------------------------------------------------------
const char* vtkShadowScene::GetFileName() const
{
  return this->Impl->FileName.c_str();
}

//------------------------------------------------------------------------------
int vtkShadowScene::GetWidth() const
{
  return this->Impl->Scene ? this->Impl->Scene->width : 0;
}

//------------------------------------------------------------------------------
int vtkShadowScene::GetHeight() const
{
  return this->Impl->Scene ? this->Impl->Scene->height : 0;
}

//------------------------------------------------------------------------------
int vtkShadowScene::GetNumberOfLights() const
{
  return this->Impl->Scene ? static_cast<int>(this->Impl->Scene->light_count) : 0;
}

//------------------------------------------------------------------------------
int vtkShadowScene::GetNumberOfObjects() const
{
  return static_cast<int>(this->Impl->Objects.size());
}

//------------------------------------------------------------------------------
const char* vtkShadowScene::GetLightTypeName(int light) const
{
  if (light < 0 || light >= this->GetNumberOfLights())
  {
    return nullptr;
  }
  return vsh_light_type_name(this->Impl->Scene->lights[light].type);
}

//------------------------------------------------------------------------------
double vtkShadowScene::GetLightRadius(int light) const
{
  if (light < 0 || light >= this->GetNumberOfLights())
  {
    return 0.0;
  }
  return this->Impl->Scene->lights[light].radius;
}

double vtkShadowScene::GetLightAngle(int light) const
{
  if (light < 0 || light >= this->GetNumberOfLights())
  {
    return 0.0;
  }
  return this->Impl->Scene->lights[light].angle;
}

vtkLight* vtkShadowScene::NewLight(int index) const
{
  if (index < 0 || index >= this->GetNumberOfLights())
  {
    vtkErrorMacro("NewLight: light " << index << " out of range");
    return nullptr;
  }
  const vsh_light& l = this->Impl->Scene->lights[index];
  vtkLight* light = vtkLight::New();
  light->SetLightTypeToSceneLight();
  light->SetColor(l.color[0], l.color[1], l.color[2]);
  light->SetIntensity(l.intensity);
  light->SetAttenuationValues(1.0, 0.0, 0.0);
  switch (l.type)
  {
    case VSH_LIGHT_DIRECTIONAL:
    {
      // VTK's directional light shines from Position towards FocalPoint;
      // put it at the scene centre minus the direction so both stay finite.
      double b[6];
      this->GetBounds(b);
      const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
      light->SetPositional(false);
      light->SetFocalPoint(c);
      light->SetPosition(c[0] - l.direction[0], c[1] - l.direction[1], c[2] - l.direction[2]);
      break;
    }
    case VSH_LIGHT_POINT:
      light->SetPositional(true);
      light->SetPosition(l.position[0], l.position[1], l.position[2]);
      light->SetFocalPoint(l.position[0], l.position[1], l.position[2] - 1.0);
      light->SetConeAngle(180.0);
      break;
    case VSH_LIGHT_SPOT:
      light->SetPositional(true);
      light->SetPosition(l.position[0], l.position[1], l.position[2]);
      light->SetFocalPoint(l.focal_point[0], l.focal_point[1], l.focal_point[2]);
      light->SetConeAngle(l.cone_angle);
      // A hard-edged cone, uniform inside, as the ray tracers are configured.
      light->SetExponent(0.0);
      break;
  }
  // Hard lights carry the keys too (0), so a pass can tell "this scene says
  // hard" from "a light made elsewhere" if it ever needs to.
  vtkShadowPassBase::SetLightSize(light, l.radius, l.angle);
  return light;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkShadowScene::GetObjectPolyData(int object) const
{
  if (object < 0 || object >= this->GetNumberOfObjects())
  {
    return nullptr;
  }
  return this->Impl->Objects[object];
}

//------------------------------------------------------------------------------
bool vtkShadowScene::GetObjectIsReceiver(int object) const
{
  return object >= 0 && object < this->GetNumberOfObjects() &&
    this->Impl->Scene->objects[object].receiver;
}

//------------------------------------------------------------------------------
bool vtkShadowScene::GetObjectCasts(int object) const
{
  return object >= 0 && object < this->GetNumberOfObjects() &&
    this->Impl->Scene->objects[object].casts;
}

//------------------------------------------------------------------------------
void vtkShadowScene::GetObjectColor(int object, double color[3]) const
{
  color[0] = color[1] = color[2] = 1.0;
  if (object >= 0 && object < this->GetNumberOfObjects())
  {
    std::copy_n(this->Impl->Scene->objects[object].color, 3, color);
  }
}

//------------------------------------------------------------------------------
double vtkShadowScene::GetObjectOpacity(int object) const
{
  return object >= 0 && object < this->GetNumberOfObjects()
    ? this->Impl->Scene->objects[object].opacity
    : 1.0;
}

//------------------------------------------------------------------------------
double vtkShadowScene::GetObjectFilter(int object) const
{
  return object >= 0 && object < this->GetNumberOfObjects()
    ? this->Impl->Scene->objects[object].filter
    : 0.0;
}

//------------------------------------------------------------------------------
const char* vtkShadowScene::GetObjectKindName(int object) const
{
  if (object < 0 || object >= this->GetNumberOfObjects())
  {
    return nullptr;
  }
  return vsh_object_kind_name(this->Impl->Scene->objects[object].kind);
}

//------------------------------------------------------------------------------
void vtkShadowScene::GetBounds(double bounds[6]) const
{
  vtkMath::UninitializeBounds(bounds);
  bool first = true;
  for (size_t i = 0; i < this->Impl->Objects.size(); ++i)
  {
    double b[6];
    const vsh_object& object = this->Impl->Scene->objects[i];
    if (object.kind == VSH_OBJECT_VOLUME)
    {
      for (int a = 0; a < 3; ++a)
      {
        b[2 * a] = object.center[a] - object.radius;
        b[2 * a + 1] = object.center[a] + object.radius;
      }
    }
    else
    {
      this->Impl->Objects[i]->GetBounds(b);
    }
    for (int a = 0; a < 3; ++a)
    {
      bounds[2 * a] = first ? b[2 * a] : std::min(bounds[2 * a], b[2 * a]);
      bounds[2 * a + 1] = first ? b[2 * a + 1] : std::max(bounds[2 * a + 1], b[2 * a + 1]);
    }
    first = false;
  }
}

//------------------------------------------------------------------------------
void vtkShadowScene::ConfigureCamera(vtkCamera* camera) const
{
  if (!camera || !this->Impl->Scene)
  {
    return;
  }
  const vsh_camera& c = this->Impl->Scene->camera;
  camera->SetPosition(c.position[0], c.position[1], c.position[2]);
  camera->SetFocalPoint(c.focal_point[0], c.focal_point[1], c.focal_point[2]);
  camera->SetViewUp(c.view_up[0], c.view_up[1], c.view_up[2]);
  camera->SetViewAngle(c.view_angle);
  camera->ParallelProjectionOff();
}

//------------------------------------------------------------------------------
bool vtkShadowScene::Populate(vtkRenderer* renderer, bool lambertian, int onlyLight) const
{
  return this->PopulateWith(renderer, lambertian ? 1 : 0, onlyLight);
}

//------------------------------------------------------------------------------
bool vtkShadowScene::PopulateMatte(vtkRenderer* renderer, int onlyLight) const
{
  return this->PopulateWith(renderer, 2, onlyLight);
}

//------------------------------------------------------------------------------
double vtkShadowScene::GetObjectMirror(int object) const
{
  return object >= 0 && object < this->GetNumberOfObjects() &&
      this->Impl->Scene->objects[object].has_mirror
    ? this->Impl->Scene->objects[object].mirror
    : 0.0;
}

//------------------------------------------------------------------------------
bool vtkShadowScene::HasMirrors() const
{
  for (int i = 0; i < this->GetNumberOfObjects(); ++i)
    if (this->GetObjectMirror(i) > 0)
      return true;
  return false;
}

//------------------------------------------------------------------------------
// mode 0: the scene's colours with a little ambient and specular; 1: white
// Lambertian; 2: matte, the scene's colours, diffuse 1, no ambient or
// specular (what the ray tracers render).
bool vtkShadowScene::PopulateWith(vtkRenderer* renderer, int mode, int onlyLight) const
{
  const bool lambertian = mode == 1;
  if (!renderer || !this->Impl->Scene)
  {
    vtkErrorMacro("Populate: no renderer or no scene loaded");
    return false;
  }
  if (onlyLight >= this->GetNumberOfLights())
  {
    vtkErrorMacro("Populate: light " << onlyLight << " out of range");
    return false;
  }
  // Every window of the process shares one X connection (vtkShadowDisplay):
  // attached before its first render, or VTK opens (and later closes) its own.
  if (!vtkShadowDisplay::Attach(renderer->GetRenderWindow()))
  {
    vtkErrorMacro("Populate: " << vtkShadowDisplay::GetErrorMessage());
    return false;
  }
  // The scene's point sizes and line widths are pixels of its own image
  // size: scaled with the window, the impostors keep their world size.
  const int* windowSize = renderer->GetRenderWindow()->GetSize();
  const double pixelScale =
    windowSize[1] > 0 ? static_cast<double>(windowSize[1]) / this->Impl->Scene->height : 1.0;
  for (int i = 0; i < this->GetNumberOfObjects(); ++i)
  {
    const vsh_object& object = this->Impl->Scene->objects[i];
    if (object.kind == VSH_OBJECT_VOLUME)
    {
      this->AddBlob(renderer, i, lambertian);
      continue;
    }
    vtkSmartPointer<vtkActor> actor;
    if (this->Impl->Drawn[i])
    {
      actor = vtkshadow::NewImpostorActor(object, this->Impl->Drawn[i], pixelScale);
    }
    else
    {
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(this->Impl->Objects[i]);
      mapper->ScalarVisibilityOff();
      actor = vtkSmartPointer<vtkActor>::New();
      actor->SetMapper(mapper);
    }
    vtkProperty* p = actor->GetProperty();
    p->SetInterpolationToPhong();
    p->SetOpacity(this->GetObjectOpacity(i));
    if (lambertian)
    {
      // A translucent object adds nothing of its own to the visibility
      // renders, only the (1 - opacity) blend factor that cancels in
      // I_on / I_off: the measure stays that of the opaque surface behind
      // it, as in the references, where the camera does not see it.
      // Its colour stays: a filter tints what it lets through by it.
      const bool translucent = this->GetObjectOpacity(i) < 1.0;
      double color[3] = { 1.0, 1.0, 1.0 };
      if (translucent)
      {
        this->GetObjectColor(i, color);
      }
      p->SetColor(color);
      p->SetAmbient(0.0);
      p->SetDiffuse(translucent ? 0.0 : 1.0);
      p->SetSpecular(0.0);
    }
    else
    {
      double color[3];
      this->GetObjectColor(i, color);
      p->SetColor(color);
      p->SetAmbient(mode == 2 ? 0.0 : 0.05);
      p->SetDiffuse(mode == 2 ? 1.0 : 0.9);
      p->SetSpecular(mode == 2 ? 0.0 : 0.1);
      p->SetSpecularPower(30.0);
    }
    // Tell shadow techniques which objects receive and which do not cast.
    vtkNew<vtkInformation> keys;
    keys->Set(vtkShadowPassBase::RECEIVER(), this->GetObjectIsReceiver(i) ? 1 : 0);
    keys->Set(vtkShadowPassBase::NO_CAST(), this->GetObjectCasts(i) ? 0 : 1);
    if (this->GetObjectFilter(i) > 0.0)
    {
      keys->Set(vtkShadowPassBase::FILTER(), this->GetObjectFilter(i));
    }
    if (this->GetObjectMirror(i) > 0)
    {
      keys->Set(vtkPlanarReflectionPass::MIRROR(), this->GetObjectMirror(i));
    }
    actor->SetPropertyKeys(keys);
    renderer->AddActor(actor);
  }
  renderer->AutomaticLightCreationOff();
  renderer->RemoveAllLights();
  for (int k = 0; k < this->GetNumberOfLights(); ++k)
  {
    if (onlyLight >= 0 && k != onlyLight)
    {
      continue;
    }
    vtkLight* light = this->NewLight(k);
    renderer->AddLight(light);
    light->Delete();
  }
  const double* bg = this->Impl->Scene->background;
  renderer->SetBackground(bg[0], bg[1], bg[2]);
  this->ConfigureCamera(renderer->GetActiveCamera());
  vtkShadowScene::ResetCameraClippingRange(renderer);
  return true;
}

//------------------------------------------------------------------------------
// A volume adds nothing of its own to the visibility renders (black, as a
// translucent surface there): its view transmittance multiplies I_on and
// I_off alike, so their ratio stays the visibility of what is behind it.
void vtkShadowScene::AddBlob(vtkRenderer* renderer, int object, bool lambertian) const
{
  double color[3] = { 0.0, 0.0, 0.0 };
  if (!lambertian)
  {
    this->GetObjectColor(object, color);
  }
  auto volume = vtkshadow::NewBlobVolume(this->Impl->Scene->objects[object], color);
  vtkNew<vtkInformation> keys;
  keys->Set(vtkShadowPassBase::NO_CAST(), this->GetObjectCasts(object) ? 0 : 1);
  volume->SetPropertyKeys(keys);
  renderer->AddVolume(volume);
}

//------------------------------------------------------------------------------
void vtkShadowScene::ResetCameraClippingRange(vtkRenderer* renderer)
{
  vtkshadow::ResetClippingRange(renderer);
}

//------------------------------------------------------------------------------
void vtkShadowScene::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->Impl->FileName << "\n";
  os << indent << "ErrorMessage: " << this->Impl->Error << "\n";
  os << indent << "Size: " << this->GetWidth() << " x " << this->GetHeight() << "\n";
  os << indent << "NumberOfLights: " << this->GetNumberOfLights() << "\n";
  os << indent << "NumberOfObjects: " << this->GetNumberOfObjects() << "\n";
}
