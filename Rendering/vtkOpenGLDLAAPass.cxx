// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenGLDLAAPass.h"

#include "vtkOpenGLAntialiasingPassInternals.h"

#include "vtkDLAAOptions.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkDLAAFS.h"
#include "vtkDLAALuma.h"
#include "vtkDLAAMasksFS.h"

#include <algorithm>
#include <string>

#include "vtk_glew.h" // For GL enums only: every call goes through VTK's classes

using namespace vtkOpenGLAntialiasingPassInternals;

vtkStandardNewMacro(vtkOpenGLDLAAPass);

//------------------------------------------------------------------------------
vtkOpenGLDLAAPass::vtkOpenGLDLAAPass()
{
  this->Options = vtkDLAAOptions::New();
}

//------------------------------------------------------------------------------
vtkOpenGLDLAAPass::~vtkOpenGLDLAAPass()
{
  if ((this->MasksTexture || this->MasksQuad.Quad || this->FilterQuad.Quad) &&
    !this->HoldsSharedResources()) // else the base class reports it
  {
    vtkErrorMacro("Graphics resources should have been released by "
                  "ReleaseGraphicsResources().");
  }
  this->Options->Delete();
}

//------------------------------------------------------------------------------
void vtkOpenGLDLAAPass::SetOptions(vtkDLAAOptions* options)
{
  if (vtkDLAAOptions::Assign(this, this->Options, options))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkOpenGLDLAAPass::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Options->GetMTime());
}

//------------------------------------------------------------------------------
void vtkOpenGLDLAAPass::SubstituteShaderSnippets(std::string& source)
{
  vtkShaderProgram::Substitute(source, "//VTK::DLAA::Luma", vtkDLAALuma, false);
}

//------------------------------------------------------------------------------
bool vtkOpenGLDLAAPass::PrepareMethodTargets(const Frame& frame)
{
  if (!this->MasksTexture)
  {
    this->MasksTexture = NewTexture(frame.Window);
  }
  // Full floats: the 17-pixel means of the masks follow the CPU's float arithmetic (half floats
  // would move the noise rejection's threshold by their rounding). With long edges the texture
  // extends 8 pixels beyond each side of the image, where the 17-pixel windows of the pixels
  // near the border read masks computed from clamped colours (vtkDLAAMasksFS.glsl).
  const int padding = this->GetMasksPadding();
  return AllocateColorTarget(this->MasksTexture, frame.Width + 2 * padding,
    frame.Height + 2 * padding, 2, VTK_FLOAT, false, GL_RG32F);
}

//------------------------------------------------------------------------------
int vtkOpenGLDLAAPass::GetMasksPadding()
{
  return this->Options->GetLongEdges() ? vtkDLAAOptions::LongEdgeRadius : 0;
}

//------------------------------------------------------------------------------
bool vtkOpenGLDLAAPass::ComputeMasks(const Frame& frame)
{
  const int padding = this->GetMasksPadding();
  const int width = frame.Width + 2 * padding;
  const int height = frame.Height + 2 * padding;
  this->BeginWorkPass(frame.Window, this->MasksTexture, width, height);
  frame.Window->GetState()->vtkglDisable(GL_DEPTH_TEST);
  if (!this->ReadyQuad(frame.Window, this->MasksQuad, vtkDLAAMasksFS,
        Define("DLAA_LUMA", this->Options->GetLumaFunction())))
  {
    return false;
  }
  vtkShaderProgram* program = this->MasksQuad.Quad->Program;
  const ScopedTextures textures(program, { { "colorTexture", this->ColorTexture } });
  program->SetUniformf("lambda", static_cast<float>(this->Options->GetLambda()));
  program->SetUniformf("epsilon", static_cast<float>(this->Options->GetEpsilon()));
  program->SetUniformi("padding", padding);
  TimedStage stage(frame.Window, "edge masks");
  this->MasksQuad.Quad->Render();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLDLAAPass::Filter(const Frame& frame)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  // Premultiplied "over" onto what lower layers drew (see vtkOpenGLAntialiasingPass); in place,
  // only the changed pixels are written, and no depth; otherwise the delegate's depth is copied.
  SetTargetWriteState(ostate, frame.X, frame.Y, frame.Width, frame.Height, frame.Composite,
    !frame.InPlace);
  const std::string defines = Define("DLAA_LUMA", this->Options->GetLumaFunction()) +
    Define("DLAA_LONG_EDGES", this->Options->GetLongEdges()) +
    Define("DLAA_IN_PLACE", frame.InPlace);
  if (!this->ReadyQuad(frame.Window, this->FilterQuad, vtkDLAAFS, defines))
  {
    return false;
  }
  vtkShaderProgram* program = this->FilterQuad.Quad->Program;
  ScopedTextures textures(program,
    { { "colorTexture", this->ColorTexture }, { "masksTexture", this->MasksTexture } });
  program->SetUniformi("padding", this->GetMasksPadding());
  if (!frame.InPlace)
  {
    textures.Bind(program, "depthTexture", this->DepthTexture);
  }
  TimedStage stage(frame.Window, "filter");
  this->FilterQuad.Quad->Render();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLDLAAPass::Antialias(const Frame& frame)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  ostate->PushFramebufferBindings();
  const bool computed = this->ComputeMasks(frame);
  ostate->PopFramebufferBindings();
  return computed && this->Filter(frame);
}

//------------------------------------------------------------------------------
void vtkOpenGLDLAAPass::ReleaseMethodResources(vtkWindow* w)
{
  this->MasksQuad.Release(w);
  this->FilterQuad.Release(w);
  DeleteObject(this->MasksTexture, w);
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLDLAAPass::GetDLAATargetMemorySize()
{
  return TextureBytes(this->MasksTexture, 8);
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLDLAAPass::GetMethodTargetMemorySize()
{
  return this->GetDLAATargetMemorySize();
}

//------------------------------------------------------------------------------
void vtkOpenGLDLAAPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Options:\n";
  this->Options->PrintSelf(os, indent.GetNextIndent());
}
