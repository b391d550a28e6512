// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenGLMLAAPass.h"

#include "vtkOpenGLAntialiasingPassInternals.h"

#include "vtkAntialiasingKit.h" // For Lab::Linearise, the CPU twin of vtkMLAALab.glsl
#include "vtkMLAAAreaTexture.h"
#include "vtkMLAAOptions.h"
#include "vtkMLAATopology.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"

#include "vtkMLAABlendingWeightsFS.h"
#include "vtkMLAAEdgeDetectionFS.h"
#include "vtkMLAALineLengthsFS.h"
#include "vtkMLAALineLengthsInitFS.h"
#include "vtkMLAALab.h"
#include "vtkMLAANeighborhoodBlendingFS.h"
#include "vtkMLAAReconstructionFS.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "vtkAntialiasingOpenGL.h" // For GL enums only: every call goes through VTK's classes

vtkStandardNewMacro(vtkOpenGLMLAAPass);

using namespace vtkOpenGLAntialiasingPassInternals;

//------------------------------------------------------------------------------
vtkOpenGLMLAAPass::vtkOpenGLMLAAPass()
{
  this->Options = vtkMLAAOptions::New();
}

//------------------------------------------------------------------------------
vtkOpenGLMLAAPass::~vtkOpenGLMLAAPass()
{
  this->ReleaseMethodResourcesOnDestruction();
  this->Options->Delete();
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::SetOptions(vtkMLAAOptions* options)
{
  if (vtkMLAAOptions::Assign(this, this->Options, options))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::PrepareMethodTargets(const Frame& frame)
{
  vtkOpenGLRenderWindow* renWin = frame.Window;
  const int width = frame.Width;
  const int height = frame.Height;
  const bool floatColor = frame.FloatColor;
  for (vtkTextureObject** texture :
    { &this->EdgesTexture, &this->WeightsTexture, &this->MaskTexture })
  {
    if (!*texture)
    {
      *texture = NewTexture(renWin);
    }
  }
  bool reallocated = false;
  // Linear filtering: the search and the crossing-edge reads rely on it (section 4.3).
  reallocated |= AllocateColorTarget(this->EdgesTexture, width, height, 2, VTK_UNSIGNED_CHAR, true);
  // 8-bit weights, as the chapter's RGBA8 texture (vtkImageMLAA quantises the same way).
  reallocated |=
    AllocateColorTarget(this->WeightsTexture, width, height, 4, VTK_UNSIGNED_CHAR, false);
  reallocated |= AllocateDepthTarget(this->MaskTexture, width, height, vtkTextureObject::Fixed16);
  // With recursive doubling only, else not kept (and no framebuffer keeps them attached): the
  // orthogonal lengths, RGBA16F (integers up to 2048 exactly), and with diagonal detection the
  // counts of staircase units, up to GetStaircaseCountReach() each way, two to a byte of an RG8
  // texture.
  const bool doubling = this->GetUsesRecursiveDoubling();
  auto keep = [&](vtkTextureObject*& texture, bool used, int components, int vtkType,
                unsigned int internalFormat) {
    if (!used)
    {
      reallocated |= texture != nullptr;
      DeleteObject(texture, renWin);
      return;
    }
    if (!texture)
    {
      texture = NewTexture(renWin);
    }
    reallocated |= AllocateColorTarget(
      texture, width, height, components, vtkType, false, internalFormat);
  };
  for (vtkTextureObject*& lengths : this->LengthsTextures)
  {
    keep(lengths, doubling, 4, VTK_FLOAT, GL_RGBA16F);
  }
  keep(this->StaircaseCountsTexture, this->GetCountsStaircases(), 2, VTK_UNSIGNED_CHAR, GL_RG8);
  // The reconstructed image (vtkMLAAOptions::Reconstruction), in the colour texture's format.
  if (this->Options->GetReconstruction())
  {
    if (!this->ReconstructedTexture)
    {
      this->ReconstructedTexture = NewTexture(renWin);
    }
    reallocated |= AllocateColorTarget(this->ReconstructedTexture, width, height, 4,
      floatColor ? VTK_FLOAT : VTK_UNSIGNED_CHAR, false);
  }
  else if (this->ReconstructedTexture)
  {
    DeleteObject(this->ReconstructedTexture, renWin);
    reallocated = true;
  }
  // The area textures (orthogonal and diagonal lines), uploaded once per maximum distance from
  // the shared generator.
  const int maxDistance = this->Options->GetMaxDistance();
  if (!this->AreaTexture || !this->DiagonalAreaTexture ||
    this->AreaTextureMaxDistance != maxDistance)
  {
    auto upload = [renWin](vtkTextureObject*& texture, int width, int components,
                    const std::vector<float>& table) {
      if (texture)
      {
        texture->ReleaseGraphicsResources(renWin);
      }
      else
      {
        texture = NewTexture(renWin);
      }
      texture->SetWrapS(vtkTextureObject::ClampToEdge);
      texture->SetWrapT(vtkTextureObject::ClampToEdge);
      texture->SetMinificationFilter(vtkTextureObject::Nearest);
      texture->SetMagnificationFilter(vtkTextureObject::Nearest);
      texture->Create2DFromRaw(
        width, width, components, VTK_FLOAT, const_cast<float*>(table.data()));
    };
    const int cellSize = maxDistance + 1;
    upload(this->AreaTexture, vtkMLAAAreaTexture::NumberOfCodes * cellSize, 2,
      *vtkMLAAAreaTexture::GetSharedTable(maxDistance));
    upload(this->DiagonalAreaTexture, vtkMLAAAreaTexture::NumberOfDiagonalCodes * cellSize, 3,
      *vtkMLAAAreaTexture::GetSharedDiagonalTable(maxDistance));
    this->AreaTextureMaxDistance = maxDistance;
  }

  return reallocated;
}

//------------------------------------------------------------------------------
namespace
{
// The inverted sRGB transfer function at the 256 values of an 8-bit channel, by the CPU filter's
// conversion (vtkAntialiasingKit::Lab::Linearise), which its tables for 8-bit images use too.
const float* SrgbToLinearTable()
{
  static const std::array<float, 256> table = [] {
    std::array<float, 256> values{};
    for (int i = 0; i < 256; ++i)
    {
      values[i] = vtkAntialiasingKit::Lab::Linearise(static_cast<float>(i) / 255.0f);
    }
    return values;
  }();
  return table.data();
}
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::SetEdgeTextures(vtkShaderProgram* program)
{
  program->SetUniformi("colorTexture", this->GetSourceTexture()->GetTextureUnit());
  if (this->DepthTexture->GetHandle())
  {
    program->SetUniformi("depthTexture", this->DepthTexture->GetTextureUnit());
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::SetEdgeUniforms(vtkShaderProgram* program)
{
  this->SetEdgeTextures(program);
  program->SetUniformf("threshold", static_cast<float>(this->Options->GetThreshold()));
  program->SetUniformf(
    "localContrastFactor", static_cast<float>(this->Options->GetLocalContrastFactor()));
  if (this->UsesSrgbTable())
  {
    program->SetUniform1fv("srgbToLinear", 256, SrgbToLinearTable());
  }
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::ComputeEdgesAndWeights(
  vtkOpenGLRenderWindow* renWin, int width, int height, bool useAlpha, bool markBlended)
{
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLFramebufferObject* fbo = this->WorkFramebuffer;
  this->BeginWorkPass(renWin, this->EdgesTexture, width, height);
  fbo->AddDepthAttachment(this->MaskTexture);

  // The edge shader's variant: what is compared, and whether alpha counts (section 4.2).
  const std::string edgeDefines =
    Define("MLAA_EDGE_DETECTION", this->Options->GetEdgeDetection()) +
    Define("MLAA_USE_ALPHA", useAlpha) + Define("MLAA_SRGB_TABLE", this->UsesSrgbTable());
  {
    // The colour, and the depth, for the three edge passes (their samplers: SetEdgeTextures). The
    // depth copy exists only when the delegate renders into the pass's textures; the shaders read
    // it in depth mode only, which always has it. (Activating a texture that was never allocated
    // fails an assertion in VTK builds that keep them, as ParaView's does.)
    ScopedTextures edgeTextures;
    edgeTextures.Activate(this->GetSourceTexture());
    if (this->DepthTexture->GetHandle())
    {
      edgeTextures.Activate(this->DepthTexture);
    }
    // Pass 0: the change mask. Cleared edges and a mask at 0; pixels that differ from their left
    // or upper neighbour write depth 1, the others keep 0 (with `markBlended`, those that differ
    // from their right or lower neighbour only write 1/4: the blending may change them, and
    // the edge detection finds nothing there).
    BeginDepthMask(ostate);
    // The mask compares whole pixels (and depths in depth mode): neither alpha's part nor the
    // threshold and Lab's table matter to it.
    if (!this->ReadyQuad(renWin, this->ChangeMaskQuad, vtkMLAAEdgeDetectionFS,
          Define("MLAA_EDGE_DETECTION", this->Options->GetEdgeDetection()) +
            Define("MLAA_CHANGE_MASK", true) + Define("MLAA_MARK_BLENDED", markBlended)))
    {
      return false;
    }
    vtkShaderProgram* program = this->ChangeMaskQuad.Quad->Program;
    this->SetEdgeTextures(program);
    ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    {
      TimedStage stage(renWin, "change mask");
      this->ChangeMaskQuad.Quad->Render();
    }
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    // Pass 1: edges, on the marked pixels only (the quad's depth, 1/2, is less than 1 there and not
    // less than 0 elsewhere, so the depth test rejects unchanged pixels before the shader runs);
    // edge pixels write the quad's depth.
    ostate->vtkglDepthFunc(GL_LESS);
    if (!this->ReadyQuad(renWin, this->EdgesQuad, vtkMLAAEdgeDetectionFS, edgeDefines))
    {
      return false;
    }
    program = this->EdgesQuad.Quad->Program;
    this->SetEdgeUniforms(program);
    {
      TimedStage stage(renWin, "edges");
      this->EdgesQuad.Quad->Render();
    }

    // Local contrast adaptation: the edge pixels (those whose mask depth was written) rewrite
    // their edges, keeping those not much weaker than their neighbours.
    ostate->vtkglDepthMask(GL_FALSE);
    ostate->vtkglDepthFunc(GL_EQUAL);
    if (this->Options->GetLocalContrastFactor() > 0.0)
    {
      if (!this->ReadyQuad(renWin, this->LocalContrastQuad, vtkMLAAEdgeDetectionFS,
            edgeDefines + Define("MLAA_LOCAL_CONTRAST", true)))
      {
        return false;
      }
      program = this->LocalContrastQuad.Quad->Program;
      this->SetEdgeUniforms(program);
      TimedStage stage(renWin, "local contrast");
      this->LocalContrastQuad.Quad->Render();
    }
  }

  // Line lengths by recursive doubling (LineLengths), and the counts of staircase units with
  // diagonal detection, on the same pixels.
  vtkTextureObject* lengths = nullptr;
  if (this->GetUsesRecursiveDoubling())
  {
    TimedStage stage(renWin, "line lengths");
    if (!this->CountLines(renWin, lengths))
    {
      return false;
    }
  }
  const bool staircaseCounts = this->GetCountsStaircases();

  // Pass 2: blending weights, on the pixels whose mask depth was written only.
  fbo->AddColorAttachment(0, this->WeightsTexture);
  DrawToAttachments(fbo, 1);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  // A sample set of a multisampled render (SampleAreas): the areas of its sample's offsets.
  const SampleSet& set = this->GetCurrentSampleSet();
  const bool sampleAreas = this->SampleAreas && set.Index >= 0 && set.Colors;
  if (sampleAreas)
  {
    this->PrepareSampleAreas(renWin, set);
  }
  else if (this->SampleAreaTexture && set.Index < 0) // a single-sample render: not kept
  {
    DeleteObject(this->SampleAreaTexture, renWin);
    this->SampleAreaOffsets.clear();
  }
  // The search length and the diagonal patterns are compile-time: constant loop bounds, and no
  // diagonal code at all without DiagonalDetection (section 4.3).
  const std::string weightsDefines =
    Define("MLAA_MAX_SEARCH_STEPS", this->Options->GetMaxSearchSteps()) +
    Define("MLAA_DIAGONAL_DETECTION", this->Options->GetDiagonalDetection()) +
    Define("MLAA_CORNER_EXTRAPOLATION", this->Options->GetCornerExtrapolation()) +
    Define("MLAA_MINIMUM_DIAGONAL_LENGTH", vtkMLAAOptions::MinimumDiagonalLength) +
    Define("MLAA_RECURSIVE_DOUBLING", lengths != nullptr) +
    (staircaseCounts ? Define("MLAA_STAIRCASE_REACH", this->GetStaircaseCountReach())
                     : std::string()) +
    Define("MLAA_SAMPLE_AREAS", sampleAreas) +
    (sampleAreas && set.Shaded
        ? Define("MLAA_SAMPLES_SHADED", static_cast<int>(set.Offsets.size() / 2))
        : std::string());
  if (!this->ReadyQuad(renWin, this->WeightsQuad, vtkMLAABlendingWeightsFS, weightsDefines))
  {
    return false;
  }
  vtkShaderProgram* program = this->WeightsQuad.Quad->Program;
  ScopedTextures textures(program,
    { { "edgesTexture", this->EdgesTexture }, { "areaTexture", this->AreaTexture },
      { "diagonalAreaTexture", this->DiagonalAreaTexture } });
  if (sampleAreas)
  {
    textures.Bind(program, "sampleAreaTexture", this->SampleAreaTexture);
    textures.Bind(program, "samplesColor", set.Colors);
    program->SetUniformi("numberOfSamples", static_cast<int>(set.Offsets.size() / 2));
    program->SetUniformi("sampleIndex", set.Index);
    // How near a pixel's border its samples come (the edge between two pixels whose samples
    // all agree lies within this of the border).
    double gap = 0.5;
    for (double offset : set.Offsets)
    {
      gap = std::min(gap, 0.5 - std::abs(offset));
    }
    program->SetUniformf("sampleGap", static_cast<float>(gap));
    if (set.Shaded)
    {
      const std::vector<float> offsets(set.Offsets.begin(), set.Offsets.end());
      program->SetUniform2fv(
        "sampleOffsets", static_cast<int>(offsets.size() / 2), offsets.data());
    }
  }
  if (lengths)
  {
    textures.Bind(program, "lengthsTexture", lengths);
  }
  if (staircaseCounts)
  {
    textures.Bind(program, "staircaseCountsTexture", this->StaircaseCountsTexture);
  }
  {
    TimedStage stage(renWin, "blending weights");
    this->WeightsQuad.Quad->Render();
  }
  ostate->vtkglDepthMask(GL_TRUE);
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::PrepareSampleAreas(vtkOpenGLRenderWindow* renWin, const SampleSet& set)
{
  const int maxDistance = this->Options->GetMaxDistance();
  if (this->SampleAreaTexture && this->SampleAreaMaxDistance == maxDistance &&
    this->SampleAreaOffsets == set.Offsets)
  {
    return;
  }
  // Per sample (offset x, y from the pixel centre), the line moved by it: across a horizontal
  // line towards the edgel's opposite pixel is +y, along it (towards its second end) +x; across
  // a vertical line -x (the opposite pixel is to the left), along it -y (its first end is the
  // upper one).
  const int size = vtkMLAAAreaTexture::NumberOfCodes * (maxDistance + 1);
  const size_t tableSize = static_cast<size_t>(size) * size * 2;
  const size_t samples = set.Offsets.size() / 2;
  std::vector<float> stacked;
  stacked.reserve(2 * samples * tableSize);
  for (size_t s = 0; s < samples; ++s)
  {
    const double x = set.Offsets[2 * s], y = set.Offsets[2 * s + 1];
    for (const auto& offset : { std::make_pair(y, x), std::make_pair(-x, -y) })
    {
      const auto table =
        vtkMLAAAreaTexture::GetSharedTable(maxDistance, offset.first, offset.second);
      stacked.insert(stacked.end(), table->begin(), table->end());
    }
  }
  if (this->SampleAreaTexture)
  {
    this->SampleAreaTexture->ReleaseGraphicsResources(renWin);
  }
  else
  {
    this->SampleAreaTexture = NewTexture(renWin);
  }
  vtkTextureObject* texture = this->SampleAreaTexture;
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->Create2DFromRaw(size, static_cast<unsigned int>(2 * samples * size), 2, VTK_FLOAT,
    stacked.data());
  this->SampleAreaOffsets = set.Offsets;
  this->SampleAreaMaxDistance = maxDistance;
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::CountLines(vtkOpenGLRenderWindow* renWin, vtkTextureObject*& lengths)
{
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLFramebufferObject* fbo = this->WorkFramebuffer;
  const bool staircases = this->GetCountsStaircases();
  // Every texture of the doubling starts at 0: the passes write the edge pixels only, and the
  // jumps land on pixels without an edge too, which must read 0. (The counts of staircase units
  // need no clearing: the weights pass reads those of units only, which are edge pixels.)
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  fbo->AddColorAttachment(0, this->LengthsTextures[0]);
  DrawToAttachments(fbo, 1);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  fbo->AddColorAttachment(0, this->LengthsTextures[1]);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);

  // Initialisation: the 0/1 flags of every direction into LengthsTextures[1], and the counts of
  // staircase units into StaircaseCountsTexture.
  if (staircases)
  {
    fbo->AddColorAttachment(1, this->StaircaseCountsTexture);
    DrawToAttachments(fbo, 2);
  }
  if (!this->ReadyQuad(renWin, this->LengthsInitQuad, vtkMLAALineLengthsInitFS,
        staircases ? Define("MLAA_STAIRCASE_COUNTS", true) +
            Define("MLAA_STAIRCASE_REACH", this->GetStaircaseCountReach())
                   : std::string()))
  {
    return false;
  }
  {
    const ScopedTextures edges(
      this->LengthsInitQuad.Quad->Program, { { "edgesTexture", this->EdgesTexture } });
    this->LengthsInitQuad.Quad->Render();
  }
  if (staircases)
  {
    fbo->RemoveColorAttachment(1);
  }

  // Doubling passes for levels 1, 4, 16, ... until the counts are exact up to the maximum
  // distance (4 level >= maximum distance), reading one texture and writing the other.
  if (!this->ReadyQuad(renWin, this->LengthsQuad, vtkMLAALineLengthsFS, std::string()))
  {
    return false;
  }
  vtkShaderProgram* program = this->LengthsQuad.Quad->Program;
  const int maxDistance = this->Options->GetMaxDistance();
  int source = 1;
  for (int level = 1; level < maxDistance; level *= 4)
  {
    fbo->AddColorAttachment(0, this->LengthsTextures[1 - source]);
    DrawToAttachments(fbo, 1);
    const ScopedTextures read(program, { { "lengthsTexture", this->LengthsTextures[source] } });
    program->SetUniformf("level", static_cast<float>(level));
    this->LengthsQuad.Quad->Render();
    source = 1 - source;
  }
  lengths = this->LengthsTextures[source];
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::GetCountsStaircases()
{
  return this->GetUsesRecursiveDoubling() && this->Options->GetDiagonalDetection();
}

//------------------------------------------------------------------------------
int vtkOpenGLMLAAPass::GetStaircaseCountReach()
{
  // A unit reads about 2 reach units when counting and 2 maximum distance / reach counts when
  // following its staircase both ways: least at the square root of the maximum distance.
  const int reach =
    static_cast<int>(std::lround(std::sqrt(static_cast<double>(this->Options->GetMaxDistance()))));
  return std::min(std::max(reach, 2), 15); // 15: two counts are packed in a byte
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::Blend(vtkOpenGLRenderWindow* renWin, int x, int y, int width,
  int height, bool composite, bool straightAlpha, bool inPlace, bool throughTexture,
  vtkOpenGLFramebufferObject* ownTarget)
{
  const std::string blendDefines =
    Define("MLAA_DEBUG_OUTPUT", this->Options->GetDebugOutput()) +
    Define("MLAA_DOMINANT_DIRECTION", this->Options->GetDominantDirectionBlending()) +
    Define("MLAA_STRAIGHT_ALPHA", straightAlpha) + Define("MLAA_IN_PLACE", inPlace);
  if (!this->ReadyQuad(renWin, this->BlendQuad, vtkMLAANeighborhoodBlendingFS, blendDefines))
  {
    return false;
  }
  if (throughTexture)
  {
    // (Sets its own state: it draws into a texture and copies the result.)
    return this->BlendThroughTexture(renWin, x, y, width, height, ownTarget);
  }
  // Premultiplied "over" onto what lower layers drew (a debug output replaces them); in place,
  // the target already holds the delegate's image and depth: only the blended pixels are
  // written, and no depth; otherwise the delegate's depth is copied.
  SetTargetWriteState(renWin->GetState(), x, y, width, height,
    composite && this->Options->GetDebugOutput() == vtkMLAAOptions::NO_DEBUG_OUTPUT, !inPlace);
  vtkShaderProgram* program = this->BlendQuad.Quad->Program;
  ScopedTextures textures(program,
    { { "colorTexture", this->GetSourceTexture() }, { "edgesTexture", this->EdgesTexture },
      { "weightsTexture", this->WeightsTexture } });
  if (!inPlace)
  {
    textures.Bind(program, "depthTexture", this->DepthTexture);
  }
  TimedStage stage(renWin, "neighbourhood blending");
  this->BlendQuad.Quad->Render();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::BlendThroughTexture(vtkOpenGLRenderWindow* renWin, int x, int y,
  int width, int height, vtkOpenGLFramebufferObject* ownTarget)
{
  // The blending shader discards the pixels without a weight, but rasterisers that shade pixels
  // in lock-step (llvmpipe) still write, masked, every pixel of the target that the quad covers:
  // most of the pass's time on llvmpipe. A depth test before the shader runs drops whole groups
  // instead, and the mask that gives it is ours, not the target's: so the source image is copied
  // into BlendedTexture, the blending drawn there on the pixels the change mask marked (any pixel
  // next to an edge differs from the pixel across it), and the result copied into the target.
  // Same image: the pixels left out are those without a weight, which the blending keeps. A
  // target of the pass's own takes the mask as its depth for the draw instead: no copies.
  vtkOpenGLState* ostate = renWin->GetState();
  unsigned int targetBinding = 0, targetBuffer = 0;
  ostate->GetCurrentDrawFramebufferState(targetBinding, targetBuffer);
  vtkTextureObject* source = this->GetSourceTexture();
  TimedStage stage(renWin, "neighbourhood blending");
  ostate->PushFramebufferBindings();
  // Copies are clipped by the scissor test.
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  vtkOpenGLFramebufferObject* fbo = ownTarget;
  const int box[4] = { 0, width, 0, height };
  if (!fbo)
  {
    if (!this->BlendedTexture)
    {
      this->BlendedTexture = NewTexture(renWin);
    }
    AllocateColorTarget(this->BlendedTexture, width, height, 4, source->GetVTKDataType(), false);
    fbo = this->WorkFramebuffer;
    fbo->Bind();
    fbo->AddColorAttachment(0, this->BlendedTexture);
    fbo->AddColorAttachment(1, source);
    fbo->ActivateReadBuffer(1);
    // (One draw buffer, set past VTK's state cache: a copy writes every draw buffer, and after the
    // line lengths' two outputs attachment 1 would be the source itself.)
    DrawToAttachments(fbo, 1);
    vtkOpenGLFramebufferObject::Blit(box, box, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    fbo->RemoveColorAttachment(1); // (not attached while the blending reads it)
    ostate->vtkglViewport(0, 0, width, height);
  }
  else
  {
    fbo->Bind();
    ostate->vtkglViewport(x, y, width, height);
  }
  fbo->AddDepthAttachment(this->MaskTexture);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglDepthFunc(GL_LESS);
  {
    // The quad at depth 0 (not tracked by vtkOpenGLState, so restored at once): the test passes
    // on every marked pixel (depth 1/4, 1/2 or 1), not on the unmarked ones (0).
    glDepthRange(0.0, 0.0);
    vtkShaderProgram* program = this->BlendQuad.Quad->Program;
    const ScopedTextures textures(program,
      { { "colorTexture", source }, { "edgesTexture", this->EdgesTexture },
        { "weightsTexture", this->WeightsTexture } });
    this->BlendQuad.Quad->Render();
    glDepthRange(0.0, 1.0);
  }
  ostate->vtkglDisable(GL_DEPTH_TEST);
  fbo->RemoveDepthAttachment();
  if (!ownTarget)
  {
    fbo->ActivateReadBuffer(0);
    ostate->vtkglBindFramebuffer(GL_DRAW_FRAMEBUFFER, targetBinding);
    ostate->vtkglDrawBuffer(targetBuffer);
    const int target[4] = { x, x + width, y, y + height };
    vtkOpenGLFramebufferObject::Blit(box, target, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  ostate->PopFramebufferBindings();
  return true;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkOpenGLMLAAPass::GetSourceTexture()
{
  return this->Options->GetReconstruction() && this->ReconstructedTexture
    ? this->ReconstructedTexture
    : this->ColorTexture;
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::SetReconstructionUniforms(vtkShaderProgram* program)
{
  program->SetUniformi("colorTexture", this->ColorTexture->GetTextureUnit());
  program->SetUniformf("threshold", static_cast<float>(this->Options->GetThreshold()));
  // The selection rule of section 4.2 from its one generator, as 256 bits.
  unsigned int bits[8];
  vtkMLAATopology::GetSelectionBits(bits);
  int words[8];
  for (int i = 0; i < 8; ++i)
  {
    words[i] = static_cast<int>(bits[i]);
  }
  program->SetUniform1iv("selectionTable", 8, words);
  // The coverage rule's window and shares, from the same generator.
  static_assert(vtkMLAATopology::CoverageTableSize == 49,
    "coverageTable and lineShareTable in vtkMLAAReconstructionFS.glsl hold 49 entries");
  program->SetUniformi("coverageRadius", vtkMLAATopology::CoverageRadius);
  program->SetUniform1fv(
    "coverageTable", vtkMLAATopology::CoverageTableSize, vtkMLAATopology::GetCoverageTable());
  program->SetUniform1fv(
    "lineShareTable", vtkMLAATopology::CoverageTableSize, vtkMLAATopology::GetLineShareTable());
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::Reconstruct(
  vtkOpenGLRenderWindow* renWin, int width, int height, bool useAlpha)
{
  this->BeginWorkPass(renWin, this->ReconstructedTexture, width, height);
  renWin->GetState()->vtkglDisable(GL_DEPTH_TEST);
  if (!this->ReadyQuad(renWin, this->ReconstructionQuad, vtkMLAAReconstructionFS,
        Define("MLAA_USE_ALPHA", useAlpha)))
  {
    return false;
  }
  ScopedTextures textures;
  textures.Activate(this->ColorTexture);
  this->SetReconstructionUniforms(this->ReconstructionQuad.Quad->Program);
  TimedStage stage(renWin, "reconstruction");
  this->ReconstructionQuad.Quad->Render();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::WriteBackReconstruction(
  vtkOpenGLRenderWindow* renWin, int x, int y, int width, int height, bool useAlpha)
{
  // The target holds the delegate's image; the blending writes back only the pixels it
  // blends, so the reconstructed ones are written here first (the others are discarded).
  vtkOpenGLState* ostate = renWin->GetState();
  ostate->vtkglViewport(x, y, width, height);
  ostate->vtkglScissor(x, y, width, height);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (!this->ReadyQuad(renWin, this->WriteBackQuad, vtkMLAAReconstructionFS,
        Define("MLAA_USE_ALPHA", useAlpha) + Define("MLAA_WRITE_BACK", true)))
  {
    return false;
  }
  ScopedTextures textures;
  textures.Activate(this->ColorTexture);
  this->SetReconstructionUniforms(this->WriteBackQuad.Quad->Program);
  TimedStage stage(renWin, "reconstruction write-back");
  this->WriteBackQuad.Quad->Render();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::UsesSrgbTable()
{
  // CIELAB edges on an 8-bit image: each channel is k / 255, so its linear value is read from a
  // table of 256 instead of computed with a pow (on llvmpipe, a sixth of the pass's time with the
  // defaults at 1920 x 1080).
  return this->Options->GetEdgeDetection() == vtkMLAAOptions::LAB &&
    this->GetSourceTexture()->GetVTKDataType() == VTK_UNSIGNED_CHAR;
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::NeedsDelegateDepth()
{
  // Depth edges read the delegate's depth as a texture.
  return this->Options->GetEdgeDetection() == vtkMLAAOptions::DEPTH;
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::UsesStraightAlpha()
{
  return !this->Options->GetPremultipliedAlpha();
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::DrawsDeferredOverlays()
{
  // Not over a debug image.
  return this->Options->GetDebugOutput() == vtkMLAAOptions::NO_DEBUG_OUTPUT;
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::SubstituteShaderSnippets(std::string& source)
{
  // The CIELAB conversion shared by the shaders that compare colours in Lab.
  vtkShaderProgram::Substitute(source, "//VTK::MLAA::Lab", vtkMLAALab, false);
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::Antialias(const Frame& frame)
{
  // The render targets, the delegate's render, the saved state and the overlays are
  // vtkOpenGLAntialiasingPass's; this is the MLAA part of the render.
  vtkOpenGLRenderWindow* renWin = frame.Window;
  vtkOpenGLState* ostate = renWin->GetState();
  const int x = frame.X, y = frame.Y, width = frame.Width, height = frame.Height;
  const bool composite = frame.Composite, useAlpha = frame.UseAlpha,
             straightAlpha = frame.StraightAlpha, inPlace = frame.InPlace;
  // In place, the blending is drawn into a texture on the pixels the change mask marked, and the
  // image copied into the target (BlendThroughTexture), unless a debug image is shown or the
  // target is multisampled (a copy cannot be written into it).
  GLint targetSamples = 0;
  glGetIntegerv(GL_SAMPLE_BUFFERS, &targetSamples);
  const bool throughTexture = inPlace && targetSamples == 0 &&
    this->Options->GetDebugOutput() == vtkMLAAOptions::NO_DEBUG_OUTPUT;
  {
    // Topological reconstruction (Biri et al., section 4.3): before edge detection, into
    // ReconstructedTexture, which the later passes read instead of ColorTexture.
    const bool reconstruction = this->Options->GetReconstruction();
    ostate->PushFramebufferBindings();
    bool computed = !reconstruction || this->Reconstruct(renWin, width, height, useAlpha);
    computed = computed &&
      this->ComputeEdgesAndWeights(renWin, width, height, useAlpha, throughTexture);
    ostate->PopFramebufferBindings();
    // (Through the texture, the copy takes the reconstructed pixels into the target.)
    if (computed && reconstruction && inPlace && !throughTexture &&
      this->Options->GetDebugOutput() == vtkMLAAOptions::NO_DEBUG_OUTPUT)
    {
      computed = this->WriteBackReconstruction(renWin, x, y, width, height, useAlpha);
    }
    return computed &&
      this->Blend(renWin, x, y, width, height, composite, straightAlpha, inPlace, throughTexture,
        frame.OwnTarget);
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::ReleaseMethodResources(vtkWindow* w)
{
  for (ShaderVariant* variant : { &this->ReconstructionQuad, &this->WriteBackQuad,
         &this->ChangeMaskQuad, &this->EdgesQuad, &this->LocalContrastQuad, &this->WeightsQuad,
         &this->BlendQuad,
         &this->LengthsInitQuad, &this->LengthsQuad })
  {
    variant->Release(w);
  }
  for (vtkTextureObject** texture : { &this->EdgesTexture, &this->WeightsTexture,
         &this->MaskTexture, &this->AreaTexture,
         &this->DiagonalAreaTexture, &this->LengthsTextures[0], &this->LengthsTextures[1],
         &this->StaircaseCountsTexture,
         &this->ReconstructedTexture, &this->SampleAreaTexture, &this->BlendedTexture })
  {
    DeleteObject(*texture, w);
  }
  this->AreaTextureMaxDistance = 0;
  this->SampleAreaOffsets.clear();
  this->SampleAreaMaxDistance = 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLMLAAPass::GetMLAATargetMemorySize()
{
  return TextureBytes(this->EdgesTexture, 2) + TextureBytes(this->WeightsTexture, 4);
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLMLAAPass::GetTargetMemorySize()
{
  return this->Superclass::GetTargetMemorySize();
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLMLAAPass::GetMethodTargetMemorySize()
{
  const int colorBytes = (this->ColorTexture && this->ColorTexture->GetVTKDataType() == VTK_FLOAT)
    ? 16
    : 4;
  return TextureBytes(this->ReconstructedTexture, colorBytes) +
    TextureBytes(this->BlendedTexture, colorBytes) + this->GetMLAATargetMemorySize() +
    TextureBytes(this->MaskTexture, 2) +
    TextureBytes(this->AreaTexture, 8) + TextureBytes(this->DiagonalAreaTexture, 12) +
    TextureBytes(this->LengthsTextures[0], 8) + TextureBytes(this->LengthsTextures[1], 8) +
    TextureBytes(this->StaircaseCountsTexture, 2) + TextureBytes(this->SampleAreaTexture, 8);
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::GetUsesRecursiveDoubling()
{
  switch (this->LineLengths)
  {
    case SEARCH_LOOP:
      return false;
    case RECURSIVE_DOUBLING:
      return true;
    default:
      return this->Options->GetCountsExactLineLengths();
  }
}

//------------------------------------------------------------------------------
const char* vtkOpenGLMLAAPass::GetLineLengthsAsString(int method)
{
  switch (method)
  {
    case AUTOMATIC:
      return "AUTOMATIC";
    case SEARCH_LOOP:
      return "SEARCH_LOOP";
    case RECURSIVE_DOUBLING:
      return "RECURSIVE_DOUBLING";
    default:
      return "unknown";
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LineLengths: " << GetLineLengthsAsString(this->LineLengths) << "\n";
  os << indent << "SampleAreas: " << (this->SampleAreas ? "On" : "Off") << "\n";
  os << indent << "Options:\n";
  this->Options->PrintSelf(os, indent.GetNextIndent());
}
