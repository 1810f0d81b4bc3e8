/**
 * @class   vtkShadowTechnique
 * @brief   Builds the render-pass pipeline of one shadow technique.
 *
 * vtkShadowTechnique turns a technique name into the render pass that a
 * vtkOpenGLRenderer runs, so that tools, tests and applications switch
 * techniques without knowing how each is assembled. The names, their
 * descriptions and the passes come from vtkShadowTechniqueRegistry (none,
 * vtk, planar, csm, auto, ...); settings are passed by name with SetOption
 * and checked against the technique's settings table (vtkShadowSettings.h).
 *
 * Enable() (and the one-call EnableShadows(), vtkshadow.enable_shadows in
 * Python, vtkshadow_enable_shadows in C) also makes the shadows visible on
 * an ordinary VTK scene: at each frame in which the renderer has no light
 * of its own, vtkLightKit's key light is there (AutoKeyLight;
 * GetAddedKeyLight, GetLightMessage), and the planar receivers are found by
 * the passes (GetDetectedReceiver).
 *
 * @code{.py}
 * technique = vtkshadow.vtkShadowTechnique()
 * technique.SetName("vtk")
 * technique.Install(renderer)
 * @endcode
 */
#ifndef vtkShadowTechnique_h
#define vtkShadowTechnique_h

#include "vtkObject.h"
#include "vtkShadowPassBase.h" // for CreatePass()
#include "vtkSmartPointer.h"   // for EnableShadows()
#include "vtkWeakPointer.h"    // for the renderer
#include "vtkshadowModule.h"   // for export macro

#include <string>  // for std::string
#include <utility> // for std::pair
#include <vector>  // for std::vector

class vtkActor;
class vtkLight;
class vtkRenderPass;
class vtkRenderer;

