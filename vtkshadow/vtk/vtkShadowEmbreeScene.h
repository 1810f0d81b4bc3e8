// vtkShadowEmbreeScene.h - the casters of a frame as Embree 3 scenes, for
// ray-traced shadows (vtkRayTracedShadowPass).
//
// One Embree geometry (in its own scene, so it can be instanced) per actor
// mesh, built from the triangles the mapper draws (vtkShadowCasterTriangles),
// with positions relative to the mesh's own centre in float; each actor is an
// instance of its mesh, placed by the matrix it is drawn with (its own, or
// its assembly path's; an actor drawn at two places is two instances), in
// top-level scenes
// whose origin is the centre of the frame's actors, so a scene 1e6 units
// from the origin keeps float precision. A mesh is rebuilt only when its
// mesh data changed (vtkshadow::CasterDataTime, not the actor's time); moving
// an actor re-commits only the top level.
//
// Two top levels share the instances' meshes: "visible" (every opaque actor:
// the primary rays that land on the rasterized surface) and "casters"
// (actors that cast: the shadow rays), where translucent actors (Opacity
// below 1) are casters too, and only there: GetCasterOpacity gives each
// caster instance's opacity by its instance id, for the tracer's context
// filter (vtkShadowRayTracer: a ray's transmittance is the product of
// (1 - opacity) over the translucent surfaces it crosses).
//
// Points drawn as spheres and lines drawn as tubes (RenderPointsAsSpheres,
// RenderLinesAsTubes: vtkShadowImpostors) are Embree spheres (RTC_GEOMETRY_TYPE_SPHERE_POINT) and
// round linear curves (RTC_GEOMETRY_TYPE_ROUND_LINEAR_CURVE: cones between spheres) whose radius is
// half their pixel width at their depth (vsh_rt_impostor_radius): the solid VTK's impostor shows
// from the camera. vtkPointGaussianMapper's splats are spheres of their world radius; plain
// points and lines wider than a pixel are the flat squares and bands VTK draws
// (RTC_GEOMETRY_TYPE_QUAD, facing the camera). Pixel sizes depend on the camera, so these are
// not instanced meshes but one scene per actor placement in the top levels' frame, rebuilt with
// the top levels whenever the camera or the viewport changes.
#ifndef vtkShadowEmbreeScene_h
#define vtkShadowEmbreeScene_h

#include "vtkType.h"

#include <embree3/rtcore.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

class vtkActor;
namespace vtkshadow
{
struct Impostors;
}

class vtkShadowEmbreeScene
{
public:
  struct Actor
  {
    vtkActor* Prop;
    bool Casts;
    double Matrix[16]; // data -> world, row major: where it is drawn (vtkshadow::ShadowActor)
    // Below 1: a translucent caster (in "casters" only, never "visible").
    double Opacity = 1.0;
    // A translucent caster's crossing, per colour channel
    // (vtkshadow::CasterTransmit); grey (1 - Opacity) unless a filter tints it.
    double Transmit[3] = { 0.0, 0.0, 0.0 };
    bool Tinted = false;
    // Whether its spheres and tubes (vtkShadowImpostors) cast: not NO_CAST.
    // They are in "visible" either way (when opaque), as they are drawn.
    bool CastsImpostors = false;
  };

  // The camera the impostors are sized for (vsh_rt_impostor_radius).
  struct Camera
  {
    double Projection[16]; // eye -> clip, row major
    double View[16];       // world -> eye, row major
    int Width;             // the viewport in pixels
  };

  // Per instance of the "visible" top level (its instance id).
  struct Instance
  {
    double Normal[9];     // inverse transpose of the instance's 3x3: object -> world normals
    double Radius;        // the mesh's radius in world units (for the offset rule)
    double Transform[12]; // stored positions -> relative to the centre, in double (row major 3x4)
    const std::vector<float>* Vertices;       // the mesh's stored positions (x, y, z)
    const std::vector<unsigned int>* Indices; // three per triangle (Embree's primID)
    // An actor's spheres and tubes (Embree spheres and round curves, no triangles:
    // GetTriangle fails), in the top levels' frame with an identity
    // placement: its own scene, for the tracer to land a pixel on it again
    // from in front (vtkShadowRayTracer: VTK's impostor depth is only near
    // the sphere's), within Slack (the largest radius) of the depth point.
    RTCScene Impostors = nullptr;
    double Slack = 0;
  };

  /**
   * Triangle `primitive` of instance `id` relative to the centre, in double
   * (the float positions Embree holds, placed by the double matrix): what a
   * pixel's surface point is computed on, so a grazing far surface keeps
   * the precision the float ray would lose. False for a bad id.
   */
  bool GetTriangle(unsigned int id, unsigned int primitive, double v[3][3]) const;

  /**
   * Every triangle of the top levels relative to the centre, in double (9
   * per triangle, as GetTriangle gives them), with its part in the
   * shadows (vsh_rt_classify.h flags: an opaque caster, a translucent
   * caster, or only drawn) and the index of the placement it belongs to:
   * what the classifier's light-space maps rasterize. Spheres, tubes and
   * flat quads have no triangles: HasImpostors says when some are left out.
   */
  void CollectTriangles(std::vector<double>& triangles, std::vector<unsigned char>& flags,
    std::vector<int>& placements) const;
  bool HasImpostors() const { return this->ImpostorParts > 0; }
  // The largest Instance::Slack of the visible top level's impostors (0
  // without any): how far in front of a depth point on one of them the
  // front-most solid's surface can be.
  double GetLargestImpostorSlack() const { return this->ImpostorSlack; }
  // Every sphere, tube segment and flat quad of the top levels as a
  // capsule, the hull of two balls (8 doubles: a[3], ra, b[3], rb),
  // relative to the centre and covering Embree's float copy: what the
  // classifier's occluders are built from (vsh_rt_classify.h).
  const std::vector<double>& GetImpostorCapsules() const { return this->ImpostorCapsules; }
  // Changes of where things are in the world (actors, meshes, matrices,
  // who casts), not counting the camera's changes of impostor radii nor
  // moves of the top levels' origin: impostor-free parts stay where they
  // were between two equal counts.
  int GetWorldCommits() const { return this->WorldCommits; }
  // The largest Instance::Radius (the tracer's offset grows with it).
  double GetLargestRadius() const;

