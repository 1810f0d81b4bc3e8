/**
 * The scene steps a renderer would run itself, for passes that render the
 * scene through a delegate.
 *
 * A vtkOpenGLRenderer ignores UseDepthPeeling and UseFXAA as soon as it has
 * a render pass: both live in the code path a pass replaces. The steps made
 * here read them from the renderer at every frame, so switching shadows on
 * keeps what the application asked for: translucent geometry by (dual)
 * depth peeling with the renderer's peels and occlusion ratio when
 * UseDepthPeeling is on, else by order-independent transparency (what the
 * renderer does without a pass); FXAA after translucent geometry and before
 * volumes and overlays (where the renderer applies it) when UseFXAA is on.
 */
#ifndef vtkShadowRendererSteps_h
#define vtkShadowRendererSteps_h

class vtkRenderStepsPass;

namespace vtkshadow
{
// A new vtkRenderStepsPass (reference count 1) with those steps.
vtkRenderStepsPass* NewRendererSteps();
}

#endif
