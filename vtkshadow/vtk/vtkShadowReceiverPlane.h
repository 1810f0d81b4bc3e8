// vtkShadowReceiverPlane.h - the plane of a flat receiver actor, and the one
// cache of those planes the planar and auto passes share.
#ifndef vtkShadowReceiverPlane_h
#define vtkShadowReceiverPlane_h

#include "vtkType.h" // for vtkMTimeType

#include <cstddef> // for size_t
#include <map>     // for std::map

class vtkActor;

namespace vtkshadow
{
/**
 * The plane (N, d with N . x + d = 0, N unit) of an actor's polydata in world
 * coordinates (actor matrix applied), or false when the geometry is empty or
 * not flat within 1e-6 of its size.
 */
bool ReceiverPlane(vtkActor* actor, double plane[4]);

/**
 * Receiver planes by actor, recomputed only when the actor's placement (its
 * matrix's MTime) or its mesh (MeshTime: mapper or input) changed; not on
 * the actor's own MTime, which VTK's pass machinery bumps every frame.
 * vtkAutoShadowPass reads the cache of its planar pass, so a plane is
 * computed once per change for both.
 */
class ReceiverPlaneCache
{
public:
  struct Entry
  {
    vtkMTimeType Time = 0;            // placement and mesh time it was computed for
    bool Flat = false;                // the geometry is a plane ...
    double Plane[4] = { 0, 0, 0, 0 }; // ... this one
    bool Reported = false;            // a "not flat" warning was given for this computation
  };

  /**
   * The actor's entry, brought up to date.
   */
  Entry& Get(vtkActor* actor);

  /**
   * Forget every entry (e.g. when graphics resources are released).
   */
  void Clear() { this->Entries.clear(); }

  size_t GetNumberOfEntries() const { return this->Entries.size(); }

private:
  std::map<vtkActor*, Entry> Entries;
};
}

#endif