  vtkShadowEmbreeScene();
  ~vtkShadowEmbreeScene();
  vtkShadowEmbreeScene(const vtkShadowEmbreeScene&) = delete;
  void operator=(const vtkShadowEmbreeScene&) = delete;

  /**
   * Bring the scenes up to date with the frame's opaque actors, seen from
   * `eye` (world) with nothing visible nearer than `nearDistance` (the near
   * clipping plane). False (with GetError()) when Embree fails; actors
   * without triangles are left out. The top levels are re-committed when an
   * actor moves, a mesh changes, or the eye is further than nearDistance
   * from their origin (which then moves to the eye), and, when an actor
   * draws points or lines, when `camera` changes (their radii).
   */
  bool Update(const std::vector<Actor>& actors, const double eye[3], double nearDistance,
    const Camera& camera);

  RTCScene GetVisible() const { return this->Visible; }
  RTCScene GetCasters() const { return this->Casters; }
  // World coordinates of the top levels' origin.
  const double* GetCentre() const { return this->Centre; }
  const Instance& GetInstance(unsigned int id) const { return this->Instances[id]; }
  bool IsEmpty() const { return this->Instances.empty(); }
  // The opacity of each instance of the "casters" top level, by instance id
  // (1 for an opaque caster), and whether any is below 1.
  const std::vector<float>& GetCasterOpacity() const { return this->CasterOpacity; }
  bool HasTranslucentCasters() const { return this->TranslucentCasters; }
  // What one crossing of each instance lets through per colour channel, 3
  // per instance id (0 for an opaque caster), and whether any is tinted.
  const std::vector<float>& GetCasterTransmit() const { return this->CasterTransmit; }
  bool HasTintedCasters() const { return this->TintedCasters; }

  // Counters since creation.
  int GetMeshBuilds() const { return this->MeshBuilds; }
  double GetMeshBuildSeconds() const { return this->MeshBuildSeconds; }
  int GetTopLevelCommits() const { return this->TopCommits; }
  double GetTopLevelSeconds() const { return this->TopSeconds; }
  // The current scene.
  int GetNumberOfMeshes() const { return static_cast<int>(this->Meshes.size()); }
  long long GetNumberOfTriangles() const;
  // Spheres and curve segments in the top levels (every placement counted).
  long long GetNumberOfImpostors() const { return this->ImpostorCount; }
  const std::string& GetError() const { return this->Error; }

private:
  struct Mesh;
  Mesh* UpdateMesh(vtkActor* actor);
  bool BuildTopLevel(const std::vector<Actor>& actors, const double eye[3], const Camera& camera);
  void AddMeshInstance(const Actor& a, const Mesh& mesh);
  void AddImpostors(const Actor& a, const Mesh& mesh, const Camera& camera);
  // The parts of AddImpostors: each adds its geometry to `scene` and returns
  // its largest radius (AddFlatQuads: its quads).
  double AddSpheres(
    RTCScene scene, const Actor& a, const vtkshadow::Impostors& drawn, const Camera& camera);
  double AddTubes(
    RTCScene scene, const Actor& a, const vtkshadow::Impostors& drawn, const Camera& camera);
  size_t AddFlatQuads(
    RTCScene scene, const Actor& a, const vtkshadow::Impostors& drawn, const Camera& camera);
  void Attach(const Actor& a, bool casts, RTCScene scene, const float transform[12],
    const Instance& instance);
  // Also notes how much of it is the world's part (WorldKeySize).
  std::vector<double> PlacementKey(const std::vector<Actor>& actors, const Camera& camera);
  // Appends the capsule of balls a and b (x, y, z, radius in float,
  // relative to the centre) to ImpostorCapsules.
  void AddCapsule(const float a[4], const float b[4]);

  RTCDevice Device = nullptr;
  RTCScene Visible = nullptr;
  RTCScene Casters = nullptr;
  std::map<vtkActor*, std::unique_ptr<Mesh>> Meshes;
  std::vector<Instance> Instances;
  // Every placement attached to a top level (translucent ones too, which
  // are not in Instances), with its part in the shadows.
  struct Part
  {
    Instance Placed;
    bool Casts;
    bool Translucent;
  };
  std::vector<Part> Parts;
  int ImpostorParts = 0;
  double ImpostorSlack = 0;
  std::vector<double> ImpostorCapsules;
  std::vector<double> World; // the placement key without the camera
  size_t WorldKeySize = 0;
  int WorldCommits = 0;
  std::vector<RTCScene> ImpostorScenes; // this top level's, released with it
  long long ImpostorCount = 0;
  std::vector<float> CasterOpacity;
  std::vector<float> CasterTransmit;
  bool TranslucentCasters = false;
  bool TintedCasters = false;
  std::vector<double> Placement;
  double Centre[3] = { 0, 0, 0 };
  int MeshBuilds = 0;
  double MeshBuildSeconds = 0;
  int TopCommits = 0;
  double TopSeconds = 0;
  std::string Error;
};

#endif
