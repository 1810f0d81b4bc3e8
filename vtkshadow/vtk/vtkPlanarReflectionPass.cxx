#include "vtkPlanarReflectionPass.h"
#include "vtkShadowStageProfile.h"

#include "vtkShadowClippingRange.h"
#include "vtkShadowFrame.h"

#include "vsh_mat4.h"
#include "vsh_plane.h"
#include "vsh_reflect.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkInformation.h"
#include "vtkInformationDoubleKey.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLinearTransform.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include "vtkPlanarReflectionClipFS.h"
#include "vtkPlanarReflectionFS.h"

#include <cmath>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkPlanarReflectionPass);
vtkInformationKeyMacro(vtkPlanarReflectionPass, MIRROR, Double);

// A mirror of this frame: the actor, R, and its plane relative to the eye.
struct vtkPlanarReflectionPass::Mirror
{
  vtkActor* Actor = nullptr;
  double R = 0;
  double Plane[4] = { 0, 0, 1, 0 };
  int World = 0; // the delegate's world key for this mirror's reflection
};

struct vtkPlanarReflectionPass::Internals
{
  std::vector<Mirror> Mirrors;
  int Found = 0;
  int Drawn = 0;
  bool Stencil = true;
  // The mirrors seen are drawn at (1 - R) of their shading and get R x the
  // reflection added (Composite): true while that holds for the frame.
  bool ScaleSeen = false;
  // Inside the mirrored draw: every mirror drawn there shows (1 - R) of its
  // shading (its reflection is the bounce not drawn).
  bool ScaleAll = false;
  vtkSmartPointer<vtkOpenGLFramebufferObject> FBO;
  int Size[2] = { 0, 0 };
  std::unique_ptr<vtkOpenGLQuadHelper> Quad;
  vtkSmartPointer<vtkRenderStepsPass> Plain;
  // The clip plane while the mirrored scene is drawn: into FBO, and into
  // any other target drawn with the camera's view (a technique's screen
  // mask depth pre-pass), recognised by Camera and the viewport's Size.
  bool ClipActive = false;
  int FBOIndex = -1;
  vtkCamera* Camera = nullptr;
  vtkRenderer* Renderer = nullptr;
  vtkOpenGLState* State = nullptr;
  float DCVC[16];
  float PlaneVC[4];
  float Viewport[4];
};

namespace
{
// Row-major double 4x4 to the column-major floats GLSL reads.
void ToGLSL(const double m[16], float out[16])
{
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      out[4 * c + r] = static_cast<float>(m[4 * r + c]);
}

// The world reflection through a plane given relative to the eye,
// T(eye) R T(-eye), composed in double: the large translations cancel here,
// not in a float matrix on the GPU.
void WorldReflection(const double planeRel[4], const double eye[3], double out[16])
{
  double r[16], t[16], tinv[16], tmp[16];
  const double neg[3] = { -eye[0], -eye[1], -eye[2] };
  vsh_reflect_matrix(planeRel, r);
  vsh_mat4_translation(eye, t);
  vsh_mat4_translation(neg, tinv);
  vsh_mat4_multiply(r, tinv, tmp);
  vsh_mat4_multiply(t, tmp, out);
}

// The stencil of the bound draw framebuffer. VTK 9.1's own framebuffers
// hold a depth-stencil texture attached as depth only: then its stencil is
// attached for the mirrors' mask (Attached = the object to detach after).
struct TargetStencil
{
  bool Usable = false;
  GLint Attached = 0;
  GLint AttachedType = GL_NONE;

