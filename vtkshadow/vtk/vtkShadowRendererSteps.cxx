#include "vtkShadowRendererSteps.h"

#include "vtkDepthPeelingPass.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpaquePass.h"
#include "vtkOpenGLFXAAFilter.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOrderIndependentTranslucentPass.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkSequencePass.h"
#include "vtkShadowDepthSeed.h"
#include "vtkSmartPointer.h"
#include "vtkTranslucentPass.h"
#include "vtkVolumetricPass.h"

namespace
{
// Translucent geometry as the renderer draws it without a pass.
class TranslucentAsRenderer : public vtkRenderPass
{
public:
  static TranslucentAsRenderer* New();
  vtkTypeMacro(TranslucentAsRenderer, vtkRenderPass);

  void Render(const vtkRenderState* s) override
  {
    auto* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
    vtkRenderPass* step = renderer && renderer->GetUseDepthPeeling()
      ? this->Peeling(renderer)
      : static_cast<vtkRenderPass*>(this->Blending());
    step->Render(s);
    this->NumberOfRenderedProps = step->GetNumberOfRenderedProps();
  }

  void ReleaseGraphicsResources(vtkWindow* w) override
  {
    if (this->DepthPeeling)
    {
      this->DepthPeeling->ReleaseGraphicsResources(w);
    }
    if (this->OrderIndependent)
    {
      this->OrderIndependent->ReleaseGraphicsResources(w);
    }
  }

private:
  vtkRenderPass* Peeling(vtkOpenGLRenderer* renderer)
  {
    if (!this->DepthPeeling)
    {
      // Dual depth peeling where the driver has it, as the renderer picks.
      if (renderer->IsDualDepthPeelingSupported())
      {
        this->DepthPeeling = vtkSmartPointer<vtkDualDepthPeelingPass>::New();
      }
      else
      {
        this->DepthPeeling = vtkSmartPointer<vtkDepthPeelingPass>::New();
      }
      vtkNew<vtkTranslucentPass> translucent;
      this->DepthPeeling->SetTranslucentPass(translucent);
    }
    this->DepthPeeling->SetMaximumNumberOfPeels(renderer->GetMaximumNumberOfPeels());
    this->DepthPeeling->SetOcclusionRatio(renderer->GetOcclusionRatio());
    return this->DepthPeeling;
  }

  vtkOrderIndependentTranslucentPass* Blending()
  {
    if (!this->OrderIndependent)
    {
      this->OrderIndependent = vtkSmartPointer<vtkOrderIndependentTranslucentPass>::New();
      vtkNew<vtkTranslucentPass> translucent;
      this->OrderIndependent->SetTranslucentPass(translucent);
    }
    return this->OrderIndependent;
  }

  vtkSmartPointer<vtkDepthPeelingPass> DepthPeeling;
  vtkSmartPointer<vtkOrderIndependentTranslucentPass> OrderIndependent;
};
vtkStandardNewMacro(TranslucentAsRenderer);

// FXAA on what is drawn so far, when the renderer asks for it.
class FXAAAsRenderer : public vtkRenderPass
{
public:
  static FXAAAsRenderer* New();
  vtkTypeMacro(FXAAAsRenderer, vtkRenderPass);

  void Render(const vtkRenderState* s) override
  {
    auto* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
    this->NumberOfRenderedProps = 0;
    if (!renderer || !renderer->GetUseFXAA())
    {
      return;
    }
    if (!this->Filter)
    {
      this->Filter = vtkSmartPointer<vtkOpenGLFXAAFilter>::New();
    }
    if (renderer->GetFXAAOptions())
    {
      this->Filter->UpdateConfiguration(renderer->GetFXAAOptions());
    }
    this->Filter->Execute(renderer);
  }

  void ReleaseGraphicsResources(vtkWindow*) override
  {
    if (this->Filter)
    {
      this->Filter->ReleaseGraphicsResources();
    }
  }

private:
  vtkSmartPointer<vtkOpenGLFXAAFilter> Filter;
};
vtkStandardNewMacro(FXAAAsRenderer);

// The opaque step, after the owner's depth pre-pass is written into the
// depth buffer where that pays (vtkShadowDepthSeed), when the owner gave one
// for this frame.
class SeededOpaquePass : public vtkOpaquePass
{
public:
  static SeededOpaquePass* New();
  vtkTypeMacro(SeededOpaquePass, vtkOpaquePass);

  void Render(const vtkRenderState* s) override
  {
    this->Seed.BeginOpaque(
      vtkOpenGLRenderWindow::SafeDownCast(s->GetRenderer()->GetRenderWindow()), this->Source);
    this->Superclass::Render(s);
    this->Seed.EndOpaque();
  }

  void ReleaseGraphicsResources(vtkWindow* w) override
  {
    this->Seed.ReleaseGraphicsResources();
    this->Superclass::ReleaseGraphicsResources(w);
  }

  vtkTextureObject* Source = nullptr;
  vtkShadowDepthSeed Seed;
};
vtkStandardNewMacro(SeededOpaquePass);

// The seeded opaque step of steps made by NewRendererSteps, else null.
SeededOpaquePass* SeededOpaque(vtkRenderPass* steps)
{
  auto* renderSteps = vtkRenderStepsPass::SafeDownCast(steps);
  return renderSteps ? SeededOpaquePass::SafeDownCast(renderSteps->GetOpaquePass()) : nullptr;
}
}

//------------------------------------------------------------------------------
vtkRenderStepsPass* vtkshadow::NewRendererSteps()
{
  vtkRenderStepsPass* steps = vtkRenderStepsPass::New();
  vtkNew<SeededOpaquePass> opaque;
  steps->SetOpaquePass(opaque);
  vtkNew<TranslucentAsRenderer> translucent;
  steps->SetTranslucentPass(translucent);
  // The volumetric step's slot runs right after translucent geometry: FXAA
  // goes there, before the volumes, as in vtkOpenGLRenderer.
  vtkNew<vtkSequencePass> fxaaThenVolumes;
  vtkNew<vtkRenderPassCollection> sequence;
  vtkNew<FXAAAsRenderer> fxaa;
  vtkNew<vtkVolumetricPass> volumes;
  sequence->AddItem(fxaa);
  sequence->AddItem(volumes);
  fxaaThenVolumes->SetPasses(sequence);
  steps->SetVolumetricPass(fxaaThenVolumes);
  return steps;
}

//------------------------------------------------------------------------------
bool vtkshadow::SetSeedDepth(vtkRenderPass* steps, vtkTextureObject* depth, bool always)
{
  SeededOpaquePass* opaque = SeededOpaque(steps);
  if (!opaque)
  {
    return false;
  }
  opaque->Source = depth;
  opaque->Seed.SetAlways(always);
  return true;
}

//------------------------------------------------------------------------------
bool vtkshadow::GetDepthSeedState(vtkRenderPass* steps, bool& seeded, double& hiddenPerPixel)
{
  const SeededOpaquePass* opaque = SeededOpaque(steps);
  seeded = opaque && opaque->Seed.GetSeeded();
  hiddenPerPixel = opaque ? opaque->Seed.GetHiddenPerPixel() : -1.0;
  return opaque != nullptr;
}
