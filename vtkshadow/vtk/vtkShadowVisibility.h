/**
 * @class   vtkShadowVisibility
 * @brief   Per-light visibility of a scene under a shadow technique.
 *
 * Visibility v in [0,1] is the fraction of light K that reaches the surface
 * seen at a pixel (1 lit, 0 fully shadowed). It is measured the same way for
 * every technique and every renderer (docs/metrics.md): only light K, white
 * Lambertian surfaces, no ambient, no specular, rendered once with the
 * technique and once without shadows into 32-bit float buffers
 * (vtkFramebufferPass), v = I_on / I_off. Pixels where I_off <= Epsilon
 * (background, surfaces facing away from the light or outside its cone) are
 * outside the mask and get v = 0.
 *
 * Images are vtkImageData with VTK's row order (row 0 at the bottom); PNG
 * files written from them have row 0 at the top.
 */
#ifndef vtkShadowVisibility_h
#define vtkShadowVisibility_h

#include "vtkObject.h"
#include "vtkshadowModule.h" // for export macro

class vtkImageData;
class vtkShadowScene;
class vtkShadowTechnique;

class VTKSHADOW_EXPORT vtkShadowVisibility : public vtkObject
{
public:
  static vtkShadowVisibility* New();
  vtkTypeMacro(vtkShadowVisibility, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The scene and the technique to measure.
   */
  virtual void SetScene(vtkShadowScene*);
  vtkGetObjectMacro(Scene, vtkShadowScene);
  virtual void SetTechnique(vtkShadowTechnique*);
  vtkGetObjectMacro(Technique, vtkShadowTechnique);

  /**
   * The light to measure (default 0).
   */
  vtkSetMacro(Light, int);
  vtkGetMacro(Light, int);

  /**
   * Image size; 0 means the scene's size (default 0 x 0).
   */
  vtkSetVector2Macro(Size, int);
  vtkGetVector2Macro(Size, int);

  /**
   * Threshold on the unshadowed intensity below which a pixel is not valid
   * (default 1e-3 of the light's full intensity).
   */
  vtkSetMacro(Epsilon, double);
  vtkGetMacro(Epsilon, double);

  /**
   * Render both images and compute visibility. Returns false (with an error
   * message) when the scene, technique or light is invalid.
   */
  bool Compute();
  const char* GetErrorMessage() const { return this->ErrorMessage; }

  /**
   * Results of the last Compute(): visibility (float, 1 component), the
   * unshadowed intensity I_off (float), the shadowed intensity I_on (float)
   * and the mask (unsigned char, 255 valid, 0 not).
   */
  vtkImageData* GetVisibility();
  vtkImageData* GetUnshadowed();
  vtkImageData* GetShadowed();
  vtkImageData* GetMask();

  /**
   * Visibility as 16-bit grayscale (65535 lit, 0 blocked) for PNG output.
   */
  vtkImageData* GetVisibility16();

  /**
   * The visibility of one colour channel (0 red, 1 green, 2 blue) as 16-bit
   * grayscale: I_on / I_off of that channel alone, over the same mask. A
   * shadow through a coloured filter (docs/translucency.md) differs per
   * channel; GetVisibility16() is that of the summed RGB. nullptr for
   * another channel or before Compute().
   */
  vtkImageData* GetChannelVisibility16(int channel);

protected:
  vtkShadowVisibility();
  ~vtkShadowVisibility() override;

  vtkSetStringMacro(ErrorMessage);
  // Deletes every result image.
  void ReleaseImages();

  vtkShadowScene* Scene;
  vtkShadowTechnique* Technique;
  int Light;
  int Size[2];
  double Epsilon;
  char* ErrorMessage;
  vtkImageData* Visibility;
  vtkImageData* Unshadowed;
  vtkImageData* Shadowed;
  vtkImageData* Mask;
  vtkImageData* Visibility16;
  vtkImageData* ChannelVisibility16[3];

private:
  vtkShadowVisibility(const vtkShadowVisibility&) = delete;
  void operator=(const vtkShadowVisibility&) = delete;
};

#endif
