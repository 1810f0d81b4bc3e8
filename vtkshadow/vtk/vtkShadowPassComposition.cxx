#include "vtkShadowPassComposition.h"

#include "vtkCameraPass.h"
#include "vtkImageProcessingPass.h"
#include "vtkOpenGLRenderer.h"
#include "vtkRenderPassCollection.h"
#include "vtkSequencePass.h"
#include "vtkShadowPassBase.h"

namespace
{
bool IsVTKShadowPass(vtkRenderPass* pass)
{
  return pass && (pass->IsA("vtkShadowMapPass") || pass->IsA("vtkShadowMapBakerPass"));
}

// The passes of the vtkSequencePass under a vtkCameraPass (or of a bare
// sequence when `bare` is true), nullptr when `pass` is not that.
vtkRenderPassCollection* SequencedSteps(vtkRenderPass* pass, bool bare)
{
  auto* camera = vtkCameraPass::SafeDownCast(pass);
  vtkRenderPass* inner = camera ? camera->GetDelegatePass() : (bare ? pass : nullptr);
  auto* sequence = vtkSequencePass::SafeDownCast(inner);
  return sequence ? sequence->GetPasses() : nullptr;
}

// Whether any of `steps` satisfies `test`.
template <typename Test>
bool AnyStep(vtkRenderPassCollection* steps, Test test)
{
  if (steps)
  {
    steps->InitTraversal();
    while (vtkRenderPass* p = steps->GetNextRenderPass())
    {
      if (test(p))
      {
        return true;
      }
    }
  }
  return false;
}

// VTK's shadow passes, alone or among the steps under a camera pass or in a
// sequence (vtkShadowMapBakerPass + vtkShadowMapPass: VTK's examples,
// vedo's add_shadows).
bool HoldsVTKShadows(vtkRenderPass* pass)
{
  return IsVTKShadowPass(pass) || AnyStep(SequencedSteps(pass, true), IsVTKShadowPass);
}

bool IsNotOpenGLShading(vtkRenderPass* pass)
{
  return pass->IsA("vtkOSPRayPass") || pass->IsA("vtkValuePass");
}

// Whether `test` holds for `pass` or any pass under it (camera and image
// pass delegates, sequence members).
template <typename Test>
bool AnyPass(vtkRenderPass* pass, Test test)
{
  if (!pass)
  {
    return false;
  }
  if (test(pass))
  {
    return true;
  }
  if (auto* camera = vtkCameraPass::SafeDownCast(pass))
  {
    return AnyPass(camera->GetDelegatePass(), test);
  }
  if (auto* image = vtkImageProcessingPass::SafeDownCast(pass))
  {
    return AnyPass(image->GetDelegatePass(), test);
  }
  return AnyStep(SequencedSteps(pass, true), [&](vtkRenderPass* p) { return AnyPass(p, test); });
}

// "vtkCameraPass > vtkSequencePass(vtkLightsPass, vtkOpaquePass)": what an
// unknown pass is made of, for the refusal.
std::string Describe(vtkRenderPass* pass)
{
  std::string out = pass->GetClassName();
  if (auto* camera = vtkCameraPass::SafeDownCast(pass))
  {
    return camera->GetDelegatePass() ? out + " > " + Describe(camera->GetDelegatePass()) : out;
  }
  auto* sequence = vtkSequencePass::SafeDownCast(pass);
  if (sequence && sequence->GetPasses())
  {
    std::string inner;
    sequence->GetPasses()->InitTraversal();
    while (vtkRenderPass* p = sequence->GetPasses()->GetNextRenderPass())
    {
      inner += (inner.empty() ? "" : ", ") + Describe(p);
    }
    return out + "(" + inner + ")";
  }
  return out;
}

// The application's scene pass at the bottom of a chain of our passes (a
// reflection pass wraps a technique's pass), or nullptr.
vtkRenderPass* ApplicationSceneOf(vtkShadowPassBase* pass)
{
  auto* inner = vtkShadowPassBase::SafeDownCast(pass->GetDelegatePass());
  return inner ? ApplicationSceneOf(inner) : pass->GetApplicationScene();
}

// Draw through the application's scene pass; said when the technique has
// steps of its own.
std::string DrawThrough(vtkShadowPassBase* ours, vtkRenderPass* scene)
{
  if (ours->SetApplicationScene(scene))
  {
    return "kept the renderer's " + Describe(scene) + ": the shadows are drawn through it";
  }
  return std::string("the technique draws the scene with its own steps (") + ours->GetClassName() +
    "): the renderer's " + Describe(scene) + " is not used";
}
}

//------------------------------------------------------------------------------
vtkshadow::PassComposition vtkshadow::ComposeShadowPass(
  vtkRenderPass* existing, vtkShadowPassBase* ours)
{
  PassComposition result;
  if (!existing)
  {
    result.Ok = true;
    result.Top = ours;
    return result;
  }
  if (auto* previous = vtkShadowPassBase::SafeDownCast(existing))
  {
    if (vtkRenderPass* scene = ApplicationSceneOf(previous))
    {
      result.Message = DrawThrough(ours, scene);
    }
    result.Ok = true;
    result.Top = ours;
    result.Replaced = existing;
    return result;
  }
  if (auto* image = vtkImageProcessingPass::SafeDownCast(existing))
  {
    PassComposition inner = ComposeShadowPass(image->GetDelegatePass(), ours);
    if (!inner.Ok)
    {
      inner.Message = std::string(existing->GetClassName()) + " > " + inner.Message;
      return inner;
    }
    image->SetDelegatePass(inner.Top);
    result = inner;
    result.Top = existing;
    result.Message = std::string("kept the renderer's ") + existing->GetClassName() +
      ": the shadows are drawn under it" + (result.Message.empty() ? "" : "; ") + result.Message;
    return result;
  }
  if (HoldsVTKShadows(existing))
  {
    result.Ok = true;
    result.Top = ours;
    result.Replaced = existing;
    result.Message =
      "replaced VTK's own shadow passes (" + Describe(existing) + ") that were on the renderer";
    return result;
  }
  // Passes that do not draw the scene with VTK's OpenGL mappers (OSPRay's
  // ray tracer; the value pass, which replaces the shading the shadows
  // modulate) have nothing for the shadows' shader hooks to act on.
  if (AnyPass(existing, IsNotOpenGLShading))
  {
    result.Message = "the renderer already has a render pass, " + Describe(existing) +
      ", that does not shade with VTK's OpenGL mappers, so shadows cannot be drawn through "
      "it; remove it first with renderer.SetPass(None)";
    return result;
  }
  // Any other arrangement of passes (a vtkRenderStepsPass, VTK's standard
  // steps under a camera pass, vedo's SSAO inside a camera pass and a
  // sequence) is the scene the shadows are drawn through: the technique's
  // shader hooks reach every mapper it draws.
  result.Message = DrawThrough(ours, existing);
  result.Ok = true;
  result.Top = ours;
  return result;
}

//------------------------------------------------------------------------------
vtkShadowPassBase* vtkshadow::FindShadowPass(vtkRenderer* renderer)
{
  auto* gl = vtkOpenGLRenderer::SafeDownCast(renderer);
  vtkRenderPass* pass = gl ? gl->GetPass() : nullptr;
  while (auto* image = vtkImageProcessingPass::SafeDownCast(pass))
  {
    pass = image->GetDelegatePass();
  }
  return vtkShadowPassBase::SafeDownCast(pass);
}