  void Find()
  {
    GLint bound = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    const GLenum stencil = bound == 0 ? GL_STENCIL : GL_STENCIL_ATTACHMENT;
    GLint type = GL_NONE, bits = 0;
    glGetFramebufferAttachmentParameteriv(
      GL_DRAW_FRAMEBUFFER, stencil, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_NONE)
    {
      glGetFramebufferAttachmentParameteriv(
        GL_DRAW_FRAMEBUFFER, stencil, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &bits);
      this->Usable = bits > 0;
      return;
    }
    if (bound == 0)
    {
      return;
    }
    GLint name = 0;
    glGetFramebufferAttachmentParameteriv(
      GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    glGetFramebufferAttachmentParameteriv(
      GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE, &bits);
    glGetFramebufferAttachmentParameteriv(
      GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    if (bits <= 0 || name == 0 || (type != GL_TEXTURE && type != GL_RENDERBUFFER))
    {
      return;
    }
    this->Attach(type, name);
    this->Usable = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    this->Attached = name;
    this->AttachedType = type;
    if (!this->Usable)
    {
      this->Release();
    }
  }

  static void Attach(GLint type, GLint name)
  {
    if (type == GL_TEXTURE)
      glFramebufferTexture2D(
        GL_DRAW_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_TEXTURE_2D, static_cast<GLuint>(name), 0);
    else
      glFramebufferRenderbuffer(
        GL_DRAW_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, static_cast<GLuint>(name));
  }

  // Leave VTK's framebuffer as it was.
  void Release()
  {
    if (this->Attached)
    {
      Attach(this->AttachedType, 0);
      this->Attached = 0;
    }
  }
};

// The plane of a mirror actor relative to the eye, facing its normals;
// false when it is not flat or has no points.
bool MirrorPlane(vtkActor* actor, const double eye[3], double plane[4], double& size)
{
  vtkMapper* mapper = actor->GetMapper();
  vtkPolyData* poly =
    mapper ? vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0)) : nullptr;
  if (!poly || poly->GetNumberOfPoints() < 3)
  {
    return false;
  }
  vtkMatrix4x4* m = actor->GetMatrix();
  const vtkIdType n = poly->GetNumberOfPoints();
  std::vector<double> rel(3 * static_cast<size_t>(n));
  double lo[3] = { 1e300, 1e300, 1e300 }, hi[3] = { -1e300, -1e300, -1e300 };
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[4] = { 0, 0, 0, 1 }, w[4];
    poly->GetPoint(i, p);
    m->MultiplyPoint(p, w);
    for (int k = 0; k < 3; ++k)
    {
      rel[3 * i + k] = w[k] / w[3] - eye[k];
      lo[k] = std::min(lo[k], rel[3 * i + k]);
      hi[k] = std::max(hi[k], rel[3 * i + k]);
    }
  }
  if (vsh_plane_fit_points(rel.data(), static_cast<size_t>(n), 1e-6, plane) != VSH_PLANE_OK)
  {
    return false;
  }
  size = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
    (hi[2] - lo[2]) * (hi[2] - lo[2]));
  // The reflecting face is the one the normals point out of (the scene's
  // plane normal); normals go through the inverse transpose of the matrix.
  vtkDataArray* normals = poly->GetPointData()->GetNormals();
  if (normals)
  {
    double nm[3], inv[16];
    normals->GetTuple(0, nm);
    vtkMatrix4x4::Invert(&m->Element[0][0], inv);
    double world[3];
    for (int k = 0; k < 3; ++k)
      world[k] = inv[k] * nm[0] + inv[4 + k] * nm[1] + inv[8 + k] * nm[2];
    if (world[0] * plane[0] + world[1] * plane[1] + world[2] * plane[2] < 0)
      for (int k = 0; k < 4; ++k)
        plane[k] = -plane[k];
  }
  return true;
}
} // namespace

//------------------------------------------------------------------------------
vtkPlanarReflectionPass::vtkPlanarReflectionPass()
  : ReflectShadows(true)
  , Reflections(true)
  , Impl(new Internals)
{
}

//------------------------------------------------------------------------------
vtkPlanarReflectionPass::~vtkPlanarReflectionPass() = default;

//------------------------------------------------------------------------------
void vtkPlanarReflectionPass::FindMirrors(const vtkRenderState* s)
{
  Internals& impl = *this->Impl;
  impl.Mirrors.clear();
  impl.Found = 0;
  const double* eye = this->GetFrame().Eye;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkActor* actor = vtkActor::SafeDownCast(s->GetPropArray()[i]);
    vtkInformation* keys = actor ? actor->GetPropertyKeys() : nullptr;
    if (!keys || !keys->Has(MIRROR()))
    {
      continue;
    }
    Mirror mirror;
    mirror.Actor = actor;
    mirror.R = keys->Get(MIRROR());
    double size = 0;
    if (!(mirror.R > 0 && mirror.R <= 1) || !MirrorPlane(actor, eye, mirror.Plane, size))
    {
      continue;
    }
    ++impl.Found;
    // Camera behind the mirror or in its plane: no reflection to draw.
    const double origin[3] = { 0, 0, 0 };
    if (vsh_reflect_eye_sees(mirror.Plane, origin, size, 1e-9))
    {
      mirror.World = static_cast<int>(impl.Mirrors.size()) + 1;
      impl.Mirrors.push_back(mirror);
    }
  }
}

