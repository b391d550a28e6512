#include "vtkOpenGLMLAAPass.h"

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

#include <string>

#include "vtk_glew.h" // For GL enums only: every call goes through VTK's classes

vtkStandardNewMacro(vtkOpenGLMLAAPass);

namespace
{
// Makes `texture` a 2D texture of the given size, components and type: resized in place (same GL
// handle, so framebuffer attachments stay valid) when only the size differs, allocated afresh
// otherwise. Returns true when the texture was allocated afresh (its handle changed).
bool AllocateColorTarget(vtkTextureObject* texture, int width, int height, int components,
  int vtkType, bool linear)
{
  const bool sameFormat = texture->GetHandle() && texture->GetComponents() == components &&
    texture->GetVTKDataType() == vtkType;
  if (sameFormat)
  {
    if (texture->GetWidth() != static_cast<unsigned int>(width) ||
      texture->GetHeight() != static_cast<unsigned int>(height))
    {
      texture->Resize(width, height);
    }
    return false;
  }
  texture->ReleaseGraphicsResources(texture->GetContext());
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
  texture->Allocate2D(width, height, components, vtkType);
  return true;
}

// The same for a depth texture.
bool AllocateDepthTarget(vtkTextureObject* texture, int width, int height, int format)
{
  if (texture->GetHandle())
  {
    if (texture->GetWidth() != static_cast<unsigned int>(width) ||
      texture->GetHeight() != static_cast<unsigned int>(height))
    {
      texture->Resize(width, height);
    }
    return false;
  }
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->AllocateDepth(width, height, format);
  return true;
}

// The same for a line-lengths texture: RGBA16F (integers up to 2048 exactly), nearest.
bool AllocateLengthsTarget(vtkTextureObject* texture, int width, int height)
{
  if (texture->GetHandle())
  {
    if (texture->GetWidth() != static_cast<unsigned int>(width) ||
      texture->GetHeight() != static_cast<unsigned int>(height))
    {
      texture->Resize(width, height);
    }
    return false;
  }
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetInternalFormat(GL_RGBA16F);
  texture->Allocate2D(width, height, 4, VTK_FLOAT);
  return true;
}

vtkTextureObject* NewTexture(vtkOpenGLRenderWindow* renWin)
{
  vtkTextureObject* texture = vtkTextureObject::New();
  texture->SetContext(renWin);
  return texture;
}

vtkIdType TextureBytes(vtkTextureObject* texture, int bytesPerTexel)
{
  return texture && texture->GetHandle()
    ? static_cast<vtkIdType>(texture->GetWidth()) * texture->GetHeight() * bytesPerTexel
    : 0;
}

// One #define line of a shader variant.
std::string Define(const char* name, int value)
{
  return std::string("#define ") + name + " " + std::to_string(value) + "\n";
}
std::string Define(const char* name, bool defined)
{
  return defined ? std::string("#define ") + name + "\n" : std::string();
}

template <typename T>
void DeleteObject(T*& object, vtkWindow* w)
{
  if (object)
  {
    object->ReleaseGraphicsResources(w);
    object->Delete();
    object = nullptr;
  }
}
}

//------------------------------------------------------------------------------
vtkOpenGLMLAAPass::vtkOpenGLMLAAPass()
{
  this->Options = vtkMLAAOptions::New();
}

