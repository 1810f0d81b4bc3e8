#include "vtkShadowCasterGeometry.h"

#include "vtkActor.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkShadowCasterTriangles.h"
#include "vtkTimeStamp.h"
#include "vtk_glew.h"

#include "vsh_auto_general.h"
#include "vsh_mat4.h"
#include "vsh_mesh_topology.h"
#include "vsh_silhouette.h"

#include <algorithm>
#include <cmath>
#include <limits>

//------------------------------------------------------------------------------
vtkShadowCasterGeometry::vtkShadowCasterGeometry() = default;

//------------------------------------------------------------------------------
vtkShadowCasterGeometry::~vtkShadowCasterGeometry() = default;

//------------------------------------------------------------------------------
bool vtkShadowCasterGeometry::Update(vtkActor* actor)
{
  const vtkMTimeType dataTime = vtkshadow::CasterDataTime(actor);
  if (dataTime == 0)
  {
    return false;
  }
  if (dataTime <= this->DataTime && this->TriangleCount > 0)
  {
    return true;
  }
  this->DataTime = dataTime;
  vtkshadow::CasterTriangles triangles;
  if (!vtkshadow::ExtractCasterTriangles(actor, triangles))
  {
    return false;
  }
  return this->Load(triangles);
}

//------------------------------------------------------------------------------
bool vtkShadowCasterGeometry::Load(vtkshadow::CasterTriangles& triangles)
{
  std::copy_n(triangles.Shift, 3, this->Shift);
  std::vector<float>& vertices = triangles.Vertices;
  std::vector<unsigned int>& indices = triangles.Indices;
  this->Instances = triangles.Instances;
  this->TriangleCount = static_cast<vtkIdType>(indices.size() / 3);
  this->VertexCount = static_cast<vtkIdType>(vertices.size() / 3);
  // Kept for silhouettes (analysed lazily, only when a planar pass asks).
  this->Positions = vertices;
  this->Triangles = indices;
  this->Topology.reset();
  this->Closed = -1;
  this->Convex = -1;
  this->Thinnest = -1.0;
  this->TaperValid = false;
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
double vtkShadowCasterGeometry::GetThinnestWidth()
{
  if (this->Thinnest >= 0.0)
  {
    return this->Thinnest;
  }
  this->IsClosed(); // analyses the topology
  const vsh_mesh_topology* topology = this->Topology.get();
  this->Thinnest = topology && topology->positions && topology->component
    ? vsh_mesh_thinnest_width(topology->positions, topology->vertex_count,
        reinterpret_cast<const unsigned int*>(topology->component), topology->component_count)
    : std::numeric_limits<double>::infinity();
  return this->Thinnest;
}

//------------------------------------------------------------------------------
void vtkShadowCasterGeometry::ComputeTaper()
{
  this->TaperValid = true;
  this->TaperWidths.clear();
  this->TaperLengths.clear();
  this->IsClosed(); // analyses the topology
  const vsh_mesh_topology* topology = this->Topology.get();
  if (!topology || !topology->positions || !topology->component || !topology->triangles ||
    topology->component_count == 0)
  {
    return;
  }
  const size_t count = topology->component_count * VSH_MESH_TAPER_SLICES;
  this->TaperWidths.resize(count);
  this->TaperLengths.resize(count);
  if (vsh_mesh_taper_profile(topology->positions, topology->vertex_count,
        reinterpret_cast<const unsigned int*>(topology->triangles), topology->triangle_count,
        reinterpret_cast<const unsigned int*>(topology->component), topology->component_count,
        this->TaperWidths.data(), this->TaperLengths.data()) != count)
  {
    this->TaperWidths.clear();
    this->TaperLengths.clear();
  }
}

//------------------------------------------------------------------------------
const std::vector<double>& vtkShadowCasterGeometry::GetTaperWidths()
{
  if (!this->TaperValid)
  {
    this->ComputeTaper();
  }
  return this->TaperWidths;
}

//------------------------------------------------------------------------------
const std::vector<double>& vtkShadowCasterGeometry::GetTaperLengths()
{
  if (!this->TaperValid)
  {
    this->ComputeTaper();
  }
  return this->TaperLengths;
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
bool vtkShadowCasterGeometry::WorldToStored(
  const double model[16], const double world[4], double stored[4]) const
{
  double inverse[16], inData[4];
  if (!vsh_mat4_inverse(model, inverse))
  {
    return false;
  }
  vsh_mat4_transform_point4(inverse, world, inData);
  this->ShiftLight(inData, stored);
  return true;
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
  const double model[16], const double eye[3], double out[16]) const
{
  double toShifted[16], modelShifted[16], toRelative[16];
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