//------------------------------------------------------------------------------
// The technique keeps state per world (vtkShadowPassBase::SetWorldKey): the
// worlds of mirrors no longer seen, or no longer drawn by the technique, are
// freed at once.
void vtkPlanarReflectionPass::ReleaseUnusedWorlds(const vtkRenderState* s)
{
  auto* technique = vtkShadowPassBase::SafeDownCast(this->DelegatePass);
  if (technique)
  {
    const bool mirrored = this->Reflections && this->ReflectShadows;
    const int used = mirrored ? static_cast<int>(this->Impl->Mirrors.size()) : 0;
    technique->ReleaseWorlds(s->GetRenderer()->GetRenderWindow(), used + 1);
  }
}

//------------------------------------------------------------------------------
void vtkPlanarReflectionPass::Render(const vtkRenderState* s)
{
  Internals& impl = *this->Impl;
  this->NumberOfRenderedProps = 0;
  impl.Drawn = 0;
  impl.ClipActive = false;
  auto* technique = vtkShadowPassBase::SafeDownCast(this->EnsureDelegatePass());
  if (technique)
  {
    technique->SetWorldKey(0);
  }
  impl.ScaleSeen = impl.ScaleAll = false;
  // The frame's camera view (IsCameraViewDraw): the renderer, its camera and
  // the viewport's size.
  impl.Renderer = s->GetRenderer();
  impl.Camera = impl.Renderer->GetActiveCamera();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(impl.Renderer->GetRenderWindow());
  impl.State = window ? window->GetState() : nullptr;
  // The technique draws the scene from this frame too: the lights are
  // updated and listed once.
  const vtkshadow::ShadowFrame& frame = this->BeginFrame(s, false);
  if (technique)
  {
    technique->SetGivenFrame(&frame);
  }
  if (!this->Reflections)
  {
    impl.Mirrors.clear();
    impl.Found = 0;
    this->RenderDelegate(s);
    if (technique)
    {
      technique->SetGivenFrame(nullptr);
    }
    this->ReleaseUnusedWorlds(s);
    return;
  }
  this->FindMirrors(s);
  // Whether the reflections can be composited (the target has a stencil),
  // known before the main draw, which shades the mirrors seen at (1 - R).
  {
    TargetStencil probe;
    probe.Find();
    impl.Stencil = probe.Usable;
    probe.Release();
  }
  impl.ScaleSeen = impl.Stencil && !impl.Mirrors.empty();
  // The clip hook is registered for the whole frame, so every mapper keeps
  // one shader for the scene and its reflection (it is off outside the
  // mirrored draw).
  this->RenderDelegateWithShaderHooks(s);
  if (technique)
  {
    technique->SetGivenFrame(nullptr);
  }
  this->ReleaseUnusedWorlds(s);
  if (impl.Mirrors.empty())
  {
    return;
  }
  for (const Mirror& mirror : impl.Mirrors)
  {
    if (!this->RenderMirrored(s, mirror))
    {
      continue;
    }
    TargetStencil stencil;
    stencil.Find();
    impl.Stencil = stencil.Usable;
    if (stencil.Usable)
    {
      this->Composite(s, mirror);
      ++impl.Drawn;
    }
    stencil.Release();
    vtkshadow::MarkStage("reflection.composite");
  }
}

namespace
{
// The scene reflected through a mirror for one draw: every other prop's
// matrix and every scene light reflected, the clipping range refitted; all
// put back by Restore().
struct MirroredWorld
{
  struct Saved
  {
    vtkProp3D* Prop;
    vtkSmartPointer<vtkLinearTransform> User;
  };
  struct SavedLight
  {
    vtkLight* Light;
    double Position[3], FocalPoint[3];
  };
  std::vector<Saved> Props;
  std::vector<SavedLight> Lights;
  double Range[2] = { 0, 0 };
  vtkRenderer* Renderer = nullptr;

