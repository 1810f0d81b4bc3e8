// vtkShadowReceiverPlane.h - the plane of a flat receiver actor.
#ifndef vtkShadowReceiverPlane_h
#define vtkShadowReceiverPlane_h

class vtkActor;

namespace vtkshadow
{
/**
 * The plane (N, d with N . x + d = 0, N unit) of an actor's polydata in world
 * coordinates (actor matrix applied), or false when the geometry is empty or
 * not flat within 1e-6 of its size.
 */
bool ReceiverPlane(vtkActor* actor, double plane[4]);
}

#endif
