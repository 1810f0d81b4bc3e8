#include "vtkShadowDisplay.h"

#include "vtkObjectFactory.h"
#include "vtkRenderWindow.h"
#include "vtkXOpenGLRenderWindow.h"

#include <X11/Xlib.h>

#include <cstdlib>
#include <mutex>
#include <string>

vtkStandardNewMacro(vtkShadowDisplay);

namespace
{
// The process's connection: opened once, never closed (closing it is what
// lets Xvfb reset under a later window; the OS closes it at exit).
struct SharedDisplay
{
  std::mutex Lock;
  bool Tried = false;
  Display* Id = nullptr;
  std::string Error;
  int Attached = 0;
};

SharedDisplay& Shared()
{
  static SharedDisplay* shared = new SharedDisplay; // never destroyed, like the connection
  return *shared;
}

std::string NoDisplayMessage()
{
  const char* name = std::getenv("DISPLAY");
  const std::string advice = "; VTK on Debian renders through X: run the command under "
                             "xvfb-run -a (e.g. xvfb-run -a vtkshadow-render SCENE ...), or set "
                             "DISPLAY to a running X server";
  if (!name || !*name)
  {
    return "no X display (DISPLAY is not set)" + advice;
  }
  return std::string("cannot open the X display DISPLAY=\"") + name +
    "\" (no X server answers there)" + advice;
}

// Open under the lock; the caller holds it.
bool OpenLocked(SharedDisplay& shared)
{
  if (!shared.Tried)
  {
    shared.Tried = true;
    const char* name = std::getenv("DISPLAY");
    // XOpenDisplay(nullptr) would read DISPLAY too; an empty name is refused
    // here because Xlib would then try ":0".
    shared.Id = (name && *name) ? XOpenDisplay(nullptr) : nullptr;
    if (!shared.Id)
    {
      shared.Error = NoDisplayMessage();
    }
  }
  return shared.Id != nullptr;
}
} // namespace

//------------------------------------------------------------------------------
bool vtkShadowDisplay::Open()
{
  SharedDisplay& shared = Shared();
  std::lock_guard<std::mutex> guard(shared.Lock);
  return OpenLocked(shared);
}

//------------------------------------------------------------------------------
bool vtkShadowDisplay::Attach(vtkRenderWindow* window)
{
  auto* xwindow = vtkXOpenGLRenderWindow::SafeDownCast(window);
  if (!xwindow || xwindow->GetDisplayId())
  {
    return true; // not X, or it already has its display: leave it alone
  }
  SharedDisplay& shared = Shared();
  std::lock_guard<std::mutex> guard(shared.Lock);
  if (!OpenLocked(shared))
  {
    return false;
  }
  // SetDisplayId marks the display as not owned by the window, so
  // finalizing the window leaves the connection open.
  xwindow->SetDisplayId(shared.Id);
  ++shared.Attached;
  return true;
}

//------------------------------------------------------------------------------
const char* vtkShadowDisplay::GetErrorMessage()
{
  SharedDisplay& shared = Shared();
  std::lock_guard<std::mutex> guard(shared.Lock);
  return shared.Error.c_str();
}

//------------------------------------------------------------------------------
int vtkShadowDisplay::GetNumberOfAttachedWindows()
{
  SharedDisplay& shared = Shared();
  std::lock_guard<std::mutex> guard(shared.Lock);
  return shared.Attached;
}

//------------------------------------------------------------------------------
void vtkShadowDisplay::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  SharedDisplay& shared = Shared();
  std::lock_guard<std::mutex> guard(shared.Lock);
  os << indent << "Open: " << (shared.Id ? "yes" : "no") << "\n";
  os << indent << "AttachedWindows: " << shared.Attached << "\n";
  os << indent << "ErrorMessage: " << shared.Error << "\n";
}