  void Apply(vtkRenderer* ren, const std::vector<vtkProp*>& props, const double planeRel[4],
    const double eye[3])
  {
    this->Renderer = ren;
    double world[16];
    WorldReflection(planeRel, eye, world);
    for (vtkProp* p : props)
    {
      vtkProp3D* prop = vtkProp3D::SafeDownCast(p);
      if (!prop)
        continue;
      this->Props.push_back({ prop, prop->GetUserTransform() });
      vtkNew<vtkMatrix4x4> m;
      m->DeepCopy(world);
      if (prop->GetUserTransform())
        vtkMatrix4x4::Multiply4x4(m, prop->GetUserTransform()->GetMatrix(), m);
      prop->SetUserMatrix(m);
    }
    vtkLightCollection* lights = ren->GetLights();
    vtkCollectionSimpleIterator it;
    lights->InitTraversal(it);
    while (vtkLight* light = lights->GetNextLight(it))
    {
      if (!light->LightTypeIsSceneLight())
        continue;
      SavedLight saved{ light, {}, {} };
      light->GetPosition(saved.Position);
      light->GetFocalPoint(saved.FocalPoint);
      this->Lights.push_back(saved);
      double rel[3], out[3];
      for (int k = 0; k < 3; ++k)
        rel[k] = saved.Position[k] - eye[k];
      vsh_reflect_point(planeRel, rel, out);
      light->SetPosition(out[0] + eye[0], out[1] + eye[1], out[2] + eye[2]);
      for (int k = 0; k < 3; ++k)
        rel[k] = saved.FocalPoint[k] - eye[k];
      vsh_reflect_point(planeRel, rel, out);
      light->SetFocalPoint(out[0] + eye[0], out[1] + eye[1], out[2] + eye[2]);
    }
    ren->GetActiveCamera()->GetClippingRange(this->Range);
    vtkshadow::ResetClippingRange(ren);
  }

  void Restore()
  {
    for (Saved& saved : this->Props)
      saved.Prop->SetUserTransform(saved.User);
    for (SavedLight& saved : this->Lights)
    {
      saved.Light->SetPosition(saved.Position);
      saved.Light->SetFocalPoint(saved.FocalPoint);
    }
    if (this->Renderer)
      this->Renderer->GetActiveCamera()->SetClippingRange(this->Range);
  }
};
} // namespace

