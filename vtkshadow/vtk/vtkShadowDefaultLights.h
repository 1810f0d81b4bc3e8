// vtkShadowDefaultLights.h - the key light enable_shadows keeps on a
// renderer without lights of its own, placed as vtkLightKit places its key,
// and how every pass brings the lights up to date for a frame.
#ifndef vtkShadowDefaultLights_h
#define vtkShadowDefaultLights_h

#include <string>

class vtkLight;
class vtkRenderer;

namespace vtkshadow
{
/**
 * Whether the renderer keeps the default lights (vtkShadowTechnique::Enable
 * with AutoKeyLight; kept in the renderer's information, so it holds for
 * whichever pass draws the renderer). UpdateLights applies it at each frame:
 *
 * - when the application's own lights (the renderer's lights but those added
 *   here) are none, or only headlights, whose shadows hide behind the
 *   casters: vtkLightKit's key light is added (a camera light at elevation
 *   50 and azimuth 10 degrees from the view direction, intensity 0.75) and
 *   a headlight at a third of the key (vtkLightKit's key-to-head ratio) is
 *   kept as the fill, so the shadowed side is not black: the application's
 *   headlights are dimmed to a quarter of their intensity, or a 0.25
 *   headlight is added when it has no light;
 * - otherwise, or when `on` is false, the lights added here are removed and
 *   the dimmed headlights get their own intensity back.
 *
 * So the lights are decided at the first frame and again whenever the
 * application's lights change, as if enable_shadows were called then. A
 * change is said once, as a VTK warning.
 */
void SetAutoKeyLight(vtkRenderer* renderer, bool on);
bool GetAutoKeyLight(vtkRenderer* renderer);

/**
 * The key light kept on the renderer, nullptr when there is none.
 */
vtkLight* FindKeyLight(vtkRenderer* renderer);

/**
 * What is done to the renderer's lights now, in a sentence ("" when
 * nothing: no key light is kept).
 */
std::string DescribeDefaultLights(vtkRenderer* renderer);

/**
 * Whether `light` is one of the default lights: the key, the fill, or a
 * headlight of the application dimmed to be the fill. They follow the
 * camera in every frame (UpdateLights).
 */
bool IsDefaultLight(vtkLight* light);

/**
 * The lights as the frame about to be drawn uses them. Every pass calls it
 * first, before its shadow work (VTK's lights pass does the same only
 * inside the delegate, after the shadows, which would make them lag a
 * frame):
 *
 * - the default lights are added or removed (SetAutoKeyLight);
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
