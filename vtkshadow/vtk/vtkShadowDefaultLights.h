// vtkShadowDefaultLights.h - the key light enable_shadows adds when a
// renderer has no light of its own, placed as vtkLightKit places its key.
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
 * lights of its own (they are left alone).
 */
vtkLight* AddKeyLight(vtkRenderer* renderer, std::string& message);
}

#endif