//------------------------------------------------------------------------------
bool vtkPlanarReflectionPass::RenderMirrored(const vtkRenderState* s, const Mirror& mirror)
{
  Internals& impl = *this->Impl;
  vtkRenderer* ren = s->GetRenderer();
  auto* win = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!win)
  {
    return false;
  }
  vtkOpenGLState* state = win->GetState();
  const vtkshadow::ShadowFrame& frame = this->GetFrame();
  const int* size = frame.Size;
  if (size[0] < 1 || size[1] < 1)
  {
    return false;
  }
  state->PushFramebufferBindings();
  if (!impl.FBO)
  {
    impl.FBO = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    impl.FBO->SetContext(win);
    impl.FBO->Bind();
    impl.FBO->PopulateFramebuffer(size[0], size[1], true, 1, VTK_UNSIGNED_CHAR, true, 24, 0, true);
  }
  else if (impl.Size[0] != size[0] || impl.Size[1] != size[1])
  {
    impl.FBO->Resize(size[0], size[1]);
  }
  impl.Size[0] = size[0];
  impl.Size[1] = size[1];
  impl.FBO->Bind();
  impl.FBO->ActivateDrawBuffer(0);

  std::vector<vtkProp*> props;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
    if (s->GetPropArray()[i] != mirror.Actor)
      props.push_back(s->GetPropArray()[i]);
  MirroredWorld world;
  world.Apply(ren, props, mirror.Plane, frame.Eye);

  // The clip plane in view coordinates: the view's rotation applied to the
  // eye-relative plane (the eye is the view's origin), and the inverse
  // projection to get back from the window.
  vtkCamera* camera = ren->GetActiveCamera();
  double clip[4], proj[16], dcvc[16];
  const double eyeRel[3] = { 0, 0, 0 };
  const double* view = frame.View;
  vsh_reflect_clip_plane(mirror.Plane, eyeRel, clip);
  for (int r = 0; r < 3; ++r)
    impl.PlaneVC[r] = static_cast<float>(
      view[4 * r] * clip[0] + view[4 * r + 1] * clip[1] + view[4 * r + 2] * clip[2]);
  impl.PlaneVC[3] = static_cast<float>(clip[3]);
  vtkMatrix4x4::DeepCopy(
    proj, camera->GetProjectionTransformMatrix(double(size[0]) / size[1], -1, 1));
  vsh_mat4_inverse(proj, dcvc);
  ToGLSL(dcvc, impl.DCVC);
  impl.Viewport[0] = impl.Viewport[1] = 0.0f;
  impl.Viewport[2] = static_cast<float>(size[0]);
  impl.Viewport[3] = static_cast<float>(size[1]);
  impl.FBOIndex = static_cast<int>(impl.FBO->GetFBOIndex());
  impl.ClipActive = true;
  impl.ScaleAll = true;

  vtkRenderState mirrored(ren);
  mirrored.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  mirrored.SetFrameBuffer(impl.FBO);
  vtkRenderPass* delegate = this->EnsureDelegatePass();
  if (!this->ReflectShadows)
  {
    if (!impl.Plain)
      impl.Plain = vtkSmartPointer<vtkRenderStepsPass>::New();
    delegate = impl.Plain;
  }
  // A reflection flips the winding of every triangle: the outside of the
  // mirrored geometry is clockwise on screen (and for the lights' maps).
  glFrontFace(GL_CW);
  auto* technique = vtkShadowPassBase::SafeDownCast(delegate);
  if (technique)
  {
    technique->SetWorldKey(mirror.World); // its own maps, still-frame state
  }
  this->PreRender(&mirrored);
  delegate->Render(&mirrored);
  this->PostRender(&mirrored);
  if (technique)
  {
    technique->SetWorldKey(0);
  }
  glFrontFace(GL_CCW);

  impl.ClipActive = false;
  impl.ScaleAll = false;
  world.Restore();
  state->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
void vtkPlanarReflectionPass::Composite(const vtkRenderState* s, const Mirror& mirror)
{
  Internals& impl = *this->Impl;
  vtkRenderer* ren = s->GetRenderer();
  auto* win = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkOpenGLState* state = win->GetState();
  const int* size = this->GetFrame().Size;
  const int* origin = this->GetFrame().Origin;
  vtkOpenGLState::ScopedglColorMask colorMask(state);
  vtkOpenGLState::ScopedglDepthMask depthMask(state);
  vtkOpenGLState::ScopedglDepthFunc depthFunc(state);
  vtkOpenGLState::ScopedglEnableDisable depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglEnableDisable stencilTest(state, GL_STENCIL_TEST);
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  vtkOpenGLState::ScopedglViewport viewport(state);
  vtkOpenGLState::ScopedglScissor scissorBox(state);
  state->vtkglViewport(origin[0], origin[1], size[0], size[1]);
  state->vtkglScissor(origin[0], origin[1], size[0], size[1]);
  state->vtkglEnable(GL_SCISSOR_TEST);

  // 1. The mirror's visible pixels into the stencil: the mirror drawn again
  // (same mapper, same depths) against the scene's depth, colour off.
  state->vtkglStencilMask(0xff);
  glClearStencil(0);
  state->vtkglClear(GL_STENCIL_BUFFER_BIT);
  state->vtkglEnable(GL_STENCIL_TEST);
  state->vtkglStencilFunc(GL_ALWAYS, 1, 0xff);
  state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  state->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  state->vtkglDisable(GL_BLEND);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LEQUAL);
  mirror.Actor->RenderOpaqueGeometry(ren);
  state->vtkglDepthMask(GL_FALSE);

  // 2. The reflection into those pixels, blended by R.
  if (!impl.Quad)
  {
    impl.Quad.reset(new vtkOpenGLQuadHelper(win, nullptr, vtkPlanarReflectionFS, ""));
  }
  if (!impl.Quad->Program)
  {
    vtkErrorMacro("the reflection shader did not compile");
    return;
  }
  win->GetShaderCache()->ReadyShaderProgram(impl.Quad->Program);
  state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglStencilFunc(GL_EQUAL, 1, 0xff);
  state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  state->vtkglEnable(GL_BLEND);
  glBlendColor(0.0f, 0.0f, 0.0f, static_cast<float>(mirror.R));
  // The mirror is already (1 - R) x its shading (SetShaderParameters), so
  // the reflection is added: the sum is clamped once, as a ray tracer's.
  state->vtkglBlendFuncSeparate(GL_CONSTANT_ALPHA, GL_ONE, GL_ZERO, GL_ONE);
  vtkTextureObject* colour = impl.FBO->GetColorAttachmentAsTextureObject(0);
  colour->Activate();
  impl.Quad->Program->SetUniformi("reflectionColor", colour->GetTextureUnit());
  impl.Quad->Render();
  colour->Deactivate();
}

