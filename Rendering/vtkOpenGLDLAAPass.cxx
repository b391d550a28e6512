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
#include "vtkOpenGLVertexArrayObject.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkDLAACornersFS.h"
#include "vtkDLAAFS.h"
#include "vtkDLAALuma.h"
#include "vtkDLAAMasksFS.h"
#include "vtkDLAATilesFS.h"
#include "vtkDLAATilesVS.h"

#include <algorithm>
#include <string>

#include "vtkAntialiasingOpenGL.h" // For glDrawArraysInstanced (VTK has no instanced quad) and GL enums

using namespace vtkOpenGLAntialiasingPassInternals;

namespace
{
// Masks a side of a tile of TilesTexture (vtkDLAATilesFS.glsl, vtkDLAATilesVS.glsl and
// vtkDLAAFS.glsl read 8 too). The shaders rely on it being the long edges' radius, which is also
// the masks' padding: a 17-pixel window then touches exactly three tiles, and the pixels of
// image tile t lie in tile t + 1 of the masks.
constexpr int TileSize = 8;
static_assert(TileSize == vtkDLAAOptions::LongEdgeRadius,
  "the DLAA shaders' tiles are as wide as the long edges' radius");
// Tiles a side of a square of the tiled filter draw (vtkDLAATilesVS.glsl): 32 x 32 pixels. On
// llvmpipe at 1920 x 1080, squares of 1, 2, 4 and 8 tiles gave the DLAA pass 0.67 / 0.62 / 0.58
// / 0.73 of FXAA's overhead on the mixed scene, 1.68 / 1.41 / 1.38 / 1.42 on the orbit and 4.25 /
// 3.70 / 2.97 / 3.03 on 45-degree stripes (docs/measurements.md): small squares cost a
// primitive each, and each split into two triangles shades the pixels along its diagonal twice.
constexpr int DrawTiles = 4;
}

vtkStandardNewMacro(vtkOpenGLDLAAPass);

//------------------------------------------------------------------------------
vtkOpenGLDLAAPass::vtkOpenGLDLAAPass()
{
  this->Options = vtkDLAAOptions::New();
}

//------------------------------------------------------------------------------
vtkOpenGLDLAAPass::~vtkOpenGLDLAAPass()
{
  this->ReleaseMethodResourcesOnDestruction();
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
  const int width = frame.Width + 2 * padding;
  const int height = frame.Height + 2 * padding;
  bool reallocated =
    AllocateColorTarget(this->MasksTexture, width, height, 2, VTK_FLOAT, false, GL_RG32F);
  if (!this->CornersTexture)
  {
    this->CornersTexture = NewTexture(frame.Window);
  }
  reallocated |= AllocateColorTarget(
    this->CornersTexture, frame.Width, frame.Height, 4, VTK_UNSIGNED_CHAR, false);
  if (!this->CornersMask)
  {
    this->CornersMask = NewTexture(frame.Window);
  }
  reallocated |=
    AllocateDepthTarget(this->CornersMask, frame.Width, frame.Height, vtkTextureObject::Fixed16);
  if (padding > 0)
  {
    if (!this->TilesTexture)
    {
      this->TilesTexture = NewTexture(frame.Window);
    }
    reallocated |= AllocateColorTarget(this->TilesTexture, (width + TileSize - 1) / TileSize,
      (height + TileSize - 1) / TileSize, 1, VTK_UNSIGNED_CHAR, false);
  }
  else
  {
    DeleteObject(this->TilesTexture, frame.Window); // (without long edges: not read)
  }
  return reallocated;
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
  {
    TimedStage stage(frame.Window, "edge masks");
    this->MasksQuad.Quad->Render();
  }
  return (padding == 0 || this->ComputeTiles(frame)) && this->ComputeCorners(frame);
}

//------------------------------------------------------------------------------
bool vtkOpenGLDLAAPass::ComputeCorners(const Frame& frame)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  this->BeginWorkPass(frame.Window, this->CornersTexture, frame.Width, frame.Height);
  this->WorkFramebuffer->AddDepthAttachment(this->CornersMask);
  // Two draws of vtkDLAACornersFS.glsl over flags and a depth mask cleared to 0: the candidates
  // write the quad's depth (1/2), then the test runs with the quad at depth 0 tested LESS, on the
  // candidates only. With long edges, only the squares of tiles near a mask other than 0 are
  // drawn (vtkDLAATilesVS.glsl, two tiles around): pass 2 reads no others.
  const bool tiled = this->Options->GetLongEdges();
  const std::string defines =
    Define("DLAA_LUMA", this->Options->GetLumaFunction()) + Define("DLAA_TILED", tiled);
  const char* vertexShader = tiled ? vtkDLAATilesVS : nullptr;
  BeginDepthMask(ostate);
  ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  bool ready = this->DrawCorners(frame, this->CornerCandidatesQuad,
    defines + Define("DLAA_CORNER_CANDIDATES", true), vertexShader, "corner candidates");
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglDepthFunc(GL_LESS);
  if (ready)
  {
    // (The depth range is not tracked by vtkOpenGLState: restored at once.)
    glDepthRange(0.0, 0.0);
    ready = this->DrawCorners(frame, this->CornersQuad, defines, vertexShader, "corners");
    glDepthRange(0.0, 1.0);
  }
  ostate->vtkglDisable(GL_DEPTH_TEST);
  this->WorkFramebuffer->RemoveDepthAttachment();
  return ready;
}

