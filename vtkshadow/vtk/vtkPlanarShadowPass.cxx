#include "vtkPlanarShadowPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkSmartPointer.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowCasterGeometry.h"
#include "vtkShadowLightingHook.h"
#include "vtkShadowReceiverPlane.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vsh_mat4.h"
#include "vsh_planar.h"

#include "vtkPlanarShadowLightFS.h"
#include "vtkPlanarShadowMaskFS.h"
#include "vtkPlanarShadowMaskVS.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPlanarShadowPass);

namespace
{
constexpr int MaxPairs = 128;
constexpr int MaxExplicitPlanes = 8;


// Row vector (plane) times matrix: a plane acting on the matrix's input space.
void PlaneTimesMatrix(const double plane[4], const double m[16], double out[4])
{
  for (int c = 0; c < 4; ++c)
  {
    out[c] = plane[0] * m[c] + plane[1] * m[4 + c] + plane[2] * m[8 + c] + plane[3] * m[12 + c];
  }
}

void ToFloat(const double* in, float* out, int n)
{
  for (int i = 0; i < n; ++i)
  {
    out[i] = static_cast<float>(in[i]);
  }
}

// Whether an actor's world bounds lie within 1e-6 of their size of the plane.
bool LiesInPlane(vtkActor* actor, const double plane[4])
{
  double b[6];
  actor->GetBounds(b);
  const double size = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4], 1e-300 });
  for (int k = 0; k < 8; ++k)
  {
    const double p[3] = { b[k & 1], b[2 + ((k >> 1) & 1)], b[4 + ((k >> 2) & 1)] };
    if (std::abs(plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3]) > 1e-6 * size)
    {
      return false;
    }
  }
  return true;
}

} // namespace

struct vtkPlanarShadowPass::Internals
{
  struct ExplicitPlane
  {
    double Origin[3];
    double Normal[3];
  };
  struct CachedPlane
  {
    vtkMTimeType Time = 0;
    bool Flat = false;
    double Plane[4] = { 0, 0, 0, 0 };
  };
  struct Caster
  {
    vtkShadowCasterGeometry Geometry;
    vtkMTimeType SeenFrame = 0;
  };

  std::vector<vtkWeakPointer<vtkActor>> ReceiverActors;
  std::vector<ExplicitPlane> Planes;
  std::map<vtkActor*, CachedPlane> ReceiverPlanes;
  std::map<vtkActor*, std::unique_ptr<Caster>> Casters;
  vtkMTimeType Frame = 0;

  vtkTextureObject* Mask = nullptr;
  vtkOpenGLFramebufferObject* FBO = nullptr;
  // Stencil for silhouette fans (winding numbers), and a screen quad.
  unsigned int Stencil = 0;
  int StencilSize[2] = { 0, 0 };
  vtkSmartPointer<vtkOpenGLBufferObject> Quad;
  vtkSmartPointer<vtkOpenGLVertexArrayObject> QuadVAO;
  vtkShaderProgram* QuadProgram = nullptr;
  int MaskSize[2] = { 0, 0 };
  int MaskChannels = 4; // 32-bit channels: 1 up to 32 pairs, else 4
  int MaskOrigin[2] = { 0, 0 };

  // Per-frame values for SetShaderParameters.
  std::map<vtkProp*, int> ReceiverIndex;
  int LightCount = 0;
  int PlaneCount = 0;
  float PlaneVC[4 * MaxExplicitPlanes] = {};
  int PlaneReceiver[MaxExplicitPlanes] = {};
  float PlaneTolerance[MaxExplicitPlanes] = {};
  std::vector<vtkProp*> Receiving; // sorted (from the map)
  bool EveryoneReceives = false;

  bool CanReceive(vtkProp* prop) const
  {
    return this->EveryoneReceives ||
      std::binary_search(this->Receiving.begin(), this->Receiving.end(), prop);
  }
};