//------------------------------------------------------------------------------
bool vtkPlanarReflectionPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  const bool declared = vtkShaderProgram::Substitute(fragmentShader, "//VTK::Clip::Dec",
    "uniform int vshMirrorClipOn;\nuniform vec4 vshMirrorViewport;\n"
    "uniform mat4 vshMirrorDCVC;\nuniform vec4 vshMirrorPlaneVC;\n"
    "uniform float vshMirrorShade;\n//VTK::Clip::Dec",
    false);
  // A mirror's own shading scaled by 1 - R (1 for every other surface).
  if (declared)
  {
    vtkShaderProgram::Substitute(fragmentShader, "//VTK::Light::Impl",
      "//VTK::Light::Impl\n  gl_FragData[0].rgb *= vshMirrorShade;\n", false);
  }
  vtkShaderProgram::Substitute(fragmentShader, "//VTK::Clip::Impl",
    std::string(vtkPlanarReflectionClipFS) + "\n  //VTK::Clip::Impl", false);
  return true;
}

//------------------------------------------------------------------------------
bool vtkPlanarReflectionPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  Internals& impl = *this->Impl;
  if (program->IsUniformUsed("vshMirrorShade"))
  {
    program->SetUniformf("vshMirrorShade", static_cast<float>(this->MirrorShade(prop)));
  }
  if (!program->IsUniformUsed("vshMirrorClipOn"))
  {
    return true;
  }
  GLint bound = -1;
  if (impl.ClipActive)
  {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  }
  const bool on = impl.ClipActive && (bound == impl.FBOIndex || this->IsCameraViewDraw(true));
  program->SetUniformi("vshMirrorClipOn", on ? 1 : 0);
  if (on)
  {
    program->SetUniform4f("vshMirrorViewport", impl.Viewport);
    program->SetUniformMatrix4x4("vshMirrorDCVC", impl.DCVC);
    program->SetUniform4f("vshMirrorPlaneVC", impl.PlaneVC);
  }
  return true;
}

//------------------------------------------------------------------------------
// The factor on a prop's shading: 1 - R for a mirror whose reflection is
// added in Composite (seen, stencil usable) so that the blend is
// (1 - R) mirror + R reflection clamped once, not the clamped mirror mixed;
// 1 - R also for every mirror inside a reflection, whose own reflection is
// the bounce not drawn (a ray tracer stopping at that depth, POV-Ray's
// max_trace_level 2, shows the same); 1 otherwise.
double vtkPlanarReflectionPass::MirrorShade(vtkProp* prop) const
{
  const Internals& impl = *this->Impl;
  auto* actor = vtkActor::SafeDownCast(prop);
  vtkInformation* keys = actor ? actor->GetPropertyKeys() : nullptr;
  if (!keys || !keys->Has(MIRROR()))
  {
    return 1.0;
  }
  const double r = keys->Get(MIRROR());
  // Not in a light's view (VTK's own pass bakes its maps through the
  // mappers with a light camera: the factor would scale the depth it
  // writes into the colour).
  if (!(r > 0 && r <= 1) || !this->IsCameraViewDraw(false))
  {
    return 1.0;
  }
  if (impl.ScaleAll)
  {
    return 1.0 - r;
  }
  if (!impl.ScaleSeen)
  {
    return 1.0;
  }
  for (const Mirror& mirror : impl.Mirrors)
  {
    if (mirror.Actor == actor)
    {
      return 1.0 - r;
    }
  }
  return 1.0;
}

