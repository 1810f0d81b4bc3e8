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

class vtkRenderPass;
class vtkRenderStepsPass;
class vtkTextureObject;

namespace vtkshadow
{
// A new vtkRenderStepsPass (reference count 1) with those steps.
vtkRenderStepsPass* NewRendererSteps();

// Have steps made by NewRendererSteps write `depth` into the depth buffer
// before their opaque step where that pays (vtkShadowDepthSeed; with
// `always`, every frame), or nothing with nullptr.
// Returns false, doing nothing, for any other pass (an application's own
// delegate). GetDepthSeedState: whether their last opaque step was seeded
// and the last measurement's saved fragments per pixel (-1 before one);
// false for any other pass.
bool SetSeedDepth(vtkRenderPass* steps, vtkTextureObject* depth, bool always = false);
bool GetDepthSeedState(vtkRenderPass* steps, bool& seeded, double& hiddenPerPixel);
}

#endif
