#include "vtkShadowVisibility.h"

#include "vtkFloatArray.h"
#include "vtkFramebufferPass.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPointData.h"
#include "vtkRenderPass.h"
#include "vtkRenderWindow.h"
#include "vtkShadowDisplay.h"
#include "vtkShadowScene.h"
#include "vtkShadowTechnique.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkShadowVisibility);
vtkCxxSetObjectMacro(vtkShadowVisibility, Scene, vtkShadowScene);
vtkCxxSetObjectMacro(vtkShadowVisibility, Technique, vtkShadowTechnique);

namespace
{
vtkImageData* NewImage(int w, int h, int type)
{
  vtkImageData* image = vtkImageData::New();
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(type, 1);
  return image;
}

// Render the renderer's window through `pass` wrapped in a float framebuffer
// and return the RGBA of every pixel (row 0 at the bottom). Float targets
// keep the dim, grazing-angle pixels as exact as the bright ones.
bool RenderFloatRGBA(vtkRenderWindow* window, vtkOpenGLRenderer* renderer, vtkRenderPass* pass,
  int w, int h, std::vector<float>& rgba)
{
  vtkNew<vtkFramebufferPass> capture;
  capture->SetColorFormat(vtkTextureObject::Float32);
  capture->SetDepthFormat(vtkTextureObject::Fixed32);
  capture->SetDelegatePass(pass);
  renderer->SetPass(capture);
  window->Render();

  vtkTextureObject* color = capture->GetColorTexture();
  if (!color || !color->GetHandle() || color->GetWidth() != static_cast<unsigned int>(w) ||
    color->GetHeight() != static_cast<unsigned int>(h))
  {
    renderer->SetPass(nullptr);
    return false;
  }
  window->MakeCurrent();
  // Errors left by the passes are theirs (VTK reports them); ours start here.
  while (glGetError() != GL_NO_ERROR)
  {
  }
  rgba.assign(static_cast<size_t>(w) * h * 4, 0.0f);
  color->Activate();
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, rgba.data());
  color->Deactivate();
  const bool ok = glGetError() == GL_NO_ERROR;
  // Release the pass (and its GL resources) while the context is current.
  capture->ReleaseGraphicsResources(window);
  renderer->SetPass(nullptr);
  return ok;
}

// The summed RGB of every pixel of an RGBA image.
std::vector<float> SumRGB(const std::vector<float>& rgba)
{
  std::vector<float> intensity(rgba.size() / 4);
  for (size_t i = 0; i < intensity.size(); ++i)
  {
    intensity[i] = rgba[4 * i] + rgba[4 * i + 1] + rgba[4 * i + 2];
  }
  return intensity;
}

// 16-bit visibility of channel c: on_c / off_c where the mask is valid.
vtkImageData* ChannelImage(const std::vector<float>& on, const std::vector<float>& off,
  const unsigned char* mask, int c, int w, int h)
{
  vtkImageData* image = NewImage(w, h, VTK_UNSIGNED_SHORT);
  auto* out = static_cast<unsigned short*>(image->GetScalarPointer());
  for (size_t i = 0; i < off.size() / 4; ++i)
  {
    const float a = on[4 * i + c], b = off[4 * i + c];
    const float v = mask[i] && b > 0 ? std::min(1.0f, std::max(0.0f, a / b)) : 0.0f;
    out[i] = static_cast<unsigned short>(std::lround(v * 65535.0f));
  }
  return image;
}
} // namespace

//------------------------------------------------------------------------------
vtkShadowVisibility::vtkShadowVisibility()
  : Scene(nullptr)
  , Technique(nullptr)
  , Light(0)
  , Size{ 0, 0 }
  , Epsilon(1e-3)
  , ErrorMessage(nullptr)
  , Visibility(nullptr)
  , Unshadowed(nullptr)
  , Shadowed(nullptr)
  , Mask(nullptr)
  , Visibility16(nullptr)
  , ChannelVisibility16{ nullptr, nullptr, nullptr }
{
}

//------------------------------------------------------------------------------
vtkShadowVisibility::~vtkShadowVisibility()
{
  this->SetScene(nullptr);
  this->SetTechnique(nullptr);
  this->SetErrorMessage(nullptr);
  this->ReleaseImages();
}

//------------------------------------------------------------------------------
void vtkShadowVisibility::ReleaseImages()
{
  for (vtkImageData** image :
    { &this->Visibility, &this->Unshadowed, &this->Shadowed, &this->Mask, &this->Visibility16,
      &this->ChannelVisibility16[0], &this->ChannelVisibility16[1], &this->ChannelVisibility16[2] })
  {
    if (*image)
    {
      (*image)->Delete();
      *image = nullptr;
    }
  }
}

