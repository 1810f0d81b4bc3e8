/**
 * @class   vtkShadowDisplay
 * @brief   One X display connection shared by every render window of the process.
 *
 * Debian's VTK renders through GLX: each vtkXOpenGLRenderWindow opens its
 * own X connection when it is first rendered and closes it when it is
 * finalized. A program that renders with one window, drops it and makes
 * another (the visibility renders, then the colour image) leaves the X
 * server with no client for a moment. Xvfb as started by `xvfb-run` resets
 * whenever its last client leaves, and a connection attempted during that
 * reset fails: VTK then prints "bad X server connection" and aborts.
 *
 * vtkShadowDisplay opens one connection on first use and keeps it for the
 * life of the process (the operating system closes it at exit), and
 * Attach() makes a window use it, so the server always has this process as
 * a client. Where no display can be opened at all it reports what to run
 * instead of letting VTK abort.
 *
 * @code{.py}
 * window = vtkRenderWindow()
 * if not vtkshadow.vtkShadowDisplay.Attach(window):
 *     raise SystemExit(vtkshadow.vtkShadowDisplay.GetErrorMessage())
 * @endcode
 */
#ifndef vtkShadowDisplay_h
#define vtkShadowDisplay_h

#include "vtkObject.h"
#include "vtkshadowModule.h" // for export macro

class vtkRenderWindow;

class VTKSHADOW_EXPORT vtkShadowDisplay : public vtkObject
{
public:
  static vtkShadowDisplay* New();
  vtkTypeMacro(vtkShadowDisplay, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Open the process's display (the first call; later calls give the same
   * answer without retrying). Returns false, with GetErrorMessage() saying
   * what to run, when DISPLAY is unset or names no reachable X server.
   */
  static bool Open();

  /**
   * Make `window` use the process's display. A window that already has a
   * display (it was rendered, or the application gave it one) and a window
   * that is not an X window are left as they are (true). Returns false when
   * the display cannot be opened; the window is then untouched and must not
   * be rendered (VTK would abort).
   */
  static bool Attach(vtkRenderWindow* window);

  /**
   * Why Open() failed, or an empty string.
   */
  static const char* GetErrorMessage();

  /**
   * Number of windows attached so far (for tests).
   */
  static int GetNumberOfAttachedWindows();

protected:
  vtkShadowDisplay() = default;
  ~vtkShadowDisplay() override = default;

private:
  vtkShadowDisplay(const vtkShadowDisplay&) = delete;
  void operator=(const vtkShadowDisplay&) = delete;
};

#endif
