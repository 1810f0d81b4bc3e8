/**
 * @class   vtkShadowTechniqueRegistry
 * @brief   The one table of shadow techniques: name, description, factory.
 *
 * Every tool reads this table: vtkShadowTechnique (and through it the C API
 * and Python), `vtkshadow-render --list-techniques`, the harness, the
 * benchmark and the robustness suite. Adding a technique is its pass class
 * (a vtkShadowPassBase) plus one line in vtkShadowTechniqueRegistry.cxx.
 *
 * @code{.py}
 * R = vtkshadow.vtkShadowTechniqueRegistry
 * for i in range(R.GetNumberOfTechniques()):
 *     print(R.GetName(i), "-", R.GetDescription(i))
 * @endcode
 */
#ifndef vtkShadowTechniqueRegistry_h
#define vtkShadowTechniqueRegistry_h

#include "vtkObject.h"
#include "vtkshadowModule.h" // for export macro

class vtkShadowPassBase;
namespace vtkshadow
{
class Settings;
}

class VTKSHADOW_EXPORT vtkShadowTechniqueRegistry : public vtkObject
{
public:
  static vtkShadowTechniqueRegistry* New();
  vtkTypeMacro(vtkShadowTechniqueRegistry, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The techniques in table order; out-of-range indices give nullptr.
   */
  static int GetNumberOfTechniques();
  static const char* GetName(int index);
  static const char* GetDescription(int index);

  /**
   * Index of `name` in the table, -1 when unknown.
   */
  static int FindTechnique(const char* name);

  /**
   * The names, separated by single spaces ("none vtk planar ...").
   */
  static const char* GetNames();

  /**
   * A new pass for the technique with default settings (caller owns it;
   * call Delete()), or nullptr for an unknown name.
   */
  static vtkShadowPassBase* CreatePass(const char* name);

#ifndef __VTK_WRAP__
  /**
   * The settings table of technique `index`'s pass, without making one
   * (empty for an out-of-range index). vtkshadow::Settings::ForTechnique
   * adds what every technique takes.
   */
  static const vtkshadow::Settings& GetSettings(int index);
#endif

protected:
  vtkShadowTechniqueRegistry() = default;
  ~vtkShadowTechniqueRegistry() override = default;

private:
  vtkShadowTechniqueRegistry(const vtkShadowTechniqueRegistry&) = delete;
  void operator=(const vtkShadowTechniqueRegistry&) = delete;
};

#endif
