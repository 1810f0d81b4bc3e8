// The extern "C" API: opaque handles that own the VTK objects.
#include "vtkshadow.h"

#include "vtkActor.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPlanarShadowPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShadowActorFlags.h"
#include "vtkShadowDisplay.h"
#include "vtkShadowPNG.h"
#include "vtkShadowScene.h"
#include "vtkShadowTechnique.h"
#include "vtkShadowTechniqueRegistry.h"
#include "vtkShadowVisibility.h"
#include "vtkSmartPointer.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <string>

struct vtkshadow_scene
{
  vtkSmartPointer<vtkShadowScene> Scene;
};

struct vtkshadow_technique
{
  vtkSmartPointer<vtkShadowTechnique> Technique;
};

namespace
{
// The vtkActor behind a void* from C, or nullptr for anything else.
vtkActor* AsActor(void* pointer)
{
  auto* object = static_cast<vtkObjectBase*>(pointer);
  return object && object->IsA("vtkActor") ? static_cast<vtkActor*>(object) : nullptr;
}

void SetError(char* error, size_t size, const std::string& message)
{
  if (error && size > 0)
  {
    std::snprintf(error, size, "%s", message.c_str());
  }
}
}

extern "C"
{
  const char* vtkshadow_version(void)
  {
    return "0.1.0";
  }

  vtkshadow_scene* vtkshadow_scene_load(const char* path, char* error, size_t error_size)
  {
    auto scene = vtkSmartPointer<vtkShadowScene>::New();
    if (!scene->Load(path))
    {
      SetError(error, error_size, scene->GetErrorMessage());
      return nullptr;
    }
    auto* handle = new vtkshadow_scene;
    handle->Scene = scene;
    return handle;
  }

  void vtkshadow_scene_free(vtkshadow_scene* scene)
  {
    delete scene;
  }

  int vtkshadow_scene_light_count(const vtkshadow_scene* scene)
  {
    return scene ? scene->Scene->GetNumberOfLights() : 0;
  }

  int vtkshadow_scene_object_count(const vtkshadow_scene* scene)
  {
    return scene ? scene->Scene->GetNumberOfObjects() : 0;
  }

  void vtkshadow_scene_size(const vtkshadow_scene* scene, int* width, int* height)
  {
    if (width)
    {
      *width = scene ? scene->Scene->GetWidth() : 0;
    }
    if (height)
    {
      *height = scene ? scene->Scene->GetHeight() : 0;
    }
  }

  int vtkshadow_scene_populate(
    const vtkshadow_scene* scene, void* vtk_renderer, char* error, size_t error_size)
  {
    auto* renderer = static_cast<vtkRenderer*>(vtk_renderer);
    if (!scene || !renderer || !renderer->IsA("vtkRenderer"))
    {
      SetError(error, error_size, "vtkshadow_scene_populate: need a scene and a vtkRenderer*");
      return 1;
    }
    return scene->Scene->Populate(renderer) ? 0 : 1;
  }

  int vtkshadow_technique_count(void)
  {
    return vtkShadowTechniqueRegistry::GetNumberOfTechniques();
  }

  const char* vtkshadow_technique_name_at(int index)
  {
    return vtkShadowTechniqueRegistry::GetName(index);
  }

  const char* vtkshadow_technique_description_at(int index)
  {
    return vtkShadowTechniqueRegistry::GetDescription(index);
  }

  vtkshadow_technique* vtkshadow_technique_new(const char* name, char* error, size_t error_size)
  {
    if (!vtkShadowTechnique::IsKnownTechnique(name))
    {
      SetError(error, error_size,
        std::string("unknown technique \"") + (name ? name : "(null)") +
          "\"; known: " + vtkShadowTechnique::GetKnownTechniques());
      return nullptr;
    }
    auto* handle = new vtkshadow_technique;
    handle->Technique = vtkSmartPointer<vtkShadowTechnique>::New();
    handle->Technique->SetName(name);
    return handle;
  }

  void vtkshadow_technique_free(vtkshadow_technique* technique)
  {
    delete technique;
  }

  const char* vtkshadow_technique_name(const vtkshadow_technique* technique)
  {
    return technique ? technique->Technique->GetName() : nullptr;
  }

  int vtkshadow_technique_set_map_resolution(vtkshadow_technique* technique, int resolution)
  {
    if (!technique || resolution < 16 || resolution > 16384)
    {
      return 1;
    }
    technique->Technique->SetMapResolution(resolution);
    return 0;
  }

  int vtkshadow_technique_set_option(
    vtkshadow_technique* technique, const char* key, double value, char* error, size_t error_size)
  {
    if (!technique || !key || !technique->Technique->SetOption(key, value))
    {
      std::ostringstream message;
      message << "vtkshadow_technique_set_option: unknown key or value out of range: "
              << (key ? key : "(null)") << " = " << value;
      SetError(error, error_size, message.str());
      return 1;
    }
    return 0;
  }

  int vtkshadow_technique_install(
    vtkshadow_technique* technique, void* vtk_renderer, char* error, size_t error_size)
  {
    auto* renderer = static_cast<vtkRenderer*>(vtk_renderer);
    if (!technique || !renderer || !renderer->IsA("vtkOpenGLRenderer") ||
      !technique->Technique->Install(renderer))
    {
      SetError(error, error_size, "vtkshadow_technique_install: need a vtkOpenGLRenderer*");
      return 1;
    }
    return 0;
  }

  int vtkshadow_technique_enable(
    vtkshadow_technique* technique, void* vtk_renderer, char* error, size_t error_size)
  {
    auto* object = static_cast<vtkObjectBase*>(vtk_renderer);
    if (!technique || !object || !object->IsA("vtkOpenGLRenderer"))
    {
      SetError(error, error_size, "vtkshadow_technique_enable: need a vtkOpenGLRenderer*");
      return 1;
    }
    if (!technique->Technique->Enable(static_cast<vtkRenderer*>(object)))
    {
      SetError(error, error_size,
        std::string("vtkshadow_technique_enable: cannot make technique \"") +
          technique->Technique->GetName() + "\" with its settings");
      return 1;
    }
    return 0;
  }

  vtkshadow_technique* vtkshadow_enable_shadows(
    void* vtk_renderer, const char* name, double max_error, char* error, size_t error_size)
  {
    vtkshadow_technique* technique =
      vtkshadow_technique_new(name ? name : "auto", error, error_size);
    if (!technique)
    {
      return nullptr;
    }
    if ((max_error >= 0.0 &&
          vtkshadow_technique_set_option(technique, "max_error", max_error, error, error_size)) ||
      vtkshadow_technique_enable(technique, vtk_renderer, error, error_size))
    {
      vtkshadow_technique_free(technique);
      return nullptr;
    }
    return technique;
  }

  int vtkshadow_technique_set_key_light(vtkshadow_technique* technique, int on)
  {
    if (!technique)
    {
      return 1;
    }
    technique->Technique->SetAutoKeyLight(on != 0);
    return 0;
  }

  const char* vtkshadow_technique_light_message(const vtkshadow_technique* technique)
  {
    return technique ? technique->Technique->GetLightMessage() : "";
  }

  int vtkshadow_technique_detected_receiver_count(const vtkshadow_technique* technique)
  {
    return technique ? technique->Technique->GetNumberOfDetectedReceivers() : 0;
  }

  int vtkshadow_actor_set_receiver(void* vtk_actor, int receiver)
  {
    vtkActor* actor = AsActor(vtk_actor);
    if (!actor)
    {
      return 1;
    }
    vtkshadow::SetFlag(actor, vtkShadowPassBase::RECEIVER(), receiver ? 1 : 0);
    return 0;
  }

  int vtkshadow_actor_set_casts(void* vtk_actor, int casts)
  {
    vtkActor* actor = AsActor(vtk_actor);
    if (!actor)
    {
      return 1;
    }
    vtkshadow::SetFlag(actor, vtkShadowPassBase::NO_CAST(), casts ? 0 : 1);
    return 0;
  }

  int vtkshadow_render_png(const vtkshadow_scene* scene, vtkshadow_technique* technique,
    const char* path, char* error, size_t error_size)
  {
    if (!scene || !technique || !path)
    {
      SetError(error, error_size, "vtkshadow_render_png: need a scene, a technique and a path");
      return 1;
    }
    vtkNew<vtkRenderWindow> window;
    // The process's one X connection (vtkShadowDisplay); none: say so, not abort.
    if (!vtkShadowDisplay::Attach(window))
    {
      SetError(error, error_size,
        std::string("vtkshadow_render_png: ") + vtkShadowDisplay::GetErrorMessage());
      return 1;
    }
    window->SetOffScreenRendering(1);
    window->SetSize(scene->Scene->GetWidth(), scene->Scene->GetHeight());
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    scene->Scene->Populate(renderer);
    if (!technique->Technique->Install(renderer))
    {
      SetError(error, error_size, "vtkshadow_render_png: cannot install the technique");
      return 1;
    }
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->SetInputBufferTypeToRGB();
    grab->ReadFrontBufferOff();
    grab->Update();
    std::string message;
    if (!vtkshadow::WritePNGAtomically(grab->GetOutput(), path, message))
    {
      SetError(error, error_size, message);
      return 1;
    }
    return 0;
  }

  int vtkshadow_visibility(const vtkshadow_scene* scene, vtkshadow_technique* technique, int light,
    const char* png_path, double* mean_visibility, long* valid_pixels, char* error,
    size_t error_size)
  {
    if (!scene || !technique)
    {
      SetError(error, error_size, "vtkshadow_visibility: need a scene and a technique");
      return 1;
    }
    vtkNew<vtkShadowVisibility> visibility;
    visibility->SetScene(scene->Scene);
    visibility->SetTechnique(technique->Technique);
    visibility->SetLight(light);
    if (!visibility->Compute())
    {
      SetError(error, error_size, visibility->GetErrorMessage());
      return 1;
    }
    const auto* v = static_cast<const float*>(visibility->GetVisibility()->GetScalarPointer());
    const auto* m = static_cast<const unsigned char*>(visibility->GetMask()->GetScalarPointer());
    const vtkIdType n = visibility->GetVisibility()->GetNumberOfPoints();
    double sum = 0.0;
    long count = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      if (m[i])
      {
        sum += v[i];
        ++count;
      }
    }
    if (mean_visibility)
    {
      *mean_visibility = count ? sum / count : 0.0;
    }
    if (valid_pixels)
    {
      *valid_pixels = count;
    }
    std::string message;
    if (png_path &&
      !vtkshadow::WritePNGAtomically(visibility->GetVisibility16(), png_path, message))
    {
      SetError(error, error_size, message);
      return 1;
    }
    return 0;
  }
}