//------------------------------------------------------------------------------
bool vtkShadowVisibility::Compute()
{
  this->SetErrorMessage(nullptr);
  if (!this->Scene || this->Scene->GetNumberOfObjects() == 0)
  {
    this->SetErrorMessage("no scene loaded");
    return false;
  }
  if (!this->Technique || !this->Technique->IsValid())
  {
    this->SetErrorMessage("no valid technique");
    return false;
  }
  if (this->Light < 0 || this->Light >= this->Scene->GetNumberOfLights())
  {
    const std::string msg = "light " + std::to_string(this->Light) + " out of range (scene has " +
      std::to_string(this->Scene->GetNumberOfLights()) + ")";
    this->SetErrorMessage(msg.c_str());
    return false;
  }
  const int w = this->Size[0] > 0 ? this->Size[0] : this->Scene->GetWidth();
  const int h = this->Size[1] > 0 ? this->Size[1] : this->Scene->GetHeight();

  vtkNew<vtkRenderWindow> window;
  // The process's one X connection: a window opening and closing its own
  // would leave Xvfb without clients between renders (it then resets).
  if (!vtkShadowDisplay::Attach(window))
  {
    this->SetErrorMessage(vtkShadowDisplay::GetErrorMessage());
    return false;
  }
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(w, h);
  vtkNew<vtkOpenGLRenderer> renderer;
  window->AddRenderer(renderer);
  this->Scene->Populate(renderer, /*lambertian=*/true, this->Light);

  vtkSmartPointer<vtkRenderPass> shadowed;
  shadowed.TakeReference(this->Technique->CreatePass());
  vtkNew<vtkShadowTechnique> none;
  none->SetName("none");
  vtkSmartPointer<vtkRenderPass> unshadowed;
  unshadowed.TakeReference(none->CreatePass());

  std::vector<float> onRGBA, offRGBA;
  if (!RenderFloatRGBA(window, renderer, unshadowed, w, h, offRGBA) ||
    !RenderFloatRGBA(window, renderer, shadowed, w, h, onRGBA))
  {
    this->SetErrorMessage("could not read back the float render target");
    return false;
  }
  const std::vector<float> on = SumRGB(onRGBA), off = SumRGB(offRGBA);

  this->ReleaseImages();
  this->Visibility = NewImage(w, h, VTK_FLOAT);
  this->Unshadowed = NewImage(w, h, VTK_FLOAT);
  this->Shadowed = NewImage(w, h, VTK_FLOAT);
  this->Mask = NewImage(w, h, VTK_UNSIGNED_CHAR);
  this->Visibility16 = NewImage(w, h, VTK_UNSIGNED_SHORT);
  auto* vis = static_cast<float*>(this->Visibility->GetScalarPointer());
  auto* offOut = static_cast<float*>(this->Unshadowed->GetScalarPointer());
  auto* onOut = static_cast<float*>(this->Shadowed->GetScalarPointer());
  auto* mask = static_cast<unsigned char*>(this->Mask->GetScalarPointer());
  auto* vis16 = static_cast<unsigned short*>(this->Visibility16->GetScalarPointer());
  for (size_t i = 0; i < off.size(); ++i)
  {
    offOut[i] = off[i];
    onOut[i] = on[i];
    const bool valid = off[i] > this->Epsilon;
    const float v = valid ? std::min(1.0f, std::max(0.0f, on[i] / off[i])) : 0.0f;
    vis[i] = v;
    mask[i] = valid ? 255 : 0;
    vis16[i] = static_cast<unsigned short>(std::lround(v * 65535.0f));
  }
  for (int c = 0; c < 3; ++c)
  {
    this->ChannelVisibility16[c] = ChannelImage(onRGBA, offRGBA, mask, c, w, h);
  }
  return true;
}

//------------------------------------------------------------------------------
vtkImageData* vtkShadowVisibility::GetVisibility()
{
  return this->Visibility;
}
vtkImageData* vtkShadowVisibility::GetUnshadowed()
{
  return this->Unshadowed;
}
vtkImageData* vtkShadowVisibility::GetShadowed()
{
  return this->Shadowed;
}
vtkImageData* vtkShadowVisibility::GetMask()
{
  return this->Mask;
}
vtkImageData* vtkShadowVisibility::GetVisibility16()
{
  return this->Visibility16;
}
vtkImageData* vtkShadowVisibility::GetChannelVisibility16(int channel)
{
  return channel >= 0 && channel < 3 ? this->ChannelVisibility16[channel] : nullptr;
}

//------------------------------------------------------------------------------
void vtkShadowVisibility::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Light: " << this->Light << "\n";
  os << indent << "Size: " << this->Size[0] << " x " << this->Size[1] << "\n";
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "Technique: "
     << (this->Technique && this->Technique->GetName() ? this->Technique->GetName() : "(none)")
     << "\n";
  os << indent << "ErrorMessage: " << (this->ErrorMessage ? this->ErrorMessage : "") << "\n";
}
