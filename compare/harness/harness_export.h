// harness_export.h - the scene as numbers for the ray tracers: POV-Ray scene
// text and the binary data file read by compare/blender/render_cycles.py.
//
// Only numbers from the loaded scene reach these outputs, each formatted by
// this code (%.17g); no string of the scene file (names, descriptions, mesh
// paths) is ever written, so a scene cannot inject POV-Ray directives or
// Python code.
#ifndef VTKSHADOW_HARNESS_EXPORT_H
#define VTKSHADOW_HARNESS_EXPORT_H

#include <cstdint>
#include <string>
#include <vector>

namespace vsh_harness
{

struct ExportObject
{
  std::vector<double> points;  // 3 per point, normalized frame (see ExportScene)
  std::vector<double> normals; // 3 per point, unit
  std::vector<uint32_t> triangles;
  bool casts = true;
  double color[3] = { 1, 1, 1 }; // linear RGB: only the colour renders use it
  double mirror = 0;             // reflectance R of a planar mirror, 0 = none
  double opacity = 1;            // each crossing lets (1 - opacity) through
  double filter = 0;             // of that, the fraction tinted by `color`
};

// A volume-rendered blob (the scene format's "volume"): extinction
// density * max(0, 1 - |p - center| / radius) per unit length, in the
// normalized frame (radius scaled, density divided by the scale). The camera
// does not see it in the visibility renders; shadow rays lose exp(-integral).
struct ExportVolume
{
  double center[3];
  double radius = 1;
  double density = 0;
  bool casts = true;
};

struct ExportLight
{
  int type = 0;       // 0 directional, 1 point, 2 spot
  double position[3]; // normalized frame (point, spot; directional: far away)
  double axis[3];     // unit: direction of travel (directional), cone axis (spot)
  double cone = 0;    // half-angle, degrees
  // The light's size: point and spot, the disk radius in the normalized
  // frame (scene radius * scale); directional, the angular diameter in
  // degrees (not scaled). 0: a hard light.
  double size = 0;
};

// The scene in the renderers' frame: x' = (x - anchor) * scale, with anchor
// the camera position and scale a power of two (so the scaling is exact)
// that brings the camera's focal distance to about 10 units. A similarity
// transform leaves visibility unchanged; it keeps single-precision mesh
// vertices (POV-Ray mesh2, Cycles) and POV-Ray's fixed 1e-3 shadow-ray
// epsilon meaningful for scenes far from the origin or at tiny scales.
struct ExportScene
{
  int width = 0, height = 0;
  double anchor[3] = { 0, 0, 0 };
  double scale = 1;
  double eye[3], focal[3], up[3];
  double view_angle = 30; // vertical, degrees
  double bounds_center[3] = { 0, 0, 0 };
  double bounds_diagonal = 1;
  std::vector<ExportLight> lights;
  std::vector<ExportObject> objects;
  std::vector<ExportVolume> volumes;
  bool has_mirror = false; // some object has mirror > 0: the colour renders run
  // Some object has opacity < 1 and filter > 0: its shadow is tinted, so
  // every renderer also gives the green and blue channels' visibility.
  bool tinted = false;
};

// POV-Ray 3.7 scene. Light K and shadows on/off are chosen on the command
// line: Declare=VSH_LIGHT=K Declare=VSH_SHADOWS=0|1.
// Lights with a size become area lights of grid x grid samples (2^k + 1,
// circular, jittered; docs/harness.md), turned about their axis by an angle
// made from `seed` (POV-Ray's jitter cannot be seeded).
std::string PovScene(const ExportScene& s, int grid = 17, int seed = 0);

// True when some light has a size (the scene has soft shadows).
bool HasSoftLight(const ExportScene& s);

// Binary data file for render_cycles.py (layout documented there). Scenes
// with a soft light get `soft_samples` samples at the pixel centre when
// `samples` is 1 (the pixel-centre reference), else `samples` over the pixel.
std::string CyclesData(const ExportScene& s, int samples, int soft_samples = 1, int seed = 0);

// POV-Ray 3.7 colour scene of a scene with mirrors (docs/reflections.md):
// every light on, shadows on, objects in their colours with finish
// { ambient 0 diffuse 1-R reflection { R } } (no fresnel, no specular), one
// bounce. Declare=VSH_MIRROR_MASK=1 renders the mask instead: mirrors
// emission 1, everything else black. Lights with a size are area lights as
// in PovScene (grid, seed).
std::string PovColourScene(const ExportScene& s, int grid = 17, int seed = 0);

} // namespace vsh_harness

#endif
