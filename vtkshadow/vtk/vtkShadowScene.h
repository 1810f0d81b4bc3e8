/**
 * @class   vtkShadowScene
 * @brief   A vtkshadow scene file loaded into VTK data: triangles, lights, camera.
 *
 * vtkShadowScene reads a scene file (docs/scene-format.md) through the C
 * scene library, tessellates its primitives with vtkshadow's own code and
 * reads its meshes with VTK's readers (PLY, OBJ, STL, VTP), so that every
 * renderer (VTK, POV-Ray, Cycles) receives exactly the same triangles.
 * Every field is validated; on failure Load() returns false and
 * GetErrorMessage() names the file, the field and the value.
 *
 * @code{.py}
 * scene = vtkshadow.vtkShadowScene()
 * if not scene.Load("scenes/basic/sphere-plane.json"):
 *     raise SystemExit(scene.GetErrorMessage())
 * scene.Populate(renderer)
 * @endcode
 */
#ifndef vtkShadowScene_h
#define vtkShadowScene_h

#include "vtkObject.h"
#include "vtkWrappingHints.h" // for VTK_WRAPEXCLUDE
#include "vtkshadowModule.h"  // for export macro

#include <memory> // for std::unique_ptr

class vtkActor;
class vtkCamera;
class vtkLight;
class vtkPolyData;
class vtkRenderer;
struct vsh_scene; // vsh_scene.h, the C scene library

class VTKSHADOW_EXPORT vtkShadowScene : public vtkObject
{
public:
  static vtkShadowScene* New();
  vtkTypeMacro(vtkShadowScene, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Load and validate a scene file. Returns false, keeps no partial scene and
   * sets the error message on any problem.
   */
  bool Load(const char* path);

  /**
   * Load a scene the C scene library has parsed already (vsh_scene_load or
   * vsh_scene_parse), so that a caller reading the scene's fields itself
   * parses the file once: meshes are read and primitives tessellated as in
   * Load(). Takes ownership of `scene` (freed on failure too); `path` is the
   * file it came from, for GetFileName() and messages. Load(path) is
   * vsh_scene_load followed by this. C++ only.
   */
  VTK_WRAPEXCLUDE bool LoadParsed(vsh_scene* scene, const char* path);

  /**
   * The parsed scene (vsh_scene.h) after a successful Load or LoadParsed,
   * owned by this object; nullptr otherwise. C++ only.
   */
  VTK_WRAPEXCLUDE const vsh_scene* GetParsedScene() const;

  /**
   * The last error ("FILE: FIELD: problem (got VALUE)"), or an empty string.
   */
  const char* GetErrorMessage() const;

  /**
   * The scene file that was loaded, or an empty string.
   */
  const char* GetFileName() const;

  /**
   * The image size the scene asks for ("size").
   */
  int GetWidth() const;
  int GetHeight() const;

  int GetNumberOfLights() const;
  int GetNumberOfObjects() const;

  /**
   * "directional", "point" or "spot".
   */
  const char* GetLightTypeName(int light) const;

  ///@{
  /**
   * The size of scene light `light`: the disk radius of a point or spot
   * light (world units) and the angular diameter of a directional light
   * (degrees); 0 for a hard light, the other kind's field, or an index out
   * of range. NewLight() stores them on the vtkLight too
   * (vtkShadowPassBase::LIGHT_RADIUS / LIGHT_ANGLE), where passes read them.
   */
  double GetLightRadius(int light) const;
  double GetLightAngle(int light) const;
  ///@}

  /**
   * A new vtkLight configured as scene light `light` (caller owns it).
   * Directional lights are non-positional scene lights; point lights are
   * positional with a 180 degree cone; spot lights have a uniform (exponent 0)
   * cone of the scene's half-angle. No distance attenuation. The light's
   * size goes into its information (vtkShadowPassBase::SetLightSize).
   */
  vtkLight* NewLight(int light) const;

  /**
   * Triangles of object `object` in world coordinates (double points, point
   * normals). The transform is already applied. For "points" and
   * "polyline" objects: the solid VTK's impostors show (spheres, a tube),
   * which the ray tracers draw; Populate() gives VTK the points and the
   * line themselves, drawn as spheres and tubes. A "volume" has no
   * triangles (Populate() adds a vtkVolume).
   */
  vtkPolyData* GetObjectPolyData(int object) const;
  bool GetObjectIsReceiver(int object) const;
  bool GetObjectCasts(int object) const;
  void GetObjectColor(int object, double color[3]) const;

  /**
   * The object's "opacity" (1 opaque) and "filter" (0 grey) of the scene
   * format: each crossing of a ray to a light lets (1 - opacity) through,
   * the filter fraction of it tinted by the colour (docs/translucency.md).
   * Populate() gives the actor the opacity.
   */
  double GetObjectOpacity(int object) const;
  double GetObjectFilter(int object) const;
  const char* GetObjectKindName(int object) const;

  /**
   * World bounds of all objects.
   */
  void GetBounds(double bounds[6]) const;

  /**
   * Set position, focal point, view-up and view angle of a camera.
   */
  void ConfigureCamera(vtkCamera* camera) const;

  /**
   * Add one actor per object (colour from the scene, or white Lambertian when
   * `lambertian` is true: diffuse 1, no ambient, no specular; a translucent
   * object is black there, so that what it adds to a pixel is the same
   * (1 - opacity) factor with and without shadows and I_on / I_off is the
   * visibility of the opaque surface behind it), the scene's
   * lights (all, or only `onlyLight` when it is >= 0), and the camera. The
   * renderer's automatic headlight is switched off. Returns false when
   * `onlyLight` is out of range.
   */
  bool Populate(vtkRenderer* renderer, bool lambertian = false, int onlyLight = -1) const;

  /**
   * Populate with the scene's colours as the ray tracers render them:
   * diffuse 1, no ambient, no specular (the reflection comparisons).
   */
  bool PopulateMatte(vtkRenderer* renderer, int onlyLight = -1) const;

  /**
   * Reflectance R of object `object` ("mirror": R), 0 when it is no mirror.
   * Populate() marks mirrors with vtkPlanarReflectionPass::MIRROR().
   */
  double GetObjectMirror(int object) const;
  bool HasMirrors() const;

  /**
   * Set the renderer's camera clipping range from the geometry it sees:
   * near just in front of the nearest visible point of any visible prop,
   * far just behind the farthest. Use it instead of
   * vtkRenderer::ResetCameraClippingRange, which keeps near at least 1/1000
   * of far and so clips close geometry in scenes with a wide depth range.
   * Call it again whenever the camera or the actors move. Populate() calls it.
   */
  static void ResetCameraClippingRange(vtkRenderer* renderer);

protected:
  bool PopulateWith(vtkRenderer* renderer, int mode, int onlyLight) const;
  void AddBlob(vtkRenderer* renderer, int object, bool lambertian) const;

  vtkShadowScene();
  ~vtkShadowScene() override;

private:
  vtkShadowScene(const vtkShadowScene&) = delete;
  void operator=(const vtkShadowScene&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
