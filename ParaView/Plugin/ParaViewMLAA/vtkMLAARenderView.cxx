#include "vtkMLAARenderView.h"

#include "vtkMLAAOptions.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLMLAAPass.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkRenderWindow.h"

vtkStandardNewMacro(vtkMLAARenderView);

//------------------------------------------------------------------------------
vtkMLAARenderView::vtkMLAARenderView()
{
  this->RequestedFXAA = this->UseFXAA;
  this->RequestedToneMapping = this->UseToneMapping;
  this->UpdatePasses();
}

//------------------------------------------------------------------------------
vtkMLAARenderView::~vtkMLAARenderView()
{
  // The renderer releases its pass's resources when it leaves the window, in vtkPVRenderView's
  // destructor; the pass leaves the renderer first (below), so it releases them itself.
  if (vtkRenderWindow* window = this->GetRenderWindow())
  {
    this->MLAAPass->ReleaseGraphicsResources(window);
  }
  if (this->SynchronizedRenderers &&
    this->SynchronizedRenderers->GetImageProcessingPass() == this->MLAAPass.GetPointer())
  {
    this->SynchronizedRenderers->SetImageProcessingPass(nullptr);
  }
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetUseMLAA(bool use)
{
  if (use != this->UseMLAA)
  {
    this->UseMLAA = use;
    this->Modified();
    this->UpdatePasses();
  }
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetMLAAOptions(vtkMLAAOptions* options)
{
  this->MLAAPass->SetOptions(options);
}

//------------------------------------------------------------------------------
vtkMLAAOptions* vtkMLAARenderView::GetMLAAOptions()
{
  return this->MLAAPass->GetOptions();
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetUseFXAA(bool use)
{
  this->RequestedFXAA = use;
  this->UpdatePasses();
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetUseToneMapping(bool use)
{
  this->RequestedToneMapping = use;
  this->UpdatePasses();
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::UpdatePasses()
{
  if (this->UseMLAA)
  {
    // The tone-mapping pass leaves the slot first (vtkPVRenderView only removes its own pass).
    this->Superclass::SetUseToneMapping(false);
    this->SynchronizedRenderers->SetImageProcessingPass(this->MLAAPass);
  }
  else
  {
    if (this->SynchronizedRenderers->GetImageProcessingPass() == this->MLAAPass.GetPointer())
    {
      this->SynchronizedRenderers->SetImageProcessingPass(nullptr);
    }
    this->Superclass::SetUseToneMapping(this->RequestedToneMapping);
  }
  // vtkPVRenderView reads UseFXAA at every render.
  this->Superclass::SetUseFXAA(this->RequestedFXAA && !this->UseMLAA);
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseMLAA: " << (this->UseMLAA ? "On" : "Off") << "\n";
  os << indent << "RequestedFXAA: " << (this->RequestedFXAA ? "On" : "Off") << "\n";
  os << indent << "RequestedToneMapping: " << (this->RequestedToneMapping ? "On" : "Off") << "\n";
  os << indent << "MLAAPass:\n";
  this->MLAAPass->PrintSelf(os, indent.GetNextIndent());
}
