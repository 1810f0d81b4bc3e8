// vtkShadowDepthSeed.h - the main pass's depth buffer filled before its
// opaque geometry from a depth pre-pass of the same view, where that pays.
//
// The screen-space techniques (volume, raytrace, csm's screen resolve) draw
// the opaque scene's depth into their mask (vtkShadowScreenMask::RenderDepth)
// and then the whole scene again, lit, into a depth buffer the camera pass
// has just cleared: a fragment drawn before the surface in front of it is
// shaded and then overwritten. With the pre-pass's depth written first, the
// depth test rejects those fragments before shading (llvmpipe and GPUs test
// depth early for shaders that neither write depth nor discard), and the
// image is the same: the visible fragment's depth is the pre-pass's (same
// mappers, same vertex shaders), and the seed is one 24-bit step deeper
// than the stored depth, so that fragment passes LEQUAL; fragments that
// pass in either case are drawn in the same order, so the same one is kept.
//
// The seed is a full-viewport draw of its own, so it pays only with enough
// such fragments (vsh_depth_seed.h): every VSH_DEPTH_SEED_MEASURE_EVERY
// frames the opaque step's fragments are counted one frame without the seed
// and one with it, and the frames in between follow vsh_depth_seed_pays.
#ifndef vtkShadowDepthSeed_h
#define vtkShadowDepthSeed_h

#include "vtkShadowClipSpaceQuad.h"

class vtkOpenGLRenderWindow;
class vtkTextureObject;

class vtkShadowDepthSeed
{
public:
  vtkShadowDepthSeed() = default;

  /**
   * Around the opaque step, with the bound framebuffer and viewport of the
   * main pass. `depth` is this frame's pre-pass depth (window depth in
   * [0,1], the viewport's size, nearest filtering), or null for none.
   * BeginOpaque writes it plus one step where the schedule says so, and on
   * the measuring frames starts the count of the step's fragments. Nothing
   * is seeded or counted when the framebuffer is multisampled (one depth a
   * pixel would drop an edge's samples that lie behind the pixel centre's
   * depth), the viewport is not the texture's size, or the stencil test is
   * on (the caller limits the scene to some pixels).
   */
  void BeginOpaque(vtkOpenGLRenderWindow* window, vtkTextureObject* depth);
  // With `always`, BeginOpaque seeds every frame it can, and measures nothing.
  void SetAlways(bool always) { this->Always = always; }
  void EndOpaque();

  // Whether this frame's opaque step was seeded.
  bool GetSeeded() const { return this->Seeded; }
  // The last measurement's fragments the seed saves per viewport pixel,
  // -1 before the first.
  double GetHiddenPerPixel() const { return this->HiddenPerPixel; }

  void ReleaseGraphicsResources();

private:
  vtkShadowDepthSeed(const vtkShadowDepthSeed&) = delete;
  void operator=(const vtkShadowDepthSeed&) = delete;

  enum class Phase
  {
    MeasureUnseeded,
    MeasureSeeded,
    Decided
  };
  bool Usable(vtkTextureObject* depth, int viewport[4]) const;
  void CollectMeasurement();
  bool Draw(vtkOpenGLRenderWindow* window, vtkTextureObject* depth, const int viewport[4]);

  vtkShadowClipSpaceQuad Quad;
  Phase Next = Phase::MeasureUnseeded;
  unsigned int Query = 0;
  bool Counting = false; // the query runs in this opaque step
  bool Pending = false;  // a count waits to be read, taken in PendingPhase
  Phase PendingPhase = Phase::Decided;
  double UnseededFragments = 0.0;
  double Pixels = 0.0;
  bool Pays = false;
  int FramesDecided = 0;
  bool Seeded = false;
  bool Always = false;
  double HiddenPerPixel = -1.0;
};

#endif
