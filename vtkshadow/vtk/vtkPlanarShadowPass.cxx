#include "vtkPlanarShadowPass.h"
#include "vtkPlanarShadowPassInternals.h"
#include "vtkShadowSettings.h"
#include "vtkShadowStageProfile.h"

#include "vtkActor.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMapper.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLBufferObject.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkShaderProgram.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowCasterGeometry.h"
#include "vtkShadowClipSpaceQuad.h"
#include "vtkShadowFrame.h"
#include "vtkShadowLightingHook.h"
#include "vtkShadowReceiverPlane.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkWeakPointer.h"
#include "vtk_glew.h"

#include "vsh_mat4.h"
#include "vsh_planar.h"
#include "vsh_planar_plan.h"
#include "vsh_soft_adaptive.h"

#include "vtkPlanarShadowLightFS.h"
#include "vtkPlanarShadowMaskFS.h"
#include "vtkPlanarShadowMaskVS.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPlanarShadowPass);

using vtkshadow::planar::LiesInPlane;
using vtkshadow::planar::MaxExplicitPlanes;
using vtkshadow::planar::MaxPairs;
using vtkshadow::planar::MaxSoftPairs;

namespace
{
// The facing test's names in the mappers' shaders (vtkShadowFacingTest.h):
// apart from the volume pass's, which may share a shader in auto's chain.
constexpr const char* FacingPrefix = "vshPlanarFacing";
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

// The props the render state draws and every actor they draw through prop
// paths (the parts of assemblies), sorted: what the mappers may ask about.
std::vector<vtkProp*> DrawnProps(const vtkRenderState* s)
{
  std::vector<vtkProp*> props(s->GetPropArray(), s->GetPropArray() + s->GetPropArrayCount());
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkshadow::ForEachPathActor(
      s->GetPropArray()[i], [&props](vtkActor* actor, const double*) { props.push_back(actor); });
  }
  std::sort(props.begin(), props.end());
  return props;
}

} // namespace

//------------------------------------------------------------------------------
vtkPlanarShadowPass::vtkPlanarShadowPass()
  : PlaneTolerance(1e-5)
  , DetectReceivers(true)
  , NumberOfShadowPairs(0)
  , NumberOfMaskTriangles(0)
  , NumberOfGeometryBuilds(0)
  , SoftSamples(16)
  , NumberOfSoftPairs(0)
  , Adaptive(false)
  , FacingTest(true)
  , NumberOfRefinedPixels(-1)
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
  if (this->Impl->Soft)
  {
    this->Impl->Soft->Delete();
  }
  if (this->Impl->SoftMark)
  {
    this->Impl->SoftMark->Delete();
  }
  if (this->Impl->Transmit)
  {
    this->Impl->Transmit->Delete();
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
  bytes += static_cast<long long>(this->Impl->SoftSize[0]) * this->Impl->SoftSize[1] * 8;
  bytes += static_cast<long long>(this->Impl->TransmitSize[0]) * this->Impl->TransmitSize[1] * 8;
  if (this->Impl->SoftMark)
  {
    bytes +=
      static_cast<long long>(this->Impl->SoftMark->GetWidth()) * this->Impl->SoftMark->GetHeight();
  }
  for (const auto& entry : this->Impl->Casters)
  {
    bytes += entry.second->Geometry.GetNumberOfBytes();
  }
  return bytes;
}

//------------------------------------------------------------------------------
vtkshadow::ReceiverPlaneCache& vtkPlanarShadowPass::GetReceiverPlaneCache()
{
  return this->Impl->ReceiverPlanes;
}