class VTKSHADOW_EXPORT vtkShadowTechnique : public vtkObject
{
public:
  static vtkShadowTechnique* New();
  vtkTypeMacro(vtkShadowTechnique, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The technique name (default "none"). Unknown names are rejected by
   * IsValid() and CreatePass().
   */
  vtkSetStringMacro(Name);
  vtkGetStringMacro(Name);

  /**
   * Shadow map edge length in texels for map-based techniques (default 2048).
   */
  vtkSetClampMacro(MapResolution, int, 16, 16384);
  vtkGetMacro(MapResolution, int);

  /**
   * Set a technique setting by name (command lines, the C API): the key and
   * range are checked against the technique's settings table (the rows of
   * its pass, vtkShadowSettings.h; map_resolution is accepted for every
   * technique and used by those with maps), without making a pass. Returns
   * false for an unknown key or a value out of range (nothing is changed
   * then). Settings are applied, in the order given, to every pass
   * CreatePass() makes.
   */
  bool SetOption(const char* key, double value);

  /**
   * Every technique's settings, one per line, tab-separated: technique,
   * key, range ("[16, 16384]", "(0, 1]", "[0, inf)"), integer ("yes" /
   * "no"), default, one line of documentation. `vtkshadow-render
   * --list-settings` prints it; docs/techniques.md's tables are made from it.
   */
  static std::string GetSettingsListing();

  /**
   * Technique details of the last frame rendered on `renderer` as a JSON
   * object (vtkShadowPassBase::GetStatsJSON of the installed pass), "{}"
   * when the renderer runs no vtkshadow pass.
   */
  std::string GetStatsJSON(vtkRenderer* renderer) const;

  /**
   * True when Name is one of the techniques this build provides.
   */
  bool IsValid() const;
  static bool IsKnownTechnique(const char* name);

  /**
   * The techniques this build provides, separated by spaces
   * (vtkShadowTechniqueRegistry::GetNames()).
   */
  static const char* GetKnownTechniques();

  /**
   * A new pass for the technique with the settings applied (caller owns it),
   * or nullptr with an error for an unknown name or a setting the technique
   * does not take.
   */
  vtkShadowPassBase* CreatePass();

  /**
   * Set the technique's pipeline on an OpenGL renderer, composed with the
   * passes it already has: image passes (vtkSSAOPass, vtkToneMappingPass,
   * vtkOpenGLFXAAPass, ...) stay on top with the shadows drawn under them,
   * a vtkRenderStepsPass (or a vtkCameraPass over VTK's standard steps)
   * becomes the scene the shadows are drawn through, an earlier technique
   * and VTK's own shadow passes are replaced; the renderer's UseFXAA and
   * UseDepthPeeling keep working. Returns false, changing nothing, for an
   * unknown technique, a renderer that is not a vtkOpenGLRenderer, or a
   * pass it cannot compose with (GetPassMessage() names it).
   */
  bool Install(vtkRenderer* renderer);

  /**
   * What the last Install() or Enable() did with the passes the renderer
   * had ("" when it had none), or why it refused them.
   */
  const char* GetPassMessage() const;

  /**
   * Bytes of shadow-map memory the technique uses for the lights of
   * `renderer` (0 for "none").
   */
  long long GetShadowMapMemory(vtkRenderer* renderer) const;

  /**
   * Shadows on an ordinary VTK scene: Install(), and the renderer keeps
   * the default lights when AutoKeyLight is on (vtkShadowDefaultLights.h):
   * at each frame in which its own lights are none or only headlights
   * (VTK's automatic headlight), vtkLightKit's key light is added, and
   * removed again when the application adds lights of its own; each change
   * is said once (a warning; GetLightMessage() says what is done now).
   * AutoKeyLight off removes key lights an earlier Enable() added. Nothing
   * happens to the lights before the first frame. Returns false, changing
   * nothing, for an unknown technique, a setting it does not take, or a
   * renderer that is not a vtkOpenGLRenderer.
   */
  bool Enable(vtkRenderer* renderer);

#ifndef __VTK_WRAP__
  /**
   * The one C++ call: a technique by name (default "auto") enabled on the
   * renderer (Enable), or nullptr with an error.
   */
  static vtkSmartPointer<vtkShadowTechnique> EnableShadows(
    vtkRenderer* renderer, const char* technique = "auto");
#endif

  /**
   * Whether Enable() has the renderer keep a key light while it has no
   * lights of its own (default on).
   */
  vtkSetMacro(AutoKeyLight, bool);
  vtkGetMacro(AutoKeyLight, bool);
  vtkBooleanMacro(AutoKeyLight, bool);

  /**
   * The key light kept on the renderer the technique was last set on (owned
   * by the renderer; added at a frame, see Enable()), nullptr when there is
   * none, and what is done to its lights now ("" when nothing).
   */
  vtkLight* GetAddedKeyLight() const;
  const char* GetLightMessage() const;

  /**
   * The actors the installed pass detected as plane receivers in its last
   * frame on the renderer it was installed on (because none was marked with
   * vtkShadowPassBase::RECEIVER()).
   */
  int GetNumberOfDetectedReceivers() const;
  vtkActor* GetDetectedReceiver(int index) const;

  /**
   * The renderer Install() or Enable() last set the technique on.
   */
  vtkRenderer* GetRenderer() const;

protected:
  vtkShadowTechnique();
  ~vtkShadowTechnique() override;

  char* Name;
  int MapResolution;
  std::vector<std::pair<std::string, double>> Options; // in the order set
  bool AutoKeyLight;
  mutable std::string LightMessage; // GetLightMessage's storage
  vtkWeakPointer<vtkRenderer> Renderer;

  // Compose `pass` with the OpenGL renderer's passes
  // (vtkShadowPassComposition.h), freeing the one it replaces; false, with
  // an error and nothing changed, when it cannot.
  bool SetPass(vtkRenderer* renderer, vtkShadowPassBase* pass);
  std::string PassMessage; // GetPassMessage's storage

private:
  vtkShadowTechnique(const vtkShadowTechnique&) = delete;
  void operator=(const vtkShadowTechnique&) = delete;
};

#endif
