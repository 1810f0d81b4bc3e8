// vtkShadowPNG.h - write PNG files so that a failure leaves nothing behind.
#ifndef vtkShadowPNG_h
#define vtkShadowPNG_h

#include "vtkshadowModule.h" // for export macro

#include <string>

class vtkImageData;

namespace vtkshadow
{
/**
 * Write `image` (unsigned char or unsigned short scalars, VTK row order) as
 * PNG to a temporary file beside `path`, then rename it into place, so a
 * reader never sees a half-written image. Returns false and sets `error`.
 */
VTKSHADOW_EXPORT bool WritePNGAtomically(
  vtkImageData* image, const std::string& path, std::string& error);

/**
 * Write `text` to `path` the same way.
 */
VTKSHADOW_EXPORT bool WriteTextAtomically(
  const std::string& text, const std::string& path, std::string& error);
}

#endif
