// vtkShadowFrame.h - one frame's inputs as plain data: the viewport, the
// camera in double, the switched-on lights and the shadow actors. The pass
// base gathers it once per Render (vtkShadowPassBase::BeginFrame) and every
// stage of the pass reads it; vtkAutoShadowPass hands its frame to the
// passes it chains, so a frame updates and lists the lights once whatever
// the number of techniques drawing it.
#ifndef vtkShadowFrame_h
#define vtkShadowFrame_h

#include "vtkShadowActorFlags.h" // for ShadowActor

#include <vector>

class vtkLight;
class vtkRenderState;
class vtkRenderer;

namespace vtkshadow
{
/**
 * A switched-on light, at its index in the mappers' numbering.
 */
struct ShadowFrameLight
{
  vtkLight* Light = nullptr;
  // Whether it casts in the pass reading the frame
  // (vtkShadowPassBase::LightCasts: SkippedLights and the headlight rule);
  // each pass sets its own, so a frame handed on keeps the giver's apart.
  bool Casts = false;
  bool Positional = false;
  bool Headlight = false;
  // (position, 1) or (direction towards the light, 0), world coordinates.
  double Homogeneous[4] = { 0, 0, 0, 0 };
  double Position[3] = { 0, 0, 0 };   // transformed (world)
  double FocalPoint[3] = { 0, 0, 0 }; // transformed (world)
  double ConeAngle = 0.0;             // degrees
  // The light's size keys (vtkShadowPassBase::GetLightRadius /
  // GetLightAngle), and the one its kind uses: the radius of a positional
  // light, the angular diameter (degrees) of a directional one.
  double Radius = 0.0;
  double Angle = 0.0;
  double Size = 0.0;
};

/**
 * The frame. Matrices are row major, as vtkMatrix4x4 holds them.
 */
struct ShadowFrame
{
  vtkRenderer* Renderer = nullptr;
  // The render state it was gathered for: a frame handed to a pass is only
  // taken for this same state.
  const vtkRenderState* State = nullptr;
  // The renderer's viewport in the render target
  // (vtkShadowPassBase::GetViewport), and its aspect (of at least a pixel
  // each way: an empty viewport still gives a finite projection).
  int Size[2] = { 0, 0 };
  int Origin[2] = { 0, 0 };
  double Aspect = 1.0;
  // The active camera.
  double Eye[3] = { 0, 0, 0 };
  double FocalPoint[3] = { 0, 0, 0 };
  double ViewUp[3] = { 0, 0, 1 };
  double ViewAngle = 30.0;
  double ClippingRange[2] = { 0, 1 };
  double View[16];           // world -> view
  double ViewRotation[16];   // View without its translation: eye-relative world -> view
  double Projection[16];     // view -> clip at Aspect, depth -1..1
  double CameraRelative[16]; // Projection x ViewRotation: eye-relative world -> clip
  std::vector<ShadowFrameLight> Lights;
  // Shadow actors (ShadowActors): Drawn from the render state (frustum
  // culled: what the frame draws, the receivers), Actors from the renderer's
  // props (casters: one behind the camera still shadows the view). Only
  // gathered when HasActors; so is Translucent (TranslucentShadowActors:
  // the translucent actors every technique casts and lets receive).
  bool HasActors = false;
  std::vector<ShadowActor> Drawn;
  std::vector<ShadowActor> Actors;
  std::vector<ShadowActor> Translucent;
  // Whether the renderer shows a vtkVolume (HasVisibleVolumes): only
  // raytrace casts it, the others say so per light.
  bool ShowsVolumes = false;
};

/**
 * Gather `frame` for render state `s`: the lights brought up to date first
 * (UpdateLights: lights that follow the camera are otherwise placed by VTK's
 * lights pass inside the delegate, after the shadow work, and their shadows
 * would lag a frame), then viewport, camera and lights, and the actors when
 * `actors` is true. Every light's Casts is left false: the pass decides.
 */
void GatherShadowFrame(const vtkRenderState* s, bool actors, ShadowFrame& frame);

/**
 * The actors of `frame` (GatherShadowFrame's, or gathered now when it left
 * them out).
 */
void GatherShadowFrameActors(const vtkRenderState* s, ShadowFrame& frame);

/**
 * The frame's camera as a homogeneous point, as lights are given (world):
 * (eye, 1), or (towards the camera, 0) for a parallel projection.
 */
void EyeHomogeneous(const ShadowFrame& frame, double out[4]);
}

#endif
