/**
 * Where a shadow technique's pass goes among the render passes a renderer
 * already has, so that switching shadows on keeps what the application set
 * up instead of replacing it silently.
 *
 * - No pass, or one of ours (an earlier technique): ours is the pass; the
 *   scene delegate an earlier technique was given carries over.
 * - An image pass with a delegate (vtkImageProcessingPass: vtkSSAOPass,
 *   vtkToneMappingPass, vtkOpenGLFXAAPass, vtkEDLShading, blur, ...): it
 *   stays on top and ours renders the scene for it (composed in its
 *   delegate chain).
 * - VTK's own shadow passes (vtkShadowMapPass / vtkShadowMapBakerPass, alone
 *   or in a vtkCameraPass + vtkSequencePass as VTK's examples and vedo set
 *   them): replaced by ours, and said so.
 * - Any other arrangement (an application's vtkRenderStepsPass, e.g. with
 *   depth peeling or a post-process pass in it; VTK's standard steps under
 *   a camera pass; vedo's SSAO inside a camera pass and a sequence): the
 *   technique draws the scene through it, its shader hooks reaching every
 *   mapper the arrangement draws.
 * - Passes that do not shade with VTK's OpenGL mappers (vtkOSPRayPass,
 *   vtkValuePass), anywhere in the arrangement: refused, naming the passes
 *   found; nothing changes.
 */
#ifndef vtkShadowPassComposition_h
#define vtkShadowPassComposition_h

#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <string> // for std::string

class vtkRenderPass;
class vtkRenderer;
class vtkShadowPassBase;

namespace vtkshadow
{
struct PassComposition
{
  bool Ok = false;
  vtkSmartPointer<vtkRenderPass> Top;      // what to set on the renderer
  vtkSmartPointer<vtkRenderPass> Replaced; // the pass taken out, if any
  std::string Message;                     // what was done with the passes there ("" if none)
};

// Compose `ours` with `existing` (the renderer's pass, may be null). On
// failure Ok is false, Message says why and nothing was changed.
PassComposition ComposeShadowPass(vtkRenderPass* existing, vtkShadowPassBase* ours);

// The shadow technique's pass on `renderer`: its pass or the one composed
// under its image passes; nullptr when there is none.
vtkShadowPassBase* FindShadowPass(vtkRenderer* renderer);
}

#endif