//------------------------------------------------------------------------------
vtkPlanarShadowPass::vtkPlanarShadowPass()
  : PlaneTolerance(1e-5)
  , NumberOfShadowPairs(0)
  , NumberOfMaskTriangles(0)
  , NumberOfGeometryBuilds(0)
  , Impl(new Internals)
{
}

//------------------------------------------------------------------------------
vtkPlanarShadowPass::~vtkPlanarShadowPass()
{
  if (this->Impl->Mask)
  {
    this->Impl->Mask->Delete();
  }
  if (this->Impl->FBO)
  {
    this->Impl->FBO->Delete();
  }
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::AddReceiverActor(vtkActor* actor)
{
  if (actor)
  {
    this->Impl->ReceiverActors.emplace_back(actor);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::RemoveReceiverActor(vtkActor* actor)
{
  auto& list = this->Impl->ReceiverActors;
  list.erase(std::remove_if(list.begin(), list.end(),
               [&](const vtkWeakPointer<vtkActor>& a) { return a == actor || !a; }),
    list.end());
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::AddReceiverPlane(
  double ox, double oy, double oz, double nx, double ny, double nz)
{
  const double length = std::sqrt(nx * nx + ny * ny + nz * nz);
  if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(ox + oy + oz))
  {
    vtkErrorMacro("AddReceiverPlane: the normal must be finite and non-zero, the origin finite");
    return;
  }
  if (static_cast<int>(this->Impl->Planes.size()) >= MaxExplicitPlanes)
  {
    vtkErrorMacro("AddReceiverPlane: at most " << MaxExplicitPlanes << " explicit planes");
    return;
  }
  this->Impl->Planes.push_back({ { ox, oy, oz }, { nx / length, ny / length, nz / length } });
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::RemoveAllReceivers()
{
  this->Impl->ReceiverActors.clear();
  this->Impl->Planes.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
long long vtkPlanarShadowPass::GetMemoryBytes() const
{
  long long bytes = static_cast<long long>(this->Impl->MaskSize[0]) * this->Impl->MaskSize[1] * 4 *
    this->Impl->MaskChannels;
  for (const auto& entry : this->Impl->Casters)
  {
    bytes += entry.second->Geometry.GetNumberOfBytes();
  }
  return bytes;
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->NumberOfShadowPairs = 0;
  this->NumberOfMaskTriangles = 0;
  vtkRenderer* renderer = s->GetRenderer();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro("vtkPlanarShadowPass needs an OpenGL render window");
    return;
  }
  Internals& impl = *this->Impl;
  ++impl.Frame;

  // Viewport of this renderer in the target: the mask matches it pixel for pixel.
  int size[2], origin[2];
  GetViewport(s, size, origin);
  impl.MaskOrigin[0] = origin[0];
  impl.MaskOrigin[1] = origin[1];

  // Lights in the mapper's numbering: every switched-on light, in order.
  struct LightInfo
  {
    double Homogeneous[4];
    bool Casts;
  };
  // Lights that follow the camera (and the automatic headlight) are updated
  // by VTK's lights pass inside the delegate, after our shadow work: bring
  // them up to date now, or their shadows lag one frame behind.
  vtkshadow::UpdateLights(renderer);
  std::vector<LightInfo> lights;
  {
    for (vtkLight* light : vtkshadow::SwitchedOnLights(renderer))
    {
      LightInfo info;
      vtkshadow::LightHomogeneous(light, info.Homogeneous);
      info.Casts = this->LightCasts(light, static_cast<int>(lights.size()));
      lights.push_back(info);
    }
  }
  impl.LightCount = static_cast<int>(lights.size());

  // Props: receivers and casters.
  std::vector<vtkActor*> casters;
  struct ReceiverInfo
  {
    vtkActor* Actor;
    double Plane[4];
  };
  std::vector<ReceiverInfo> receivers;
  impl.ReceiverIndex.clear();
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    auto* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    if (!actor || !actor->GetVisibility() || !actor->GetMapper())
    {
      continue;
    }
    const bool opaque = !actor->HasTranslucentPolygonalGeometry();
    bool receiver = vtkshadow::HasFlag(actor, RECEIVER());
    for (const auto& r : impl.ReceiverActors)
    {
      receiver = receiver || r == actor;
    }
    if (receiver && opaque)
    {
      Internals::CachedPlane& cached = impl.ReceiverPlanes[actor];
      vtkMTimeType t = actor->GetMTime();
      if (auto* data = actor->GetMapper()->GetInputDataObject(0, 0))
      {
        t = std::max(t, data->GetMTime());
      }
      t = std::max(t, actor->GetMapper()->GetMTime());
      if (t > cached.Time)
      {
        cached.Time = t;
        cached.Flat = vtkshadow::ReceiverPlane(actor, cached.Plane);
        if (!cached.Flat)
        {
          vtkWarningMacro("receiver actor " << actor << " is not flat: it receives no shadow");
        }
      }
      // Every (receiver, light) pair needs a mask bit: at most 128 of them.
      if (cached.Flat && (static_cast<int>(receivers.size()) + 1) * std::max<int>(impl.LightCount, 1) > MaxPairs)
      {
        vtkWarningMacro("more receivers than " << MaxPairs << " mask bits allow for "
                                               << impl.LightCount << " lights: ignoring some");
      }
      else if (cached.Flat)
      {
        ReceiverInfo info{ actor, {} };
        std::copy_n(cached.Plane, 4, info.Plane);
        impl.ReceiverIndex[actor] = static_cast<int>(receivers.size());
        receivers.push_back(info);
      }
    }
    if (opaque && !vtkshadow::HasFlag(actor, NO_CAST()))
    {
      casters.push_back(actor);
    }
  }
  // Only receiving actors get the shadow lookup in their shaders; when the set
  // changes, VTK's mappers must rebuild their shaders.
  {
    std::vector<vtkProp*> receiving;
    for (const auto& entry : impl.ReceiverIndex)
    {
      receiving.push_back(entry.first);
    }
    const bool everyone = !impl.Planes.empty();
    if (receiving != impl.Receiving || everyone != impl.EveryoneReceives)
    {
      impl.Receiving = receiving;
      impl.EveryoneReceives = everyone;
      this->BumpShaderTime();
    }
  }
  for (const auto& p : impl.Planes)
  {
    ReceiverInfo info{ nullptr, { p.Normal[0], p.Normal[1], p.Normal[2],
                                  -(p.Normal[0] * p.Origin[0] + p.Normal[1] * p.Origin[1] +
                                    p.Normal[2] * p.Origin[2]) } };
    receivers.push_back(info);
  }

  // Camera: projection times the eye-relative view rotation, in double.
  vtkCamera* camera = renderer->GetActiveCamera();
  const double aspect = size[1] > 0 ? static_cast<double>(size[0]) / size[1] : 1.0;
  double eye[3];
  camera->GetPosition(eye);
  double view[16], projection[16], cameraRelative[16];
  vtkMatrix4x4::DeepCopy(view, camera->GetViewTransformMatrix());
  view[3] = view[7] = view[11] = 0.0; // rotation only: inputs are relative to the eye
  vtkMatrix4x4::DeepCopy(projection, camera->GetProjectionTransformMatrix(aspect, -1, 1));
  vsh_mat4_multiply(projection, view, cameraRelative);

  // Explicit planes in view coordinates for the receivers' fragment shaders.
  impl.PlaneCount = 0;
  for (size_t r = 0; r < receivers.size(); ++r)
  {
    if (receivers[r].Actor || impl.PlaneCount >= MaxExplicitPlanes)
    {
      continue;
    }
    const double* pl = receivers[r].Plane;
    double nvc[3];
    vsh_mat4_transform_direction(view, pl, nvc);
    const double d = pl[3] + pl[0] * eye[0] + pl[1] * eye[1] + pl[2] * eye[2];
    float* out = impl.PlaneVC + 4 * impl.PlaneCount;
    ToFloat(nvc, out, 3);
    out[3] = static_cast<float>(d);
    impl.PlaneReceiver[impl.PlaneCount] = static_cast<int>(r);
    impl.PlaneTolerance[impl.PlaneCount] = static_cast<float>(this->PlaneTolerance);
    ++impl.PlaneCount;
  }

  // The mask target, sized to the viewport.
  vtkOpenGLState* state = window->GetState();
  if (!impl.Mask)
  {
    impl.Mask = vtkTextureObject::New();
    impl.FBO = vtkOpenGLFramebufferObject::New();
  }
  impl.Mask->SetContext(window);
  impl.FBO->SetContext(window);
  // One 32-bit channel while the pairs fit in it: clearing, writing and
  // reading a quarter of the bytes is most of the pass's per-pixel cost on a
  // software rasterizer. Up to 128 pairs need all four channels. (The
  // lighting code reads .x for pairs 0..31 either way.)
  const int maskChannels = static_cast<int>(receivers.size()) * impl.LightCount <= 32 ? 1 : 4;
  if (impl.MaskSize[0] != size[0] || impl.MaskSize[1] != size[1] || !impl.Mask->GetHandle() ||
    impl.MaskChannels != maskChannels)
  {
    impl.Mask->ReleaseGraphicsResources(window);
    impl.Mask->SetRequireTextureInteger(true);
    impl.Mask->SetInternalFormat(maskChannels == 1 ? GL_R32UI : GL_RGBA32UI);
    impl.Mask->SetFormat(maskChannels == 1 ? GL_RED_INTEGER : GL_RGBA_INTEGER);
    impl.Mask->SetDataType(GL_UNSIGNED_INT);
    impl.Mask->SetMinificationFilter(vtkTextureObject::Nearest);
    impl.Mask->SetMagnificationFilter(vtkTextureObject::Nearest);
    impl.Mask->Allocate2D(size[0], size[1], maskChannels, VTK_UNSIGNED_INT);
    impl.MaskSize[0] = size[0];
    impl.MaskSize[1] = size[1];
    impl.MaskChannels = maskChannels;
  }

  state->PushFramebufferBindings();
  impl.FBO->Bind();
  impl.FBO->AddColorAttachment(0, impl.Mask);
  impl.FBO->ActivateDrawBuffers(1);
  if (!impl.Stencil || impl.StencilSize[0] != size[0] || impl.StencilSize[1] != size[1])
  {
    if (!impl.Stencil)
    {
      glGenRenderbuffers(1, &impl.Stencil);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, impl.Stencil);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, size[0], size[1]);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    impl.StencilSize[0] = size[0];
    impl.StencilSize[1] = size[1];
  }
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, impl.Stencil);
  {
    vtkOpenGLState::ScopedglViewport viewport(state);
    vtkOpenGLState::ScopedglScissor scissorBox(state);
    vtkOpenGLState::ScopedglEnableDisable stencil(state, GL_STENCIL_TEST);
    vtkOpenGLState::ScopedglEnableDisable depth(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
    vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglColorMask colorMask(state);
    state->vtkglViewport(0, 0, size[0], size[1]);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    const GLuint zero[4] = { 0, 0, 0, 0 };
    glClearBufferuiv(GL_COLOR, 0, zero);

    const int pairs = static_cast<int>(receivers.size()) * impl.LightCount;
    vtkShaderProgram* program = nullptr;
    if (pairs > 0)
    {
      program = window->GetShaderCache()->ReadyShaderProgram(
        vtkPlanarShadowMaskVS, vtkPlanarShadowMaskFS, "");
    }
    if (program)
    {
      // Overlapping shadow triangles and casters only set the same bit again.
      glEnable(GL_COLOR_LOGIC_OP);
      glLogicOp(GL_OR);
      glEnable(GL_CLIP_DISTANCE0);
      glEnable(GL_CLIP_DISTANCE1);
      for (size_t r = 0; r < receivers.size(); ++r)
      {
        for (int l = 0; l < impl.LightCount; ++l)
        {
          const int pair = static_cast<int>(r) * impl.LightCount + l;
          if (!lights[l].Casts || pair >= MaxPairs)
          {
            continue;
          }
          // Orient the plane towards the light: its lit side is the light's side.
          double plane[4];
          std::copy_n(receivers[r].Plane, 4, plane);
          const double* light = lights[l].Homogeneous;
          const double side = plane[0] * light[0] + plane[1] * light[1] + plane[2] * light[2] +
            plane[3] * light[3];
          if (side < 0)
          {
            for (double& v : plane)
            {
              v = -v;
            }
          }
          double shadow[16], clip[2][4];
          if (vsh_planar_shadow_matrix_relative(plane, light, eye, shadow) != VSH_PLANAR_OK ||
            vsh_planar_caster_clip_planes_relative(plane, light, eye, clip) != VSH_PLANAR_OK)
          {
            continue; // light on, behind or parallel to the plane: no shadow
          }
          ++this->NumberOfShadowPairs;
          double shadowDC[16];
          vsh_mat4_multiply(cameraRelative, shadow, shadowDC);
          unsigned int bits[4] = { 0, 0, 0, 0 };
          bits[pair / 32] = 1u << (pair % 32);
          glUniform4uiv(glGetUniformLocation(program->GetHandle(), "pairBit"), 1, bits);
          struct Fan
          {
            vtkShadowCasterGeometry* Geometry;
            float MCDC[16];
            double Light[4];
          };
          std::vector<Fan> fans;
          double fanRect[4] = { 1e300, 1e300, -1e300, -1e300 }; // NDC x0 y0 x1 y1
          bool fanRectFull = false;
          for (vtkActor* actor : casters)
          {
            if (actor == receivers[r].Actor)
            {
              continue; // a flat receiver does not shadow itself
            }
            if (!receivers[r].Actor && LiesInPlane(actor, receivers[r].Plane))
            {
              continue; // nor does a surface lying in an explicit receiver plane
            }
            auto& caster = impl.Casters[actor];
            if (!caster)
            {
              caster.reset(new Internals::Caster);
            }
            if (caster->SeenFrame != impl.Frame)
            {
              const vtkMTimeType built = caster->Geometry.GetBuildTime();
              caster->Geometry.Update(actor);
              if (caster->Geometry.GetBuildTime() != built)
              {
                ++this->NumberOfGeometryBuilds;
              }
              caster->SeenFrame = impl.Frame;
            }
            if (caster->Geometry.GetNumberOfTriangles() == 0)
            {
              continue;
            }
            // Model (shifted) -> world -> relative to the eye, in double.
            double model[16], modelRelative[16];
            vtkMatrix4x4::DeepCopy(model, actor->GetMatrix());
            caster->Geometry.GetModelRelativeMatrix(actor, eye, modelRelative);
            double mcdc[16], keep0[4], keep1[4];
            vsh_mat4_multiply(shadowDC, modelRelative, mcdc);
            PlaneTimesMatrix(clip[0], modelRelative, keep0);
            PlaneTimesMatrix(clip[1], modelRelative, keep1);
            float mcdcF[16], keep0F[4], keep1F[4];
            // vtkShaderProgram expects column-major (OpenGL) order.
            double transposed[16];
            vsh_mat4_transpose(mcdc, transposed);
            ToFloat(transposed, mcdcF, 16);
            ToFloat(keep0, keep0F, 4);
            ToFloat(keep1, keep1F, 4);
            // Clipping costs a software rasterizer a stage per triangle: skip
            // it when every corner of the caster's bounds is kept anyway.
            double b[6];
            actor->GetBounds(b);
            bool clipNeeded = false;
            for (int k = 0; k < 8 && !clipNeeded; ++k)
            {
              const double p[3] = { b[k & 1] - eye[0], b[2 + ((k >> 1) & 1)] - eye[1],
                b[4 + ((k >> 2) & 1)] - eye[2] };
              for (const auto& plane : clip)
              {
                clipNeeded = clipNeeded ||
                  plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3] <= 0.0;
              }
            }
            if (!clipNeeded && caster->Geometry.IsClosed())
            {
              // Closed and unclipped: its silhouette fans, counted in the
              // stencil below, cover exactly what its triangles would.
              Fan fan;
              fan.Geometry = &caster->Geometry;
              std::copy_n(mcdcF, 16, fan.MCDC);
              double inverse[16];
              if (vsh_mat4_inverse(model, inverse))
              {
                vsh_mat4_transform_point4(inverse, light, fan.Light);
                fans.push_back(fan);
                for (int k = 0; k < 8; ++k)
                {
                  const double p[4] = { b[k & 1] - eye[0], b[2 + ((k >> 1) & 1)] - eye[1],
                    b[4 + ((k >> 2) & 1)] - eye[2], 1.0 };
                  double q[4];
                  vsh_mat4_transform_point4(shadowDC, p, q);
                  if (!(q[3] > 0.0))
                  {
                    fanRectFull = true;
                    continue;
                  }
                  fanRect[0] = std::min(fanRect[0], q[0] / q[3]);
                  fanRect[1] = std::min(fanRect[1], q[1] / q[3]);
                  fanRect[2] = std::max(fanRect[2], q[0] / q[3]);
                  fanRect[3] = std::max(fanRect[3], q[1] / q[3]);
                }
                continue;
              }
            }
            if (clipNeeded)
            {
              glEnable(GL_CLIP_DISTANCE0);
              glEnable(GL_CLIP_DISTANCE1);
            }
            else
            {
              glDisable(GL_CLIP_DISTANCE0);
              glDisable(GL_CLIP_DISTANCE1);
              keep0F[0] = keep0F[1] = keep0F[2] = 0.0f;
              keep0F[3] = 1.0f;
              std::copy_n(keep0F, 4, keep1F);
            }
            program->SetUniformMatrix4x4("shadowMCDC", mcdcF);
            program->SetUniform4f("receiverSideMC", keep0F);
            program->SetUniform4f("belowLightMC", keep1F);
            caster->Geometry.Draw(program);
            this->NumberOfMaskTriangles += caster->Geometry.GetNumberOfTriangles();
          }
          if (!fans.empty())
          {
            // Winding numbers of the silhouette fans in the stencil (front
            // +1, back -1), then the pair's bit wherever it is not zero,
            // within the casters' projected bounds.
            int x0 = 0, y0 = 0, x1 = size[0], y1 = size[1];
            if (!fanRectFull)
            {
              x0 = std::max(0, static_cast<int>(std::floor((fanRect[0] * 0.5 + 0.5) * size[0])) - 1);
              y0 = std::max(0, static_cast<int>(std::floor((fanRect[1] * 0.5 + 0.5) * size[1])) - 1);
              x1 = std::min(size[0], static_cast<int>(std::ceil((fanRect[2] * 0.5 + 0.5) * size[0])) + 1);
              y1 = std::min(size[1], static_cast<int>(std::ceil((fanRect[3] * 0.5 + 0.5) * size[1])) + 1);
            }
            if (x1 > x0 && y1 > y0)
            {
              // Through vtkOpenGLState: VTK caches this state, and a stale
              // cache would leave our scissor box on its own renders.
              state->vtkglEnable(GL_SCISSOR_TEST);
              state->vtkglScissor(x0, y0, x1 - x0, y1 - y0);
              state->vtkglStencilMask(0xff);
              glClearStencil(0);
              state->vtkglClear(GL_STENCIL_BUFFER_BIT);
              state->vtkglEnable(GL_STENCIL_TEST);
              // Counting only: OR-ing zero writes nothing (llvmpipe does not
              // honour a colour mask with logic ops on integer targets).
              const unsigned int none[4] = { 0, 0, 0, 0 };
              const GLint pairBitLocation = glGetUniformLocation(program->GetHandle(), "pairBit");
              glUniform4uiv(pairBitLocation, 1, none);
              state->vtkglStencilFunc(GL_ALWAYS, 0, 0xff);
              state->vtkglStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
              state->vtkglStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
              glDisable(GL_CLIP_DISTANCE0);
              glDisable(GL_CLIP_DISTANCE1);
              // Keep-all planes too: llvmpipe was seen to apply the clip
              // distances a shader writes even with them disabled.
              const float keepAll[4] = { 0, 0, 0, 1 };
              program->SetUniform4f("receiverSideMC", keepAll);
              program->SetUniform4f("belowLightMC", keepAll);
              for (const Fan& fan : fans)
              {
                float mcdc[16];
                std::copy_n(fan.MCDC, 16, mcdc);
                program->SetUniformMatrix4x4("shadowMCDC", mcdc);
                fan.Geometry->DrawSilhouetteFans(program, fan.Light);
                this->NumberOfMaskTriangles += fan.Geometry->GetNumberOfSilhouetteTriangles();
              }
              glUniform4uiv(pairBitLocation, 1, bits);
              state->vtkglStencilFunc(GL_NOTEQUAL, 0, 0xff);
              state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
              // A quad over the viewport in clip space sets the bit.
              if (!impl.Quad)
              {
                const std::vector<float> corners = { -1, -1, 0, 1, -1, 0, 1, 1, 0, -1, -1, 0, 1, 1,
                  0, -1, 1, 0 };
                impl.Quad = vtkSmartPointer<vtkOpenGLBufferObject>::New();
                impl.Quad->SetType(vtkOpenGLBufferObject::ArrayBuffer);
                impl.Quad->Upload(corners, vtkOpenGLBufferObject::ArrayBuffer);
                impl.QuadVAO = vtkSmartPointer<vtkOpenGLVertexArrayObject>::New();
                impl.QuadProgram = nullptr;
              }
              if (impl.QuadProgram != program)
              {
                impl.QuadVAO->ShaderProgramChanged();
                impl.QuadVAO->Bind();
                impl.QuadVAO->AddAttributeArray(
                  program, impl.Quad, "vertexMC", 0, 3 * sizeof(float), VTK_FLOAT, 3, false);
                impl.QuadProgram = program;
              }
              float identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
              const float keep[4] = { 0, 0, 0, 1 };
              program->SetUniformMatrix4x4("shadowMCDC", identity);
              program->SetUniform4f("receiverSideMC", keep);
              program->SetUniform4f("belowLightMC", keep);
              impl.QuadVAO->Bind();
              glDrawArrays(GL_TRIANGLES, 0, 6);
              impl.QuadVAO->Release();
              state->vtkglDisable(GL_STENCIL_TEST);
              state->vtkglDisable(GL_SCISSOR_TEST);
            }
          }
        }
      }
      glDisable(GL_CLIP_DISTANCE0);
      glDisable(GL_CLIP_DISTANCE1);
      glDisable(GL_COLOR_LOGIC_OP);
    }
  }
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
  impl.FBO->RemoveColorAttachment(0);
  state->PopFramebufferBindings();

  // Forget casters that left the scene.
  for (auto it = impl.Casters.begin(); it != impl.Casters.end();)
  {
    if (it->second->SeenFrame + 1 < impl.Frame && it->second->SeenFrame != 0)
    {
      it->second->Geometry.ReleaseGraphicsResources(window);
      it = impl.Casters.erase(it);
    }
    else
    {
      ++it;
    }
  }

  // The scene, with the receivers' lighting reading the mask.
  impl.Mask->Activate();
  this->RenderDelegateWithShaderHooks(s);
  impl.Mask->Deactivate();
}

//------------------------------------------------------------------------------
bool vtkPlanarShadowPass::PreReplaceShaderValues(std::string&, std::string&,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  if (!this->Impl->CanReceive(prop))
  {
    return true; // casters and translucent actors keep VTK's own shader
  }
  // Our declarations ride along with VTK's lighting declarations.
  if (fragmentShader.find("//VTK::Light::Dec") != std::string::npos)
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Dec",
      std::string("//VTK::Light::Dec\n") + vtkPlanarShadowLightFS, false);
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkPlanarShadowPass::PostReplaceShaderValues(std::string&, std::string&,
  std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  if (fragmentShader.find("vshPlanarLit") == std::string::npos)
  {
    return true;
  }
  // Each light's diffuse and specular terms times its mask bit; the mask is
  // read once per fragment.
  vtkshadow::InjectLightFactors(fragmentShader, "vshPlanarLit(%d)", "vshPlanarPrepare(vertexVC.xyz);");
  return true;
}

//------------------------------------------------------------------------------
bool vtkPlanarShadowPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  Internals& impl = *this->Impl;
  if (!program->IsUniformUsed("vshPlanarMask") || !impl.Mask)
  {
    return true;
  }
  program->SetUniformi("vshPlanarMask", impl.Mask->GetTextureUnit());
  program->SetUniform2i("vshPlanarMaskOrigin", impl.MaskOrigin);
  auto it = impl.ReceiverIndex.find(prop);
  program->SetUniformi("vshPlanarReceiver", it == impl.ReceiverIndex.end() ? -1 : it->second);
  program->SetUniformi("vshPlanarLightCount", std::max(impl.LightCount, 1));
  program->SetUniformi("vshPlanarPlaneCount", impl.PlaneCount);
  if (impl.PlaneCount > 0)
  {
    program->SetUniform4fv("vshPlanarPlaneVC", impl.PlaneCount,
      reinterpret_cast<const float(*)[4]>(impl.PlaneVC));
    program->SetUniform1iv("vshPlanarPlaneReceiver", impl.PlaneCount, impl.PlaneReceiver);
    program->SetUniform1fv("vshPlanarPlaneTolerance", impl.PlaneCount, impl.PlaneTolerance);
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::ReleaseGraphicsResources(vtkWindow* w)
{
  Internals& impl = *this->Impl;
  if (impl.Mask)
  {
    impl.Mask->ReleaseGraphicsResources(w);
  }
  if (impl.FBO)
  {
    impl.FBO->ReleaseGraphicsResources(w);
  }
  impl.MaskSize[0] = impl.MaskSize[1] = 0;
  if (impl.Stencil)
  {
    glDeleteRenderbuffers(1, &impl.Stencil);
    impl.Stencil = 0;
    impl.StencilSize[0] = impl.StencilSize[1] = 0;
  }
  if (impl.QuadVAO)
  {
    impl.QuadVAO->ReleaseGraphicsResources();
    impl.Quad->ReleaseGraphicsResources();
  }
  impl.Quad = nullptr;
  impl.QuadVAO = nullptr;
  impl.QuadProgram = nullptr;
  for (auto& entry : impl.Casters)
  {
    entry.second->Geometry.ReleaseGraphicsResources(w);
  }
  impl.Casters.clear();
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ReceiverActors: " << this->Impl->ReceiverActors.size() << "\n";
  os << indent << "ReceiverPlanes: " << this->Impl->Planes.size() << "\n";
  os << indent << "PlaneTolerance: " << this->PlaneTolerance << "\n";
  os << indent << "NumberOfShadowPairs: " << this->NumberOfShadowPairs << "\n";
  os << indent << "NumberOfMaskTriangles: " << this->NumberOfMaskTriangles << "\n";
  os << indent << "NumberOfGeometryBuilds: " << this->NumberOfGeometryBuilds << "\n";
}

//------------------------------------------------------------------------------
bool vtkPlanarShadowPass::SetOption(const char* key, double value)
{
  if (key && std::string(key) == "plane_tolerance")
  {
    if (!(value >= 0.0 && value <= 1.0))
    {
      return false;
    }
    this->SetPlaneTolerance(value);
    return true;
  }
  return this->Superclass::SetOption(key, value);
}

//------------------------------------------------------------------------------
std::string vtkPlanarShadowPass::GetStatsJSON(vtkRenderer*) const
{
  return "\"shadow_pairs\": " + std::to_string(this->NumberOfShadowPairs) +
    ", \"mask_triangles\": " + std::to_string(this->NumberOfMaskTriangles) +
    ", \"geometry_builds\": " + std::to_string(this->NumberOfGeometryBuilds);
}