//------------------------------------------------------------------------------
// Every draw of the camera's view of the mirrored scene is clipped, whatever
// its target: the reflection's own framebuffer, and a technique's depth
// pre-pass (vtkShadowScreenMask, used by csm's screen resolve, volume and
// raytrace), whose depth must be the clipped scene's or something behind the
// mirror decides the shadows of the reflected pixels. The maps a technique
// draws from a light through the mappers (VTK's vtkShadowMapBakerPass swaps
// in a light camera, at the map's size) are not clipped: the clip plane is
// given in the camera's view and viewport, and the mirrored world's lighting
// keeps every object. A draw is the camera's view when the renderer's active
// camera is the scene's and the viewport has the frame's size (for the
// clip also origin 0, the reflection's: exactly the draws for which its
// window-to-view mapping holds).
bool vtkPlanarReflectionPass::IsCameraViewDraw(bool atOrigin) const
{
  const Internals& impl = *this->Impl;
  if (!impl.Renderer || impl.Renderer->GetActiveCamera() != impl.Camera || !impl.State)
  {
    return false;
  }
  GLint viewport[4] = { -1, -1, -1, -1 };
  impl.State->vtkglGetIntegerv(GL_VIEWPORT, viewport);
  return (!atOrigin || (viewport[0] == 0 && viewport[1] == 0)) &&
    viewport[2] == this->GetFrame().Size[0] && viewport[3] == this->GetFrame().Size[1];
}

//------------------------------------------------------------------------------
long long vtkPlanarReflectionPass::GetMemoryBytes() const
{
  auto* base = vtkShadowPassBase::SafeDownCast(this->DelegatePass);
  const long long own =
    this->Impl->FBO ? 8LL * this->Impl->Size[0] * static_cast<long long>(this->Impl->Size[1]) : 0;
  return own + (base ? base->GetMemoryBytes() : 0);
}

//------------------------------------------------------------------------------
std::string vtkPlanarReflectionPass::GetStatsJSON(vtkRenderer* renderer) const
{
  auto* base = vtkShadowPassBase::SafeDownCast(this->DelegatePass);
  const std::string inner = base ? base->GetStatsJSON(renderer) : std::string();
  std::ostringstream os;
  os << "\"reflections\": {\"enabled\": " << (this->Reflections ? "true" : "false")
     << ", \"reflect_shadows\": " << (this->ReflectShadows ? "true" : "false")
     << ", \"mirrors\": " << this->Impl->Found << ", \"seen\": " << this->Impl->Mirrors.size()
     << ", \"drawn\": " << this->Impl->Drawn
     << ", \"mirror_worlds_bytes\": " << (base ? base->GetWorldsMemoryBytes() : 0)
     << ", \"stencil\": " << (this->Impl->Stencil ? "true" : "false") << "}";
  return inner.empty() ? os.str() : inner + ", " + os.str();
}

//------------------------------------------------------------------------------
bool vtkPlanarReflectionPass::SetOption(const char* key, double value)
{
  auto* base = vtkShadowPassBase::SafeDownCast(this->DelegatePass);
  return base ? base->SetOption(key, value) : this->Superclass::SetOption(key, value);
}

//------------------------------------------------------------------------------
void vtkPlanarReflectionPass::ReleaseGraphicsResources(vtkWindow* w)
{
  Internals& impl = *this->Impl;
  if (impl.FBO)
  {
    impl.FBO->ReleaseGraphicsResources(w);
    impl.FBO = nullptr;
  }
  if (impl.Quad)
  {
    impl.Quad->ReleaseGraphicsResources(w);
    impl.Quad.reset();
  }
  if (impl.Plain)
  {
    impl.Plain->ReleaseGraphicsResources(w);
  }
  impl.Size[0] = impl.Size[1] = 0;
  this->Superclass::ReleaseGraphicsResources(w);
}

//------------------------------------------------------------------------------
void vtkPlanarReflectionPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Reflections: " << this->Reflections << "\n";
  os << indent << "ReflectShadows: " << this->ReflectShadows << "\n";
}
