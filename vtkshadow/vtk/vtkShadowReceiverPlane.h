// vtkShadowReceiverPlane.h - the plane of a flat receiver actor, and the one
// cache of those planes the planar and auto passes share.
#ifndef vtkShadowReceiverPlane_h
#define vtkShadowReceiverPlane_h

#include "vtkType.h" // for vtkMTimeType

#include <array>   // for std::array
#include <cstddef> // for size_t
#include <map>     // for std::map
#include <vector>  // for std::vector

class vtkActor;
class vtkInformationIntegerKey;

namespace vtkshadow
{
struct ShadowActor;

/**
 * The plane (N, d with N . x + d = 0, N unit) of an actor's polydata in world
 * coordinates (`matrix`, data -> world, row major: the matrix the actor is
 * drawn with, vtkshadow::ShadowActor), or false when the geometry is empty or
 * not flat within 1e-6 of its size (plus the rounding of float points far
 * from the origin: vsh_plane_fit_stored_points). `surface` (may be null) is
 * set to whether the polydata has polygons or strips: only surfaces are
 * detected as receivers (a flat set of lines or points receives nothing
 * visible).
 */
bool ReceiverPlane(
  vtkActor* actor, const double matrix[16], double plane[4], bool* surface = nullptr);

/**
 * The flat parts of an actor's surface in world coordinates (vsh_flat_parts:
 * planes holding at least 5 % of its area, at most 6, the largest first:
 * a box's faces, a slab floor's top), each with the distance within which
 * a point counts as lying on it (its mesh's rounding). Empty for a mesh
 * without polygons or with more than 4 million triangles.
 */
struct FlatPart
{
  std::array<double, 4> Plane;
  double Area;
  double OnPlane; // world distance: points closer than this lie on the part
};
std::vector<FlatPart> FlatParts(vtkActor* actor, const double matrix[16]);

/**
 * Receiver planes by actor (and instance: the same actor drawn at two
 * places), recomputed only when the actor's placement (its matrix's values)
 * or its mesh (MeshTime: mapper or input) changed; not on MTimes of the
 * actor or its matrix, which VTK bumps every frame (its pass machinery, and
 * the matrices an assembly pokes into its parts while drawing).
 * vtkAutoShadowPass reads the cache of its planar pass, so a plane is
 * computed once per change for both.
 */
class ReceiverPlaneCache
{
public:
  struct Entry
  {
    vtkMTimeType Time = 0;            // mesh time it was computed for
    double Matrix[16] = {};           // placement it was computed for
    bool Flat = false;                // the geometry is a plane ...
    double Plane[4] = { 0, 0, 0, 0 }; // ... this one
    bool Reported = false;            // a "not flat" warning was given for this computation
    bool Surface = false;             // it has polygons or strips (detection needs them)
    bool PartsDone = false;           // Parts computed for this Time and Matrix
    std::vector<FlatPart> Parts;      // its flat parts when it is not flat
  };

  /**
   * The shadow actor's entry, brought up to date.
   */
  Entry& Get(const ShadowActor& actor);

  /**
   * The flat parts of the shadow actor's surface (FlatParts), computed
   * once per change like its plane; none for an actor that is flat as a
   * whole (it is a receiver itself) or has no surface.
   */
  const std::vector<FlatPart>& GetParts(const ShadowActor& actor);

  /**
   * Forget every entry (e.g. when graphics resources are released).
   */
  void Clear() { this->Entries.clear(); }

  size_t GetNumberOfEntries() const { return this->Entries.size(); }

private:
  std::map<std::pair<vtkActor*, int>, Entry> Entries;
};

/**
 * The frame's plane receivers among `actors` (visible opaque ones), and
 * whether they were detected rather than marked.
 *
 * Marked: actors with RECEIVER() = 1 (key `receiverKey`, on the actor or,
 * when the actor does not carry it, on the assembly it is drawn by) or in
 * `added`
 * (vtkPlanarShadowPass::AddReceiverActor). When any actor is marked, only
 * marked actors receive: explicit marks override detection. When none is
 * and `detect` is on, every flat surface actor (ReceiverPlane, through the
 * cache) is a receiver: floors, cut planes, slices drawn as polydata, unless
 * it opts out with RECEIVER() = 0 (so scene files, which mark every object,
 * are never second-guessed).
 */
struct ReceiverChoice
{
  std::vector<ShadowActor> Receivers;
  bool Detected = false;
};
ReceiverChoice ChooseReceivers(const std::vector<ShadowActor>& actors,
  const std::vector<vtkActor*>& added, vtkInformationIntegerKey* receiverKey, bool detect,
  ReceiverPlaneCache& cache);
}

#endif