//------------------------------------------------------------------------------
vtkshadow::ReceiverChoice vtkPlanarShadowPass::ChooseReceivers(
  const std::vector<vtkshadow::ShadowActor>& actors)
{
  // Explicit planes (AddReceiverPlane) are marks too: no detection then.
  return vtkshadow::ChooseReceivers(actors, this->Impl->AddedActors(), RECEIVER(),
    this->DetectReceivers && this->Impl->Planes.empty(), this->Impl->ReceiverPlanes);
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::Render(const vtkRenderState* s)
{
  this->NumberOfRenderedProps = 0;
  this->NumberOfShadowPairs = 0;
  this->NumberOfMaskTriangles = 0;
  vtkshadow::MarkStage("setup");
  vtkRenderer* renderer = s->GetRenderer();
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!window)
  {
    vtkErrorMacro("vtkPlanarShadowPass needs an OpenGL render window");
    return;
  }
  Internals& impl = *this->Impl;
  ++impl.Frame;
  Frame frame(this->BeginFrame(s));
  // One value per light: a filter's colour comes out grey.
  this->NoteGreyFilters(frame.Shared);
  this->NoteUncastVolumes(frame.Shared);
  // The mask matches the viewport pixel for pixel.
  std::copy_n(frame.Shared.Origin, 2, impl.MaskOrigin);
  for (const vtkshadow::ShadowFrameLight& light : frame.Shared.Lights)
  {
    vsh_planar_light plain;
    std::copy_n(light.Homogeneous, 4, plain.homogeneous);
    plain.casts = light.Casts ? 1 : 0;
    frame.Lights.push_back(plain);
  }
  impl.LightCount = static_cast<int>(frame.Lights.size());
  impl.FrameProps = DrawnProps(s);
  // Translucent actors receive on their own fragments too: a flat one is a
  // receiver like an opaque one (marked, or detected).
  std::vector<vtkshadow::ShadowActor> receivers = frame.Shared.Drawn;
  for (const vtkshadow::ShadowActor& a : frame.Shared.Translucent)
  {
    receivers.push_back(a);
  }
  this->GatherReceivers(receivers, frame);
  // Casters from the renderer's props, not the frustum-culled list: a
  // caster behind the camera still shadows a receiver in view.
  this->GatherCasters(frame.Shared.Actors, frame);
  this->NoteClosedCasters(renderer, frame);
  this->GatherTranslucentCasters(frame);
  this->SetUpPlanes(frame);
  // Which (receiver, light) pairs cast, with their matrices: plain planning.
  std::vector<vsh_planar_pair> pairs(MaxPairs);
  const int count = vsh_planar_plan_pairs(frame.Planes.data(),
    static_cast<int>(frame.Receivers.size()), frame.Lights.data(),
    static_cast<int>(frame.Lights.size()), frame.Shared.Eye, pairs.data(), MaxPairs);
  pairs.resize(std::max(count, 0));
  for (vsh_planar_pair& pair : pairs)
  {
    // clip[0] is the receiver's plane (normalized, eye-relative): casters
    // are kept from CasterLift above it.
    pair.clip[0][3] -= frame.CasterLift[pair.receiver];
  }
  // Pairs whose light has a size are sampled (SoftSamples hard shadows).
  const std::vector<vsh_planar_pair> softPairs = this->SplitSoftPairs(frame, pairs);
  // Pairs that get the translucent casters' transmittance (none without them).
  const std::vector<vsh_planar_pair> transmitPairs = this->TransmitPairs(frame, pairs, softPairs);
  vtkshadow::MarkStage("planar.plan");
  this->DrawMask(window, frame, pairs, softPairs, transmitPairs);
  this->ForgetRemovedCasters(window);
  vtkshadow::MarkStage("planar.mask");

  // The scene, with the receivers' lighting reading the mask.
  impl.Mask->Activate();
  if (!softPairs.empty())
  {
    impl.Soft->Activate();
  }
  if (!transmitPairs.empty())
  {
    impl.Transmit->Activate();
  }
  this->RenderDelegateWithShaderHooks(s);
  if (!transmitPairs.empty())
  {
    impl.Transmit->Deactivate();
  }
  if (!softPairs.empty())
  {
    impl.Soft->Deactivate();
  }
  impl.Mask->Deactivate();
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::GatherReceivers(
  const std::vector<vtkshadow::ShadowActor>& actors, Frame& frame)
{
  Internals& impl = *this->Impl;
  impl.ReceiverIndex.clear();
  impl.ReceiverByKeys.clear();
  // Marked actors, or else the flat ones (detection).
  const vtkshadow::ReceiverChoice choice = this->ChooseReceivers(actors);
  impl.Detected.clear();
  for (const vtkshadow::ShadowActor& receiver : choice.Receivers)
  {
    vtkActor* actor = receiver.Actor;
    if (choice.Detected)
    {
      impl.Detected.emplace_back(actor);
    }
    vtkshadow::ReceiverPlaneCache::Entry& plane = impl.ReceiverPlanes.Get(receiver);
    if (!plane.Flat)
    {
      if (!plane.Reported)
      {
        vtkWarningMacro("receiver actor " << actor << " is not flat: it receives no shadow");
        plane.Reported = true;
      }
      continue;
    }
    // Every (receiver, light) pair needs a mask bit: at most 128 of them.
    if (!vsh_planar_receiver_fits(static_cast<int>(frame.Receivers.size()), impl.LightCount))
    {
      vtkWarningMacro("more receivers than " << MaxPairs << " mask bits allow for "
                                             << impl.LightCount << " lights: ignoring some");
      continue;
    }
    impl.ReceiverIndex[actor] = static_cast<int>(frame.Receivers.size());
    // Keys now, so that an inner actor sharing them can be traced back (the
    // render pass would give the actor keys in PreRender anyway).
    if (!actor->GetPropertyKeys())
    {
      vtkNew<vtkInformation> keys;
      actor->SetPropertyKeys(keys);
    }
    impl.ReceiverByKeys[actor->GetPropertyKeys()] = actor;
    frame.Receivers.push_back(actor);
    frame.Planes.insert(frame.Planes.end(), plane.Plane, plane.Plane + 4);
    frame.CasterLift.push_back(0.0);
  }
  // Explicit planes receive on every opaque fragment lying on them.
  for (const auto& p : impl.Planes)
  {
    const double plane[4] = { p.Normal[0], p.Normal[1], p.Normal[2],
      -(p.Normal[0] * p.Origin[0] + p.Normal[1] * p.Origin[1] + p.Normal[2] * p.Origin[2]) };
    frame.Receivers.push_back(nullptr);
    frame.Planes.insert(frame.Planes.end(), plane, plane + 4);
    frame.CasterLift.push_back(0.0);
  }
  const bool detecting =
    this->DetectReceivers && impl.Planes.empty() && (choice.Detected || choice.Receivers.empty());
  impl.DetectedParts = detecting ? this->GatherFlatParts(actors, choice, frame) : 0;
  this->UpdateReceivingSet();
}

//------------------------------------------------------------------------------
int vtkPlanarShadowPass::GatherFlatParts(const std::vector<vtkshadow::ShadowActor>& actors,
  const vtkshadow::ReceiverChoice& choice, Frame& frame)
{
  // The flat parts of the meshes that are not receivers as a whole (a box's
  // top, a slab floor), as planes every fragment on them receives on, like
  // explicit planes. Only parts whose visible side is lit by a casting
  // light can show a shadow; the largest of those take the plane slots.
  Internals& impl = *this->Impl;
  std::vector<vtkshadow::FlatPart> candidates;
  for (const vtkshadow::ShadowActor& actor : actors)
  {
    const bool receiver = std::any_of(choice.Receivers.begin(), choice.Receivers.end(),
      [&](const vtkshadow::ShadowActor& r) { return r.Actor == actor.Actor; });
    if (receiver || vtkshadow::FlagKeys(actor, RECEIVER()))
    {
      continue; // a receiver itself, or opted out with RECEIVER() = 0
    }
    for (const vtkshadow::FlatPart& part : impl.ReceiverPlanes.GetParts(actor))
    {
      if (this->PartCanShowShadow(part.Plane.data(), frame))
      {
        candidates.push_back(part);
      }
    }
  }
  std::stable_sort(candidates.begin(), candidates.end(),
    [](const vtkshadow::FlatPart& a, const vtkshadow::FlatPart& b) { return a.Area > b.Area; });
  int added = 0;
  for (const vtkshadow::FlatPart& part : candidates)
  {
    const int planes =
      static_cast<int>(std::count(frame.Receivers.begin(), frame.Receivers.end(), nullptr));
    if (planes >= MaxExplicitPlanes ||
      !vsh_planar_receiver_fits(static_cast<int>(frame.Receivers.size()), impl.LightCount))
    {
      break;
    }
    frame.Receivers.push_back(nullptr);
    frame.Planes.insert(frame.Planes.end(), part.Plane.begin(), part.Plane.end());
    frame.CasterLift.push_back(part.OnPlane);
    ++added;
  }
  return added;
}

//------------------------------------------------------------------------------
bool vtkPlanarShadowPass::PartCanShowShadow(const double plane[4], const Frame& frame) const
{
  // Seen from the eye's side and lit from that side by a casting light
  // (either orientation of the plane: meshes are not all wound outwards).
  const double eye = plane[0] * frame.Shared.Eye[0] + plane[1] * frame.Shared.Eye[1] +
    plane[2] * frame.Shared.Eye[2] + plane[3];
  for (const vsh_planar_light& light : frame.Lights)
  {
    const double* l = light.homogeneous;
    const double side = plane[0] * l[0] + plane[1] * l[1] + plane[2] * l[2] + plane[3] * l[3];
    if (light.casts && eye * side > 0.0)
    {
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::UpdateReceivingSet()
{
  // Only receiving actors get the shadow lookup in their shaders; when the set
  // changes, VTK's mappers must rebuild their shaders.
  Internals& impl = *this->Impl;
  std::vector<vtkProp*> receiving;
  for (const auto& entry : impl.ReceiverIndex)
  {
    receiving.push_back(entry.first);
  }
  const bool everyone = !impl.Planes.empty() || impl.DetectedParts > 0;
  if (receiving != impl.Receiving || everyone != impl.EveryoneReceives)
  {
    impl.Receiving = receiving;
    impl.EveryoneReceives = everyone;
    this->BumpShaderTime();
  }
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::GatherCasters(
  const std::vector<vtkshadow::ShadowActor>& actors, Frame& frame)
{
  for (const vtkshadow::ShadowActor& actor : actors)
  {
    if (vtkshadow::CastsAsSurface(actor, NO_CAST()))
    {
      frame.Casters.push_back(actor);
    }
  }
  // Points drawn as spheres and lines drawn as tubes: their closed proxies,
  // drawn as silhouette fans like any closed caster.
  this->Impl->Proxies.Append(frame.Shared, actors, frame.Casters);
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::NoteClosedCasters(vtkRenderer* renderer, const Frame& frame)
{
  // A facet of a closed opaque caster facing away from a light this pass
  // casts is in the caster's own shadow. Receivers do not need it (they are
  // flat, so open), nor do the impostors' proxies (VTK lights the spheres
  // and tubes it draws by their exact normals).
  Internals& impl = *this->Impl;
  impl.FacingBits.clear();
  int casting = 0;
  for (size_t light = 0; light < frame.Shared.Lights.size(); ++light)
  {
    const bool casts = frame.Shared.Lights[light].Casts;
    casting |= casts && light < vtkshadow::FacingLights::MaxLights ? 1 << light : 0;
  }
  if (this->FacingTest && casting != 0)
  {
    impl.Facing = vtkshadow::FacingLightsOf(renderer, frame.Shared, this->SoftSamples > 1);
    for (const vtkshadow::ShadowActor& caster : frame.Casters)
    {
      if (!caster.Proxy && !impl.ReceiverIndex.count(caster.Actor) &&
        this->CasterGeometry(caster.Actor)->IsClosed())
      {
        impl.FacingBits[caster.Actor] = casting;
      }
    }
  }
  // Only these actors' shaders carry the facing test.
  impl.FacingShaders.Begin();
  for (const auto& entry : impl.FacingBits)
  {
    impl.FacingShaders.Add(entry.first);
  }
  if (impl.FacingShaders.Commit())
  {
    this->BumpShaderTime();
  }
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::SetUpPlanes(const Frame& frame)
{
  // Explicit planes in view coordinates for the receivers' fragment shaders.
  Internals& impl = *this->Impl;
  impl.PlaneCount = 0;
  for (size_t r = 0; r < frame.Receivers.size(); ++r)
  {
    if (frame.Receivers[r] || impl.PlaneCount >= MaxExplicitPlanes)
    {
      continue;
    }
    double planeVC[4];
    vsh_planar_plane_to_view(
      &frame.Planes[4 * r], frame.Shared.ViewRotation, frame.Shared.Eye, planeVC);
    ToFloat(planeVC, impl.PlaneVC + 4 * impl.PlaneCount, 4);
    impl.PlaneReceiver[impl.PlaneCount] = static_cast<int>(r);
    impl.PlaneTolerance[impl.PlaneCount] = static_cast<float>(this->PlaneTolerance);
    ++impl.PlaneCount;
  }
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::AllocateMask(vtkOpenGLRenderWindow* window, const Frame& frame)
{
  Internals& impl = *this->Impl;
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
  const int* size = frame.Shared.Size;
  const int maskChannels =
    vsh_planar_mask_channels(static_cast<int>(frame.Receivers.size()), impl.LightCount);
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
    impl.DirtyAll = true;
  }
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::AttachStencil(const Frame& frame)
{
  // Stencil (with depth, unused) for the fans' winding numbers.
  Internals& impl = *this->Impl;
  const int* size = frame.Shared.Size;
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
  glFramebufferRenderbuffer(
    GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, impl.Stencil);
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::DrawMask(vtkOpenGLRenderWindow* window, const Frame& frame,
  const std::vector<vsh_planar_pair>& pairs, const std::vector<vsh_planar_pair>& softPairs,
  const std::vector<vsh_planar_pair>& transmitPairs)
{
  Internals& impl = *this->Impl;
  this->AllocateMask(window, frame);
  vtkOpenGLState* state = window->GetState();
  state->PushFramebufferBindings();
  impl.FBO->Bind();
  impl.FBO->AddColorAttachment(0, impl.Mask);
  impl.FBO->ActivateDrawBuffers(1);
  this->AttachStencil(frame);
  {
    vtkOpenGLState::ScopedglViewport viewport(state);
    vtkOpenGLState::ScopedglScissor scissorBox(state);
    vtkOpenGLState::ScopedglEnableDisable stencil(state, GL_STENCIL_TEST);
    vtkOpenGLState::ScopedglEnableDisable depth(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable cull(state, GL_CULL_FACE);
    vtkOpenGLState::ScopedglEnableDisable scissor(state, GL_SCISSOR_TEST);
    vtkOpenGLState::ScopedglColorMask colorMask(state);
    state->vtkglViewport(0, 0, frame.Shared.Size[0], frame.Shared.Size[1]);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_CULL_FACE);
    state->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    this->ClearWritten(state);
    vsh_planar_rect_init(&impl.Written);

    vtkShaderProgram* program = nullptr;
    if (!frame.Receivers.empty() && impl.LightCount > 0)
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
      for (const vsh_planar_pair& pair : pairs)
      {
        this->DrawPair(program, state, frame, pair);
      }
      glDisable(GL_CLIP_DISTANCE0);
      glDisable(GL_CLIP_DISTANCE1);
      glDisable(GL_COLOR_LOGIC_OP);
    }
    impl.DirtyAll = false;
    if (!vsh_planar_rect_pixels(&impl.Written, frame.Shared.Size, impl.DirtyBox))
    {
      std::fill_n(impl.DirtyBox, 4, 0);
    }
    if (!softPairs.empty())
    {
      this->DrawSoftPairs(window, state, frame, softPairs);
    }
    if (!transmitPairs.empty())
    {
      this->DrawTransmitPairs(window, state, frame, transmitPairs);
    }
  }
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
  impl.FBO->RemoveColorAttachment(0);
  state->PopFramebufferBindings();
}

//------------------------------------------------------------------------------
// Zero the mask where the last frame wrote bits (all of it after an
// allocation); the rest is still zero.
void vtkPlanarShadowPass::ClearWritten(vtkOpenGLState* state)
{
  Internals& impl = *this->Impl;
  const GLuint zero[4] = { 0, 0, 0, 0 };
  if (impl.DirtyAll)
  {
    state->vtkglDisable(GL_SCISSOR_TEST);
    glClearBufferuiv(GL_COLOR, 0, zero);
  }
  else if (impl.DirtyBox[2] > impl.DirtyBox[0] && impl.DirtyBox[3] > impl.DirtyBox[1])
  {
    const int* b = impl.DirtyBox;
    state->vtkglEnable(GL_SCISSOR_TEST);
    state->vtkglScissor(b[0], b[1], b[2] - b[0], b[3] - b[1]);
    glClearBufferuiv(GL_COLOR, 0, zero);
  }
  state->vtkglDisable(GL_SCISSOR_TEST);
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::DrawPair(
  vtkShaderProgram* program, vtkOpenGLState* state, const Frame& frame, const vsh_planar_pair& pair)
{
  ++this->NumberOfShadowPairs;
  double shadowDC[16];
  vsh_mat4_multiply(frame.Shared.CameraRelative, pair.shadow, shadowDC);
  unsigned int bits[4];
  vsh_planar_pair_bits(pair.bit, bits);
  glUniform4uiv(glGetUniformLocation(program->GetHandle(), "pairBit"), 1, bits);
  vtkActor* receiver = frame.Receivers[pair.receiver];
  const double* receiverPlane = &frame.Planes[4 * pair.receiver];
  std::vector<Fan> fans;
  vsh_planar_rect fanRect;
  vsh_planar_rect_init(&fanRect);
  for (const vtkshadow::ShadowActor& caster : frame.Casters)
  {
    if (caster.Actor == receiver && !caster.Proxy)
    {
      continue; // a flat receiver does not shadow itself (its spheres do)
    }
    if (!receiver && LiesInPlane(caster, receiverPlane))
    {
      continue; // nor does a surface lying in an explicit receiver plane
    }
    vtkShadowCasterGeometry* geometry =
      caster.Proxy ? caster.Proxy : this->CasterGeometry(caster.Actor);
    if (geometry->GetNumberOfTriangles() > 0)
    {
      this->DrawCaster(program, frame, pair, frame.Lights[pair.light].homogeneous, shadowDC, caster,
        *geometry, &fans, &fanRect);
    }
  }
  if (!fans.empty())
  {
    this->FillFans(program, state, frame, fans, fanRect, bits);
  }
}

//------------------------------------------------------------------------------
vtkShadowCasterGeometry* vtkPlanarShadowPass::CasterGeometry(vtkActor* actor)
{
  // Built on first use in a frame, rebuilt only when the mesh changed.
  Internals& impl = *this->Impl;
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
  return &caster->Geometry;
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::DrawCaster(vtkShaderProgram* program, const Frame& frame,
  const vsh_planar_pair& pair, const double light[4], const double shadowDC[16],
  const vtkshadow::ShadowActor& caster, vtkShadowCasterGeometry& geometry, std::vector<Fan>* fans,
  vsh_planar_rect* fanRect)
{
  // Model (shifted) -> world -> relative to the eye, in double.
  const double* model = caster.Matrix;
  double modelRelative[16];
  geometry.GetModelRelativeMatrix(model, frame.Shared.Eye, modelRelative);
  double mcdc[16], keep0[4], keep1[4], transposed[16];
  vsh_mat4_multiply(shadowDC, modelRelative, mcdc);
  PlaneTimesMatrix(pair.clip[0], modelRelative, keep0);
  PlaneTimesMatrix(pair.clip[1], modelRelative, keep1);
  float mcdcF[16], keep0F[4], keep1F[4];
  // vtkShaderProgram expects column-major (OpenGL) order.
  vsh_mat4_transpose(mcdc, transposed);
  ToFloat(transposed, mcdcF, 16);
  ToFloat(keep0, keep0F, 4);
  ToFloat(keep1, keep1F, 4);
  // Clipping costs a software rasterizer a stage per triangle: skip it when
  // every corner of the caster's bounds is kept anyway.
  const double* b = caster.Bounds;
  const bool clipNeeded = vsh_planar_bounds_clipped(pair.clip, b, frame.Shared.Eye) != 0;
  double inverse[16];
  if (fans && !clipNeeded && geometry.IsClosed() && vsh_mat4_inverse(model, inverse))
  {
    // Closed and unclipped: its silhouette fans, counted in the stencil,
    // cover exactly what its triangles would (without `fans`, every
    // triangle is drawn: a translucent caster's transmittance).
    Fan fan;
    fan.Geometry = &geometry;
    std::copy_n(mcdcF, 16, fan.MCDC);
    vsh_mat4_transform_point4(inverse, light, fan.Light);
    fans->push_back(fan);
    vsh_planar_rect_add_bounds(fanRect, shadowDC, b, frame.Shared.Eye);
    return;
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
  geometry.Draw(program);
  vsh_planar_rect_add_bounds(&this->Impl->Written, shadowDC, b, frame.Shared.Eye);
  this->NumberOfMaskTriangles += geometry.GetNumberOfTriangles();
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::FillFans(vtkShaderProgram* program, vtkOpenGLState* state,
  const Frame& frame, const std::vector<Fan>& fans, const vsh_planar_rect& fanRect,
  const unsigned int bits[4])
{
  // Winding numbers of the silhouette fans in the stencil (front +1, back
  // -1), then the pair's bit wherever it is not zero, within the casters'
  // projected bounds.
  int box[4];
  if (!vsh_planar_rect_pixels(&fanRect, frame.Shared.Size, box))
  {
    return;
  }
  vsh_planar_rect& written = this->Impl->Written;
  written.full |= fanRect.full;
  for (int k = 0; k < 2; ++k)
  {
    written.ndc[k] = std::min(written.ndc[k], fanRect.ndc[k]);
    written.ndc[2 + k] = std::max(written.ndc[2 + k], fanRect.ndc[2 + k]);
  }
  // Through vtkOpenGLState: VTK caches this state, and a stale cache would
  // leave our scissor box on its own renders.
  state->vtkglEnable(GL_SCISSOR_TEST);
  state->vtkglScissor(box[0], box[1], box[2] - box[0], box[3] - box[1]);
  state->vtkglStencilMask(0xff);
  glClearStencil(0);
  state->vtkglClear(GL_STENCIL_BUFFER_BIT);
  state->vtkglEnable(GL_STENCIL_TEST);
  // Counting only: OR-ing zero writes nothing (llvmpipe does not honour a
  // colour mask with logic ops on integer targets).
  const unsigned int none[4] = { 0, 0, 0, 0 };
  const GLint pairBitLocation = glGetUniformLocation(program->GetHandle(), "pairBit");
  glUniform4uiv(pairBitLocation, 1, none);
  state->vtkglStencilFunc(GL_ALWAYS, 0, 0xff);
  state->vtkglStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
  state->vtkglStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
  glDisable(GL_CLIP_DISTANCE0);
  glDisable(GL_CLIP_DISTANCE1);
  // Keep-all planes too: llvmpipe was seen to apply the clip distances a
  // shader writes even with them disabled.
  const float keepAll[4] = { 0, 0, 0, 1 };
  program->SetUniform4f("receiverSideMC", keepAll);
  program->SetUniform4f("belowLightMC", keepAll);
  this->DrawFans(program, fans);
  glUniform4uiv(pairBitLocation, 1, bits);
  state->vtkglStencilFunc(GL_NOTEQUAL, 0, 0xff);
  state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  this->DrawViewportQuad(program);
  state->vtkglDisable(GL_STENCIL_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::DrawFans(vtkShaderProgram* program, const std::vector<Fan>& fans)
{
  for (const Fan& fan : fans)
  {
    float mcdc[16];
    std::copy_n(fan.MCDC, 16, mcdc);
    program->SetUniformMatrix4x4("shadowMCDC", mcdc);
    fan.Geometry->DrawSilhouetteFans(program, fan.Light);
    this->NumberOfMaskTriangles += fan.Geometry->GetNumberOfSilhouetteTriangles();
  }
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::DrawViewportQuad(vtkShaderProgram* program)
{
  // A quad over the viewport in clip space sets the bit.
  float identity[16] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  const float keep[4] = { 0, 0, 0, 1 };
  program->SetUniformMatrix4x4("shadowMCDC", identity);
  program->SetUniform4f("receiverSideMC", keep);
  program->SetUniform4f("belowLightMC", keep);
  this->Impl->Quad.Draw(program);
}

//------------------------------------------------------------------------------
void vtkPlanarShadowPass::ForgetRemovedCasters(vtkOpenGLRenderWindow* window)
{
  // Casters not drawn last frame nor this one have left the scene.
  Internals& impl = *this->Impl;
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
}

//------------------------------------------------------------------------------
bool vtkPlanarShadowPass::PreReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp* prop)
{
  // Our declarations ride along with VTK's lighting declarations.
  if (fragmentShader.find("//VTK::Light::Dec") == std::string::npos)
  {
    return true;
  }
  // The facing test's code for the closed casters (NoteClosedCasters), its
  // lights chosen per draw by a uniform.
  std::string declarations = this->Impl->FacingShaders.Has(this->Impl->Outer(prop))
    ? vtkshadow::FacingShaderCode(FacingPrefix)
    : std::string();
  if (this->Impl->CanReceive(prop))
  {
    // The soft lookup only in frames with soft pairs: hard frames keep the
    // hard shader, byte for byte.
    declarations = std::string(this->Impl->SoftShader ? "#define VSH_PLANAR_SOFT 1\n" : "") +
      (this->Impl->TransmitShader ? "#define VSH_PLANAR_TRANSMIT 1\n" : "") +
      vtkPlanarShadowLightFS + declarations;
  }
  vtkShaderProgram::Substitute(
    fragmentShader, "//VTK::Light::Dec", "//VTK::Light::Dec\n" + declarations, false);
  return true;
}

//------------------------------------------------------------------------------
bool vtkPlanarShadowPass::PostReplaceShaderValues(
  std::string&, std::string&, std::string& fragmentShader, vtkAbstractMapper*, vtkProp*)
{
  // A light with a size: 0 where the facet sees none of it, else 1 (the
  // mask is 1 on a caster; the N.L-weighted visibility Cycles and raytrace
  // give a convex caster's terminator, vshFacingCombine).
  const std::string facing = std::string(FacingPrefix) + "Combine(%d, vertexVC.xyz, 1.0)";
  const std::string facingPrepare = std::string(FacingPrefix) + "Prepare(vertexVC.xyz);";
  const bool faces =
    fragmentShader.find(std::string(FacingPrefix) + "Prepare") != std::string::npos;
  const bool receives = fragmentShader.find("vshPlanarLit") != std::string::npos;
  // Each light's diffuse and specular terms times its factor: a receiver's
  // mask bit (read once per fragment), and the facing test.
  if (faces && !receives)
  {
    this->InjectLightFactors(fragmentShader, facing, facingPrepare);
  }
  else if (receives)
  {
    this->InjectLightFactors(fragmentShader, "vshPlanarLit(%d)" + (faces ? " * " + facing : ""),
      "vshPlanarPrepare(vertexVC.xyz);" + (faces ? " " + facingPrepare : ""));
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkPlanarShadowPass::SetShaderParameters(
  vtkShaderProgram* program, vtkAbstractMapper*, vtkProp* prop, vtkOpenGLVertexArrayObject*)
{
  Internals& impl = *this->Impl;
  vtkProp* outer = impl.Outer(prop);
  const auto closed = impl.FacingBits.find(outer);
  vtkshadow::SetFacingUniforms(
    program, FacingPrefix, closed == impl.FacingBits.end() ? 0 : closed->second, impl.Facing);
  if (!program->IsUniformUsed("vshPlanarMask") || !impl.Mask)
  {
    return true;
  }
  program->SetUniformi("vshPlanarMask", impl.Mask->GetTextureUnit());
  program->SetUniform2i("vshPlanarMaskOrigin", impl.MaskOrigin);
  auto it = impl.ReceiverIndex.find(outer);
  program->SetUniformi("vshPlanarReceiver", it == impl.ReceiverIndex.end() ? -1 : it->second);
  program->SetUniformi("vshPlanarLightCount", std::max(impl.LightCount, 1));
  program->SetUniformi("vshPlanarPlaneCount", impl.PlaneCount);
  if (impl.PlaneCount > 0)
  {
    program->SetUniform4fv(
      "vshPlanarPlaneVC", impl.PlaneCount, reinterpret_cast<const float(*)[4]>(impl.PlaneVC));
    program->SetUniform1iv("vshPlanarPlaneReceiver", impl.PlaneCount, impl.PlaneReceiver);
    program->SetUniform1fv("vshPlanarPlaneTolerance", impl.PlaneCount, impl.PlaneTolerance);
  }
  if (impl.Soft && program->IsUniformUsed("vshPlanarSoft"))
  {
    program->SetUniformi("vshPlanarSoft", impl.Soft->GetTextureUnit());
    program->SetUniform1iv("vshPlanarSoftPair", MaxSoftPairs, impl.SoftPair);
  }
  if (impl.Transmit && program->IsUniformUsed("vshPlanarTransmit"))
  {
    program->SetUniformi("vshPlanarTransmit", impl.Transmit->GetTextureUnit());
    program->SetUniform1iv(
      "vshPlanarTransmitPair", vtkshadow::planar::MaxTransmitPairs, impl.TransmitPair);
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
  if (impl.Soft)
  {
    impl.Soft->ReleaseGraphicsResources(w);
  }
  if (impl.SoftMark)
  {
    impl.SoftMark->ReleaseGraphicsResources(w);
  }
  impl.SoftSize[0] = impl.SoftSize[1] = 0;
  if (impl.Transmit)
  {
    impl.Transmit->ReleaseGraphicsResources(w);
  }
  impl.TransmitSize[0] = impl.TransmitSize[1] = 0;
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
  impl.Quad.ReleaseGraphicsResources();
  impl.Proxies.ReleaseGraphicsResources(w);
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
  os << indent << "DetectedReceivers: " << this->Impl->Detected.size() << "\n";
  os << indent << "NumberOfShadowPairs: " << this->NumberOfShadowPairs << "\n";
  os << indent << "NumberOfMaskTriangles: " << this->NumberOfMaskTriangles << "\n";
  os << indent << "NumberOfGeometryBuilds: " << this->NumberOfGeometryBuilds << "\n";
  os << indent << "NumberOfSoftPairs: " << this->NumberOfSoftPairs << "\n";
  os << indent << "NumberOfRefinedPixels: " << this->NumberOfRefinedPixels << "\n";
}

//------------------------------------------------------------------------------
// The settings, once (vtkShadowSettings.h).
const vtkshadow::Settings& vtkPlanarShadowPass::SettingsTable()
{
  using P = vtkPlanarShadowPass;
  using vtkshadow::Row;
  static const vtkshadow::Settings table(&vtkShadowPassBase::SettingsTable(),
    {
      Row("plane_tolerance", vtkshadow::Closed(0, 1), &P::SetPlaneTolerance, &P::GetPlaneTolerance,
        "fragments this close to a receiver plane (relative to their distance) receive"),
      Row("detect_receivers", vtkshadow::Flag(), &P::SetDetectReceivers, &P::GetDetectReceivers,
        "flat actors receive when none is marked a receiver"),
      Row("soft_samples", vtkshadow::Integers(1, 1024), &P::SetSoftSamples, &P::GetSoftSamples,
        "samples of a light with a size (docs/soft-shadows.md)"),
      Row("adaptive", vtkshadow::Flag(), &P::SetAdaptive, &P::GetAdaptive,
        "soft_samples > 8: the samples beyond a batch of 8 only where the batch disagrees"),
      Row("facing_test", vtkshadow::Flag(), &P::SetFacingTest, &P::GetFacingTest,
        "darken the facets of closed casters that face away from a light"),
    });
  return table;
}

//------------------------------------------------------------------------------
std::string vtkPlanarShadowPass::GetStatsJSON(vtkRenderer* renderer) const
{
  // Per adaptive soft pair: its light, the pixels that got all N samples
  // and the box they were drawn in (pixels).
  std::string adaptive = "[";
  for (const Internals::PairStats& pair : this->Impl->SoftStats)
  {
    adaptive += std::string(adaptive.size() > 1 ? ", " : "") +
      "{\"light\": " + std::to_string(pair.Light) +
      ", \"refined_px\": " + std::to_string(pair.Refined) +
      ", \"box_px\": " + std::to_string(pair.BoxPixels) + "}";
  }
  adaptive += "]";
  return "\"shadow_pairs\": " + std::to_string(this->NumberOfShadowPairs) +
    ", \"mask_triangles\": " + std::to_string(this->NumberOfMaskTriangles) +
    ", \"geometry_builds\": " + std::to_string(this->NumberOfGeometryBuilds) +
    ", \"soft_pairs\": " + std::to_string(this->NumberOfSoftPairs) + ", \"transmit_pairs\": " +
    std::to_string(std::count_if(std::begin(this->Impl->TransmitPair),
      std::end(this->Impl->TransmitPair), [](int bit) { return bit >= 0; })) +
    ", \"soft_samples\": " + std::to_string(this->SoftSamples) +
    ", \"soft_batch\": " + std::to_string(this->Impl->SoftAdaptive ? VSH_SOFT_ADAPTIVE_BATCH : 0) +
    ", \"soft_adaptive\": " + adaptive +
    ", \"detected_receivers\": " + this->DetectedReceiversJSON(renderer) +
    ", \"detected_flat_parts\": " + std::to_string(this->Impl->DetectedParts) + ", " +
    this->Impl->Proxies.StatsJSON();
}

//------------------------------------------------------------------------------
int vtkPlanarShadowPass::GetNumberOfDetectedReceivers() const
{
  return static_cast<int>(this->Impl->Detected.size());
}

//------------------------------------------------------------------------------
vtkActor* vtkPlanarShadowPass::GetDetectedReceiver(int index) const
{
  const auto& detected = this->Impl->Detected;
  return index >= 0 && index < static_cast<int>(detected.size()) ? detected[index].GetPointer()
                                                                 : nullptr;
}
