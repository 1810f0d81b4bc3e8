// vtkShadowVolumeSides - a shadow volume's side triangles drawn with their
// depth bias as a clamped polygon offset instead of a depth written by the
// fragment shader (docs/shadow-volumes.md, "Self-shadowing and the depth
// bias"). The offset is the same bias, but without a shader-written depth
// the rasterizer tests depth and stencil before shading, which is most of
// the volumes' fill on llvmpipe.
#ifndef vtkShadowVolumeSides_h
#define vtkShadowVolumeSides_h

class vtkOpenGLRenderWindow;
class vtkShaderProgram;

class vtkShadowVolumeSides
{
public:
  /**
   * The sides' program (glsl/vtkShadowVolumeSidesFS.glsl with `biased`'s
   * vertex shader) where `enabled`, the context has polygon offset clamp
   * (GL_EXT_polygon_offset_clamp) and the program reads its vertices from the
   * attribute location `biased` does, so that one vertex array serves both;
   * nullptr otherwise (Program()), and the caller draws the sides with
   * `biased`. Leaves `biased` bound.
   */
  void Ready(vtkOpenGLRenderWindow* window, vtkShaderProgram* biased, bool enabled);

  /**
   * Draws vertices [first, first + count) of the bound vertex array as the
   * sides of a volume: entering (front) faces moved away from the camera by
   * depthBias x 2^-24 + min(slopeBias x slope, 2^-12), leaving (back) faces
   * towards it by as much, slope the larger of the window depth's
   * derivatives per pixel (vtkShadowVolumeFS's terms without the caps').
   * Two draws, each culling the other faces, or with `leavingOnly` the
   * leaving faces' draw alone; the stencil operations are the caller's.
   * `volumeMCDC` is the volume's model-to-clip matrix (transposed, as the
   * biased program takes it). Leaves the sides' program bound, face culling
   * off, polygon offset off.
   */
  void Draw(vtkOpenGLRenderWindow* window, const float volumeMCDC[16], int first, int count,
    double depthBias, double slopeBias, bool leavingOnly = false);

  vtkShaderProgram* Program() const { return this->Sides; }

private:
  vtkShaderProgram* Sides = nullptr;
};

#endif
