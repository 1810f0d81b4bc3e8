// vtkShadowDefaultLights.h - the key light enable_shadows adds when a
// renderer has no light of its own, placed as vtkLightKit places its key,
// and how every pass brings the lights up to date for a frame.
#ifndef vtkShadowDefaultLights_h
#define vtkShadowDefaultLights_h

#include <string>

class vtkLight;
class vtkRenderer;

namespace vtkshadow
{
/**
 * Whether the renderer has no light that could cast a visible shadow of
 * its own: no light at all (VTK would make its automatic headlight at the
 * first render) or only headlights, whose shadows hide behind the casters.
 */
bool HasOnlyHeadlights(vtkRenderer* renderer);

/**
 * When HasOnlyHeadlights: add vtkLightKit's key light (a camera light at
 * elevation 50 and azimuth 10 degrees from the view direction, intensity
 * 0.75) and keep a headlight at a third of the key (vtkLightKit's
 * key-to-head ratio) as the fill, so the shadowed side is not black:
 * existing headlights are dimmed to 0.25, or one is added when there was no
 * light. Returns the key light (owned by the renderer) and says what was
 * done in `message`; nullptr and an empty message when the renderer has
 * lights of its own (they are left alone). The key and the fill are marked
 * as default lights (IsDefaultLight).
 */
vtkLight* AddKeyLight(vtkRenderer* renderer, std::string& message);

/**
 * Whether `light` is one of the lights AddKeyLight added or dimmed to be
 * the fill: they follow the camera in every frame (UpdateLights).
 */
bool IsDefaultLight(vtkLight* light);

/**
 * The lights as the frame about to be drawn uses them. Every pass calls it
 * first, before its shadow work (VTK's lights pass does the same only
 * inside the delegate, after the shadows, which would make them lag a
 * frame):
 *
 * - VTK's automatic headlight is made when the renderer has no light;
 * - headlights and camera lights are placed at the camera as VTK places
 *   them (vtkRenderer::UpdateLightsGeometryToFollowCamera): all of them
 *   when the renderer's LightFollowCamera is on, and the default lights
 *   (IsDefaultLight) whatever LightFollowCamera says, so the key and fill
 *   stay where vtkLightKit puts them relative to the view in every
 *   technique. With LightFollowCamera off the application's own lights stay
 *   where it put them, as VTK leaves them.
 */
void UpdateLights(vtkRenderer* renderer);
}

#endif