//------------------------------------------------------------------------------
bool vtkOpenGLDLAAPass::DrawCorners(const Frame& frame, ShaderVariant& variant,
  const std::string& defines, const char* vertexShader, const char* stageName)
{
  if (!this->ReadyQuad(frame.Window, variant, vtkDLAACornersFS, defines, vertexShader))
  {
    return false;
  }
  vtkShaderProgram* program = variant.Quad->Program;
  ScopedTextures textures(program, { { "colorTexture", this->ColorTexture } });
  program->SetUniformf("sideContrast",
    vtkDLAAOptions::SideContrast(this->Options->GetEpsilon(), this->Options->GetLambda()));
  program->SetUniformi("cornerSearch", vtkDLAAOptions::CornerSearch);
  program->SetUniformi("runEnds", 2);
  program->SetUniformi("crossingLength", vtkDLAAOptions::CornerCrossing);
  program->SetUniformi("cornerRun", vtkDLAAOptions::CornerRun);
  TimedStage stage(frame.Window, stageName);
  if (vertexShader)
  {
    textures.Bind(program, "tilesTexture", this->TilesTexture);
    DrawSquares(variant, frame, 2);
  }
  else
  {
    variant.Quad->Render();
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLDLAAPass::ComputeTiles(const Frame& frame)
{
  this->BeginWorkPass(frame.Window, this->TilesTexture, this->TilesTexture->GetWidth(),
    this->TilesTexture->GetHeight());
  if (!this->ReadyQuad(frame.Window, this->TilesQuad, vtkDLAATilesFS, std::string()))
  {
    return false;
  }
  const ScopedTextures textures(
    this->TilesQuad.Quad->Program, { { "masksTexture", this->MasksTexture } });
  TimedStage stage(frame.Window, "mask tiles");
  this->TilesQuad.Quad->Render();
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
  // A sample image of a render whose samples were each shaded on its own (ShortEdgesFromSamples):
  // the samples' average measures what the short-edge blur estimates.
  const SampleSet& set = this->GetCurrentSampleSet();
  const bool noShortEdges =
    this->ShortEdgesFromSamples && set.Index >= 0 && set.Shaded && set.Colors;
  const std::string defines = Define("DLAA_LUMA", this->Options->GetLumaFunction()) +
    Define("DLAA_LONG_EDGES", this->Options->GetLongEdges()) +
    Define("DLAA_IN_PLACE", frame.InPlace) + Define("DLAA_MOTION_FRAME", frame.MotionFrame) +
    Define("DLAA_NO_SHORT_EDGES", noShortEdges);
  // In place, with long edges, only the squares of pixels that may change are drawn
  // (vtkDLAATilesVS.glsl): the others keep the delegate's image, which the target holds.
  // Otherwise every pixel is written.
  const bool tiled = frame.InPlace && this->Options->GetLongEdges();
  ShaderVariant& variant = tiled ? this->FilterTilesQuad : this->FilterQuad;
  if (!this->ReadyQuad(
        frame.Window, variant, vtkDLAAFS, defines, tiled ? vtkDLAATilesVS : nullptr))
  {
    return false;
  }
  vtkShaderProgram* program = variant.Quad->Program;
  ScopedTextures textures(program,
    { { "colorTexture", this->ColorTexture }, { "masksTexture", this->MasksTexture } });
  program->SetUniformi("padding", this->GetMasksPadding());
  textures.Bind(program, "cornersTexture", this->CornersTexture);
  if (this->Options->GetLongEdges())
  {
    textures.Bind(program, "tilesTexture", this->TilesTexture);
  }
  if (noShortEdges)
  {
    textures.Bind(program, "samplesColor", set.Colors);
    program->SetUniformi("numberOfSamples", static_cast<int>(set.Offsets.size() / 2));
  }
  if (!frame.InPlace)
  {
    textures.Bind(program, "depthTexture", this->DepthTexture);
  }
  TimedStage stage(frame.Window, "filter");
  if (tiled)
  {
    DrawSquares(variant, frame, 1);
  }
  else
  {
    variant.Quad->Render();
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenGLDLAAPass::DrawSquares(ShaderVariant& variant, const Frame& frame, int margin)
{
  // One instance of the screen quad per square (vtkOpenGLQuadHelper draws one).
  vtkShaderProgram* program = variant.Quad->Program;
  program->SetUniformi("drawTiles", DrawTiles);
  program->SetUniformi("margin", margin);
  const int side = TileSize * DrawTiles;
  const int squares = ((frame.Width + side - 1) / side) * ((frame.Height + side - 1) / side);
  variant.Quad->VAO->Bind();
  glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, squares);
  variant.Quad->VAO->Release();
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
  this->TilesQuad.Release(w);
  this->CornerCandidatesQuad.Release(w);
  this->CornersQuad.Release(w);
  this->FilterQuad.Release(w);
  this->FilterTilesQuad.Release(w);
  DeleteObject(this->MasksTexture, w);
  DeleteObject(this->TilesTexture, w);
  DeleteObject(this->CornersTexture, w);
  DeleteObject(this->CornersMask, w);
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLDLAAPass::GetDLAATargetMemorySize()
{
  return TextureBytes(this->MasksTexture, 8) + TextureBytes(this->TilesTexture, 1) +
    TextureBytes(this->CornersTexture, 4) + TextureBytes(this->CornersMask, 2);
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
  os << indent << "ShortEdgesFromSamples: " << (this->ShortEdgesFromSamples ? "On" : "Off")
     << "\n";
  os << indent << "Options:\n";
  this->Options->PrintSelf(os, indent.GetNextIndent());
}