//------------------------------------------------------------------------------
vtkOpenGLMLAAPass::~vtkOpenGLMLAAPass()
{
  if (this->ColorTexture || this->EdgesQuad.Quad || this->DelegateFramebuffer)
  {
    vtkErrorMacro("Graphics resources should have been released by ReleaseGraphicsResources().");
  }
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
void vtkOpenGLMLAAPass::PrepareTargets(
  vtkOpenGLRenderWindow* renWin, int width, int height, bool floatColor, bool depth)
{
  for (vtkTextureObject** texture : { &this->ColorTexture, &this->DepthTexture,
         &this->EdgesTexture, &this->WeightsTexture, &this->MaskTexture })
  {
    if (!*texture)
    {
      *texture = NewTexture(renWin);
    }
  }
  bool reallocated = AllocateColorTarget(
    this->ColorTexture, width, height, 4, floatColor ? VTK_FLOAT : VTK_UNSIGNED_CHAR, false);
  if (depth)
  {
    // 24-bit depth, as a window's depth buffer, so the delegate renders as it would in the
    // window.
    reallocated |=
      AllocateDepthTarget(this->DepthTexture, width, height, vtkTextureObject::Fixed24);
  }
  else if (this->DepthTexture->GetHandle())
  {
    this->DepthTexture->ReleaseGraphicsResources(renWin); // not needed in place
    reallocated = true;
  }
  // Linear filtering: the search and the crossing-edge reads rely on it (section 4.3).
  reallocated |= AllocateColorTarget(this->EdgesTexture, width, height, 2, VTK_UNSIGNED_CHAR, true);
  // 8-bit weights, as the chapter's RGBA8 texture (vtkImageMLAA quantises the same way).
  reallocated |=
    AllocateColorTarget(this->WeightsTexture, width, height, 4, VTK_UNSIGNED_CHAR, false);
  reallocated |= AllocateDepthTarget(this->MaskTexture, width, height, vtkTextureObject::Fixed16);
  if (this->GetUsesRecursiveDoubling())
  {
    for (vtkTextureObject*& lengths : this->LengthsTextures)
    {
      if (!lengths)
      {
        lengths = NewTexture(renWin);
      }
      reallocated |= AllocateLengthsTarget(lengths, width, height);
    }
  }
  else
  {
    // Not needed by the search loop: not kept (and no framebuffer keeps them attached).
    for (vtkTextureObject*& lengths : this->LengthsTextures)
    {
      reallocated |= lengths != nullptr;
      DeleteObject(lengths, renWin);
    }
  }
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
  if (reallocated)
  {
    // Framebuffer objects remember their attachments: start afresh with the new textures.
    DeleteObject(this->DelegateFramebuffer, renWin);
    DeleteObject(this->MLAAFramebuffer, renWin);
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

  if (!this->DelegateFramebuffer)
  {
    this->DelegateFramebuffer = vtkOpenGLFramebufferObject::New();
    this->DelegateFramebuffer->SetContext(renWin);
  }
  if (!this->MLAAFramebuffer)
  {
    this->MLAAFramebuffer = vtkOpenGLFramebufferObject::New();
    this->MLAAFramebuffer->SetContext(renWin);
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::RenderDelegateToTextures(
  const vtkRenderState* s, int width, int height, bool composite)
{
  vtkOpenGLState* ostate = this->DelegateFramebuffer->GetContext()->GetState();
  vtkRenderState delegateState(s->GetRenderer());
  delegateState.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  delegateState.SetRequiredKeys(s->GetRequiredKeys());
  delegateState.SetFrameBuffer(this->DelegateFramebuffer);

  this->DelegateFramebuffer->Bind();
  this->DelegateFramebuffer->AddColorAttachment(0, this->ColorTexture);
  this->DelegateFramebuffer->ActivateDrawBuffer(0);
  this->DelegateFramebuffer->AddDepthAttachment(this->DepthTexture);
  this->DelegateFramebuffer->StartNonOrtho(width, height);
  ostate->vtkglViewport(0, 0, width, height);
  ostate->vtkglScissor(0, 0, width, height);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  if (composite)
  {
    // The renderer preserves the colour buffer, so it will not clear this one: start from
    // transparent black. VTK's blending (source alpha, one minus source alpha for colour; one,
    // one minus source alpha for alpha) then leaves premultiplied colour here.
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  }

  this->DelegatePass->Render(&delegateState);
  this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::CopyTargetToColorTexture(vtkOpenGLRenderWindow* renWin,
  unsigned int targetBinding, unsigned int targetBuffer, int x, int y, int width, int height)
{
  vtkOpenGLState* ostate = renWin->GetState();
  this->DelegateFramebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  this->DelegateFramebuffer->AddColorAttachment(0, this->ColorTexture);
  this->DelegateFramebuffer->ActivateDrawBuffer(0);
  ostate->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, targetBinding);
  ostate->vtkglReadBuffer(targetBuffer);
  const int source[4] = { x, x + width, y, y + height };
  const int destination[4] = { 0, width, 0, height };
  vtkOpenGLFramebufferObject::Blit(source, destination, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::ShaderVariant::Release(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    delete this->Quad;
    this->Quad = nullptr;
  }
  this->Defines.clear();
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::ReadyQuad(vtkOpenGLRenderWindow* renWin, ShaderVariant& variant,
  const char* fs, const std::string& defines)
{
  if (variant.Quad && variant.Defines != defines)
  {
    // The options changed what the shader does: build the other variant (the shader cache
    // keeps the programs, so switching back is cheap).
    variant.Release(renWin);
  }
  vtkOpenGLQuadHelper*& quad = variant.Quad;
  if (!quad)
  {
    std::string source = fs;
    vtkShaderProgram::Substitute(source, "//VTK::MLAA::Dec", defines, false);
    // The CIELAB conversion shared by the shaders that compare colours in Lab.
    vtkShaderProgram::Substitute(source, "//VTK::MLAA::Lab", vtkMLAALab, false);
    quad = new vtkOpenGLQuadHelper(renWin, nullptr, source.c_str(), "");
    variant.Defines = defines;
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  if (!quad->Program || !quad->Program->GetCompiled())
  {
    vtkErrorMacro("Could not build an MLAA shader program.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::SetEdgeUniforms(vtkShaderProgram* program)
{
  program->SetUniformi("colorTexture", this->GetSourceTexture()->GetTextureUnit());
  program->SetUniformi("depthTexture", this->DepthTexture->GetTextureUnit());
  program->SetUniformf("threshold", static_cast<float>(this->Options->GetThreshold()));
  program->SetUniformf(
    "localContrastFactor", static_cast<float>(this->Options->GetLocalContrastFactor()));
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::ComputeEdgesAndWeights(
  vtkOpenGLRenderWindow* renWin, int width, int height, bool useAlpha)
{
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLFramebufferObject* fbo = this->MLAAFramebuffer;
  fbo->Bind();
  fbo->AddColorAttachment(0, this->EdgesTexture);
  fbo->ActivateDrawBuffer(0);
  fbo->AddDepthAttachment(this->MaskTexture);
  fbo->StartNonOrtho(width, height);
  ostate->vtkglViewport(0, 0, width, height);
  ostate->vtkglScissor(0, 0, width, height);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

  // Pass 1: edges. Cleared edges and a far mask; edge pixels write the quad's depth.
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglClearDepth(1.0);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  // The edge shader's variant: what is compared, and whether alpha counts (section 4.2).
  const std::string edgeDefines =
    Define("MLAA_EDGE_DETECTION", this->Options->GetEdgeDetection()) +
    Define("MLAA_USE_ALPHA", useAlpha);
  if (!this->ReadyQuad(renWin, this->EdgesQuad, vtkMLAAEdgeDetectionFS, edgeDefines))
  {
    return false;
  }
  vtkShaderProgram* program = this->EdgesQuad.Quad->Program;
  vtkTextureObject* source = this->GetSourceTexture();
  source->Activate();
  this->DepthTexture->Activate();
  this->SetEdgeUniforms(program);
  this->EdgesQuad.Quad->Render();

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
    this->LocalContrastQuad.Quad->Render();
  }
  this->DepthTexture->Deactivate();
  source->Deactivate();

  // Line lengths by recursive doubling (LineLengths), on the same pixels.
  vtkTextureObject* lengths = nullptr;
  if (this->GetUsesRecursiveDoubling())
  {
    lengths = this->ComputeLineLengths(renWin);
    if (!lengths)
    {
      return false;
    }
  }

  // Pass 2: blending weights, on the pixels whose mask depth was written only.
  fbo->AddColorAttachment(0, this->WeightsTexture);
  fbo->ActivateDrawBuffer(0);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  // The search length and the diagonal patterns are compile-time: constant loop bounds, and no
  // diagonal code at all without DiagonalDetection (section 4.3).
  const std::string weightsDefines =
    Define("MLAA_MAX_SEARCH_STEPS", this->Options->GetMaxSearchSteps()) +
    Define("MLAA_DIAGONAL_DETECTION", this->Options->GetDiagonalDetection()) +
    Define("MLAA_MINIMUM_DIAGONAL_LENGTH", vtkMLAAOptions::MinimumDiagonalLength) +
    Define("MLAA_RECURSIVE_DOUBLING", lengths != nullptr);
  if (!this->ReadyQuad(renWin, this->WeightsQuad, vtkMLAABlendingWeightsFS, weightsDefines))
  {
    return false;
  }
  program = this->WeightsQuad.Quad->Program;
  this->EdgesTexture->Activate();
  this->AreaTexture->Activate();
  this->DiagonalAreaTexture->Activate();
  program->SetUniformi("edgesTexture", this->EdgesTexture->GetTextureUnit());
  program->SetUniformi("areaTexture", this->AreaTexture->GetTextureUnit());
  program->SetUniformi("diagonalAreaTexture", this->DiagonalAreaTexture->GetTextureUnit());
  if (lengths)
  {
    lengths->Activate();
    program->SetUniformi("lengthsTexture", lengths->GetTextureUnit());
  }
  this->WeightsQuad.Quad->Render();
  if (lengths)
  {
    lengths->Deactivate();
  }
  this->DiagonalAreaTexture->Deactivate();
  this->AreaTexture->Deactivate();
  this->EdgesTexture->Deactivate();
  ostate->vtkglDepthMask(GL_TRUE);
  return true;
}

//------------------------------------------------------------------------------
vtkTextureObject* vtkOpenGLMLAAPass::ComputeLineLengths(vtkOpenGLRenderWindow* renWin)
{
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLFramebufferObject* fbo = this->MLAAFramebuffer;
  // Both textures start at 0: the passes write the edge pixels only, and the jumps of the
  // doubling land on pixels without an edge too, which must read 0.
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  for (vtkTextureObject* lengths : this->LengthsTextures)
  {
    fbo->AddColorAttachment(0, lengths);
    fbo->ActivateDrawBuffer(0);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  }

  // Initialisation: the 0/1 flags of every direction into LengthsTextures[1] (still attached).
  if (!this->ReadyQuad(renWin, this->LengthsInitQuad, vtkMLAALineLengthsInitFS, std::string()))
  {
    return nullptr;
  }
  this->EdgesTexture->Activate();
  this->LengthsInitQuad.Quad->Program->SetUniformi(
    "edgesTexture", this->EdgesTexture->GetTextureUnit());
  this->LengthsInitQuad.Quad->Render();
  this->EdgesTexture->Deactivate();

  // Doubling passes for levels 1, 4, 16, ... until the counts are exact up to the maximum
  // distance (4 level >= maximum distance), reading one texture and writing the other.
  if (!this->ReadyQuad(renWin, this->LengthsQuad, vtkMLAALineLengthsFS, std::string()))
  {
    return nullptr;
  }
  vtkShaderProgram* program = this->LengthsQuad.Quad->Program;
  const int maxDistance = this->Options->GetMaxDistance();
  int source = 1;
  for (int level = 1; level < maxDistance; level *= 4)
  {
    vtkTextureObject* from = this->LengthsTextures[source];
    vtkTextureObject* to = this->LengthsTextures[1 - source];
    fbo->AddColorAttachment(0, to);
    fbo->ActivateDrawBuffer(0);
    from->Activate();
    program->SetUniformi("lengthsTexture", from->GetTextureUnit());
    program->SetUniformf("level", static_cast<float>(level));
    this->LengthsQuad.Quad->Render();
    from->Deactivate();
    source = 1 - source;
  }
  return this->LengthsTextures[source];
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::Blend(vtkOpenGLRenderWindow* renWin, int x, int y, int width,
  int height, bool composite, bool straightAlpha, bool inPlace)
{
  vtkOpenGLState* ostate = renWin->GetState();
  ostate->vtkglViewport(x, y, width, height);
  ostate->vtkglScissor(x, y, width, height);
  if (composite && this->Options->GetDebugOutput() == vtkMLAAOptions::NO_DEBUG_OUTPUT)
  {
    // Premultiplied "over": result + (1 - its alpha) * what lower layers drew. Where this
    // renderer drew nothing (transparent black) the framebuffer keeps its pixels exactly; an
    // opaque pixel replaces them, as it would without the pass.
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  else
  {
    ostate->vtkglDisable(GL_BLEND);
  }
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (inPlace)
  {
    // The target already holds the delegate's image and depth: only the blended pixels are
    // written, and no depth.
    ostate->vtkglDisable(GL_DEPTH_TEST);
  }
  else
  {
    // Depth writes need the depth test on; ALWAYS copies the delegate's depth.
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_ALWAYS);
    ostate->vtkglDepthMask(GL_TRUE);
  }
  const std::string blendDefines =
    Define("MLAA_DEBUG_OUTPUT", this->Options->GetDebugOutput()) +
    Define("MLAA_DOMINANT_DIRECTION", this->Options->GetDominantDirectionBlending()) +
    Define("MLAA_STRAIGHT_ALPHA", straightAlpha) + Define("MLAA_IN_PLACE", inPlace);
  if (!this->ReadyQuad(renWin, this->BlendQuad, vtkMLAANeighborhoodBlendingFS, blendDefines))
  {
    return false;
  }
  vtkShaderProgram* program = this->BlendQuad.Quad->Program;
  vtkTextureObject* source = this->GetSourceTexture();
  source->Activate();
  if (!inPlace)
  {
    this->DepthTexture->Activate();
    program->SetUniformi("depthTexture", this->DepthTexture->GetTextureUnit());
  }
  this->EdgesTexture->Activate();
  this->WeightsTexture->Activate();
  program->SetUniformi("colorTexture", source->GetTextureUnit());
  program->SetUniformi("edgesTexture", this->EdgesTexture->GetTextureUnit());
  program->SetUniformi("weightsTexture", this->WeightsTexture->GetTextureUnit());
  this->BlendQuad.Quad->Render();
  this->WeightsTexture->Deactivate();
  this->EdgesTexture->Deactivate();
  if (!inPlace)
  {
    this->DepthTexture->Deactivate();
  }
  source->Deactivate();
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
}

//------------------------------------------------------------------------------
bool vtkOpenGLMLAAPass::Reconstruct(
  vtkOpenGLRenderWindow* renWin, int width, int height, bool useAlpha)
{
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLFramebufferObject* fbo = this->MLAAFramebuffer;
  fbo->Bind();
  fbo->AddColorAttachment(0, this->ReconstructedTexture);
  fbo->ActivateDrawBuffer(0);
  fbo->StartNonOrtho(width, height);
  ostate->vtkglViewport(0, 0, width, height);
  ostate->vtkglScissor(0, 0, width, height);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (!this->ReadyQuad(renWin, this->ReconstructionQuad, vtkMLAAReconstructionFS,
        Define("MLAA_USE_ALPHA", useAlpha)))
  {
    return false;
  }
  this->ColorTexture->Activate();
  this->SetReconstructionUniforms(this->ReconstructionQuad.Quad->Program);
  this->ReconstructionQuad.Quad->Render();
  this->ColorTexture->Deactivate();
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
  this->ColorTexture->Activate();
  this->SetReconstructionUniforms(this->WriteBackQuad.Quad->Program);
  this->WriteBackQuad.Quad->Render();
  this->ColorTexture->Deactivate();
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro("No delegate pass: nothing to antialias.");
    return;
  }

  vtkRenderer* renderer = s->GetRenderer();
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!renWin)
  {
    vtkErrorMacro("vtkOpenGLMLAAPass needs a vtkOpenGLRenderWindow.");
    return;
  }
  vtkOpenGLState* ostate = renWin->GetState();

  // A hardware selection render (picking): the colour buffer holds encoded prop, cell and point
  // ids, not colours, and a blend of two ids is a third, wrong one. Render straight into the
  // target, untouched, as vtkOpenGLRenderer does without a pass: the camera (which clears), the
  // lights, and UpdateGeometry, which hands the props to the selector. (The selector numbers the
  // props only in UpdateGeometry; render passes such as vtkRenderStepsPass do not call it.)
  if (renderer->GetSelector())
  {
    renWin->MakeCurrent();
    this->UpdateCamera(renderer);
    this->UpdateLightGeometry(renderer);
    this->UpdateLights(renderer);
    this->UpdateGeometry(renderer, s->GetFrameBuffer());
    this->NumberOfRenderedProps = renderer->GetNumberOfPropsRendered();
    vtkOpenGLCheckErrorMacro("failed after vtkOpenGLMLAAPass::Render");
    return;
  }

  // The viewport to fill: the renderer's (tiled) viewport in the window, or the whole of a
  // framebuffer object when an enclosing pass renders this one into its own target.
  int x = 0, y = 0, width = 0, height = 0;
  bool floatColor = false;
  if (auto* targetFbo = vtkOpenGLFramebufferObject::SafeDownCast(s->GetFrameBuffer()))
  {
    int size[2];
    s->GetWindowSize(size);
    width = size[0];
    height = size[1];
    vtkTextureObject* target = targetFbo->GetColorAttachmentAsTextureObject(0);
    floatColor = target && target->GetVTKDataType() == VTK_FLOAT;
  }
  else
  {
    renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
  }
  if (width < 1 || height < 1)
  {
    return;
  }
  // A renderer that preserves the colour buffer (a layer above 0, or
  // SetPreserveColorBuffer(1)) draws over what is already there: its image is composited over
  // the target, and its alpha (coverage) takes part in edge detection.
  const bool composite = renderer->Transparent() != 0;
  // Alpha takes part in edge detection only where the result keeps it: when compositing, and
  // with KeepAlpha. Otherwise the image is opaque to whoever reads it (an RGB screenshot, the
  // screen), and the alpha VTK leaves in the framebuffer (0 on the background, 1 on geometry,
  // whatever the background colour) would make edges that nobody sees.
  const bool useAlpha = composite || this->KeepAlpha;
  // Straight alpha: the colours are premultiplied before blending and divided by alpha after.
  // The texture of a composited renderer is premultiplied by construction.
  const bool straightAlpha =
    this->KeepAlpha && !composite && !this->Options->GetPremultipliedAlpha();
  // In place: the delegate renders straight into the target, as it would without the pass; its
  // colour is copied (blitted) into ColorTexture, and the last pass writes only the pixels that
  // blending changes. This saves copying every pixel's colour and depth back with a shader. A
  // composited renderer needs its own transparent texture, and depth edges the delegate's depth
  // as a texture: those render the delegate into the pass's textures and copy everything back.
  const bool inPlace =
    !composite && this->Options->GetEdgeDetection() != vtkMLAAOptions::DEPTH;
  unsigned int targetBinding = 0, targetBuffer = 0;
  ostate->GetCurrentDrawFramebufferState(targetBinding, targetBuffer);

  vtkRenderStepsPass* steps =
    this->AntialiasOverlays ? nullptr : vtkRenderStepsPass::SafeDownCast(this->DelegatePass);
  vtkSmartPointer<vtkRenderPass> overlay = steps ? steps->GetOverlayPass() : nullptr;
  bool done = false;
  {
    // Save the state this pass changes; restored at the end of this block.
    vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
    vtkOpenGLState::ScopedglEnableDisable depthTestSaver(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
    vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
    vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
    vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
    vtkOpenGLState::ScopedglScissor scissorSaver(ostate);

    this->PrepareTargets(renWin, width, height, floatColor, !inPlace);

    // Render the delegate, keeping its overlay step for after the antialiasing.
    if (overlay)
    {
      steps->SetOverlayPass(nullptr);
    }
    if (inPlace)
    {
      this->DelegatePass->Render(s);
      this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
      ostate->PushFramebufferBindings();
      this->CopyTargetToColorTexture(renWin, targetBinding, targetBuffer, x, y, width, height);
      ostate->PopFramebufferBindings();
    }
    else
    {
      ostate->PushFramebufferBindings();
      this->RenderDelegateToTextures(s, width, height, composite);
      ostate->PopFramebufferBindings();
    }
    if (overlay)
    {
      steps->SetOverlayPass(overlay);
    }

    // Topological reconstruction (Biri et al., section 4.3): before edge detection, into
    // ReconstructedTexture, which the later passes read instead of ColorTexture.
    const bool reconstruction = this->Options->GetReconstruction();
    ostate->PushFramebufferBindings();
    bool computed = !reconstruction || this->Reconstruct(renWin, width, height, useAlpha);
    computed = computed && this->ComputeEdgesAndWeights(renWin, width, height, useAlpha);
    ostate->PopFramebufferBindings();
    if (computed && reconstruction && inPlace &&
      this->Options->GetDebugOutput() == vtkMLAAOptions::NO_DEBUG_OUTPUT)
    {
      computed = this->WriteBackReconstruction(renWin, x, y, width, height, useAlpha);
    }
    done =
      computed && this->Blend(renWin, x, y, width, height, composite, straightAlpha, inPlace);
  }

  // The overlays (not over a debug image): drawn on top of the result, in the state the pass was
  // entered with, in the renderer's viewport, as the render steps would have drawn them.
  if (done && overlay && this->Options->GetDebugOutput() == vtkMLAAOptions::NO_DEBUG_OUTPUT)
  {
    ostate->vtkglViewport(x, y, width, height);
    ostate->vtkglScissor(x, y, width, height);
    overlay->Render(s);
    this->NumberOfRenderedProps += overlay->GetNumberOfRenderedProps();
  }
  vtkOpenGLCheckErrorMacro("failed after vtkOpenGLMLAAPass::Render");
}

//------------------------------------------------------------------------------
void vtkOpenGLMLAAPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  for (ShaderVariant* variant : { &this->ReconstructionQuad, &this->WriteBackQuad,
         &this->EdgesQuad, &this->LocalContrastQuad, &this->WeightsQuad, &this->BlendQuad,
         &this->LengthsInitQuad, &this->LengthsQuad })
  {
    variant->Release(w);
  }
  DeleteObject(this->DelegateFramebuffer, w);
  DeleteObject(this->MLAAFramebuffer, w);
  for (vtkTextureObject** texture : { &this->ColorTexture, &this->DepthTexture,
         &this->EdgesTexture, &this->WeightsTexture, &this->MaskTexture, &this->AreaTexture,
         &this->DiagonalAreaTexture, &this->LengthsTextures[0], &this->LengthsTextures[1],
         &this->ReconstructedTexture })
  {
    DeleteObject(*texture, w);
  }
  this->AreaTextureMaxDistance = 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLMLAAPass::GetMLAATargetMemorySize()
{
  return TextureBytes(this->EdgesTexture, 2) + TextureBytes(this->WeightsTexture, 4);
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLMLAAPass::GetTargetMemorySize()
{
  const int colorBytes = (this->ColorTexture && this->ColorTexture->GetVTKDataType() == VTK_FLOAT)
    ? 16
    : 4;
  return TextureBytes(this->ColorTexture, colorBytes) +
    TextureBytes(this->ReconstructedTexture, colorBytes) + TextureBytes(this->DepthTexture, 4) +
    this->GetMLAATargetMemorySize() + TextureBytes(this->MaskTexture, 2) +
    TextureBytes(this->AreaTexture, 8) + TextureBytes(this->DiagonalAreaTexture, 12) +
    TextureBytes(this->LengthsTextures[0], 8) + TextureBytes(this->LengthsTextures[1], 8);
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
      return this->Options->GetMaxSearchSteps() >= AutomaticDoublingSteps;
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
  os << indent << "AntialiasOverlays: " << (this->AntialiasOverlays ? "On" : "Off") << "\n";
  os << indent << "KeepAlpha: " << (this->KeepAlpha ? "On" : "Off") << "\n";
  os << indent << "LineLengths: " << GetLineLengthsAsString(this->LineLengths) << "\n";
  os << indent << "Options:\n";
  this->Options->PrintSelf(os, indent.GetNextIndent());
}
