/**
 * @class   vtkPlanarShadowPass
 * @brief   Exact shadows of every opaque actor on flat receivers.
 *
 * vtkPlanarShadowPass projects the casters onto each receiver plane from each
 * light (the classic "ground shadow" matrix, computed in double precision by
 * vtkshadow's C core, camera-relative) and rasterizes them into a screen-space
 * bit mask, one bit per (receiver, light) pair. While its delegate renders the
 * scene, the receivers' lighting code multiplies each light's diffuse and
 * specular term by that light's bit: a shadow removes exactly its light's
 * contribution and nothing else. The shadow is therefore exact on the
 * receiver, appears only on the receiver's visible fragments (never off its
 * edges), never darkens twice where casters overlap, and cannot z-fight (the
 * mask draw uses no depth test).
 *
 * Receivers: actors marked with RECEIVER() or added with AddReceiverActor()
 * (their flat geometry defines the plane and the area), or explicit planes
 * (AddReceiverPlane()), which receive on every opaque fragment lying on them.
 * Casters: every visible opaque actor except receivers onto themselves and
 * actors marked with NO_CAST(). Lights: every switched-on scene light
 * (directional, point, spot); the headlight only with CastHeadlightShadowsOn().
 * At most 128 (receiver, light) pairs.
 *
 * @code{.py}
 * planar = vtkshadow.vtkPlanarShadowPass()
 * planar.AddReceiverActor(floor_actor)
 * renderer.SetPass(planar)      # delegate defaults to vtkRenderStepsPass
 * @endcode
 */
#ifndef vtkPlanarShadowPass_h
#define vtkPlanarShadowPass_h

#include "vtkOpenGLRenderPass.h"
#include "vtkshadowModule.h" // for export macro

#include <memory> // for std::unique_ptr

class vtkActor;
class vtkInformationIntegerKey;
class vtkProp;
class vtkRenderPass;
class vtkTextureObject;

class VTKSHADOW_EXPORT vtkPlanarShadowPass : public vtkOpenGLRenderPass
{
public:
  static vtkPlanarShadowPass* New();
  vtkTypeMacro(vtkPlanarShadowPass, vtkOpenGLRenderPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Property key: an actor with RECEIVER() = 1 is a receiver.
   */
  static vtkInformationIntegerKey* RECEIVER();

  /**
   * Property key: an actor with NO_CAST() = 1 casts no planar shadow.
   */
  static vtkInformationIntegerKey* NO_CAST();

  /**
   * Receivers given as actors with flat geometry.
   */
  void AddReceiverActor(vtkActor* actor);
  void RemoveReceiverActor(vtkActor* actor);

  /**
   * Receivers given as planes (a point and a normal, world coordinates).
   * Every opaque fragment within the tolerance (relative to its distance from
   * the camera, default 1e-5) of the plane receives the shadow.
   */
  void AddReceiverPlane(double originX, double originY, double originZ, double normalX,
    double normalY, double normalZ);
  void RemoveAllReceivers();
  vtkSetMacro(PlaneTolerance, double);
  vtkGetMacro(PlaneTolerance, double);

  /**
   * Whether the headlight casts shadows too (default off: they hide behind
   * the objects that cast them).
   */
  vtkSetMacro(CastHeadlightShadows, bool);
  vtkGetMacro(CastHeadlightShadows, bool);
  vtkBooleanMacro(CastHeadlightShadows, bool);

  /**
   * Lights this pass leaves unshadowed, as bits: bit i for light i in the
   * mapper's numbering (the renderer's switched-on lights, in order).
   * Default 0, every light casts. vtkAutoShadowPass uses it to give each
   * light its own technique, or none when it casts no visible shadow.
   */
  vtkSetMacro(SkippedLights, unsigned int);
  vtkGetMacro(SkippedLights, unsigned int);

  /**
   * The pass that renders the scene (default: a vtkRenderStepsPass).
   */
  virtual void SetDelegatePass(vtkRenderPass* pass);
  vtkGetObjectMacro(DelegatePass, vtkRenderPass);

  /**
   * Number of (receiver, light) pairs that cast in the last frame, and the
   * number of caster triangles drawn into the mask in it.
   */
  vtkGetMacro(NumberOfShadowPairs, int);
  vtkGetMacro(NumberOfMaskTriangles, vtkIdType);

  /**
   * How many times caster geometry was (re)built since creation: stays
   * constant while neither props nor their data change.
   */
  vtkGetMacro(NumberOfGeometryBuilds, int);

  /**
   * Bytes of GPU memory the pass holds (mask texture and caster copies).
   */
  vtkIdType GetMemoryBytes() const;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  bool PreReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool PostReplaceShaderValues(std::string& vertexShader, std::string& geometryShader,
    std::string& fragmentShader, vtkAbstractMapper* mapper, vtkProp* prop) override;
  bool SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
    vtkOpenGLVertexArrayObject* VAO = nullptr) override;
  vtkMTimeType GetShaderStageMTime() override;

protected:
  vtkPlanarShadowPass();
  ~vtkPlanarShadowPass() override;

  vtkRenderPass* DelegatePass;
  double PlaneTolerance;
  bool CastHeadlightShadows;
  unsigned int SkippedLights;
  int NumberOfShadowPairs;
  vtkIdType NumberOfMaskTriangles;
  int NumberOfGeometryBuilds;

private:
  vtkPlanarShadowPass(const vtkPlanarShadowPass&) = delete;
  void operator=(const vtkPlanarShadowPass&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Impl;
};

#endif
