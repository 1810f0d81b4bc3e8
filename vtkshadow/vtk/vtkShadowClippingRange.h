// vtkShadowClippingRange.h - near and far planes from the geometry the camera
// actually sees.
//
// vtkRenderer::ResetCameraClippingRange keeps the near plane at least
// NearClippingPlaneTolerance (1/1000 with a 24-bit depth buffer) of the far
// plane, measured on the bounding box of everything. A scene with a depth
// range of 1e5 (a sphere 0.15 from the camera, a floor 2e4 long) then has
// its near plane at 20: everything close is clipped away. Here near and far
// come from each visible prop's bounding box clipped exactly to the view
// frustum, refined to the prop's own triangles when its box reaches the
// camera (a terrain around it), so nothing visible is clipped and the
// near/far ratio is no wider than the picture needs.
#ifndef vtkShadowClippingRange_h
#define vtkShadowClippingRange_h

class vtkRenderer;

namespace vtkshadow
{
/**
 * Smallest near/far ratio ever set: where geometry truly passes through the
 * eye, the near plane stays at this fraction of the far plane.
 */
constexpr double MinNearFarRatio = 1e-7;

/**
 * Compute [near, far] for the renderer's active camera from its visible
 * props. `aspect` <= 0: the renderer's own (4 if it has no size yet; a wider
 * frustum only moves near closer). Returns false (range untouched) when
 * there is no visible geometry in front of the camera or the camera is
 * parallel or degenerate.
 */
bool VisibleClippingRange(vtkRenderer* renderer, double aspect, double range[2]);

/**
 * Set the active camera's clipping range from VisibleClippingRange, or
 * VTK's own ResetCameraClippingRange where that returns false.
 */
void ResetClippingRange(vtkRenderer* renderer, double aspect = 0.0);
}

#endif
