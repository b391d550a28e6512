// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Small helpers of the antialiasing passes (vtkOpenGLAntialiasingPass, its temporal history and
// multisampled targets, and its subclasses): render targets that are resized in place, textures
// bound for a scope, #define lines of shader variants.
// Private header.
#ifndef vtkOpenGLAntialiasingPassInternals_h
#define vtkOpenGLAntialiasingPassInternals_h

#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkRenderState.h"
#include "vtkRenderTimerLog.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkType.h"

#include <algorithm>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "vtkAntialiasingOpenGL.h" // For GL enums only

namespace vtkOpenGLAntialiasingPassInternals
{
// Resizes an allocated texture to width x height in place (same GL handle), if needed.
inline void ResizeInPlace(vtkTextureObject* texture, int width, int height)
{
  if (texture->GetWidth() != static_cast<unsigned int>(width) ||
    texture->GetHeight() != static_cast<unsigned int>(height))
  {
    texture->Resize(width, height);
  }
}

// Makes `texture` a 2D texture of the given size, components and type (and, when `internalFormat`
// is not 0, that GL internal format): resized in place (same GL handle, so framebuffer attachments
// stay valid) when only the size differs, allocated afresh otherwise. Returns true when the texture
// was allocated afresh (its handle changed).
inline bool AllocateColorTarget(vtkTextureObject* texture, int width, int height, int components,
  int vtkType, bool linear, unsigned int internalFormat = 0)
{
  const bool sameFormat = texture->GetHandle() && texture->GetComponents() == components &&
    texture->GetVTKDataType() == vtkType;
  if (sameFormat)
  {
    ResizeInPlace(texture, width, height);
    return false;
  }
  texture->ReleaseGraphicsResources(texture->GetContext());
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(linear ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
  if (internalFormat)
  {
    texture->SetInternalFormat(internalFormat);
  }
  texture->Allocate2D(width, height, components, vtkType);
  return true;
}

// The same for a depth texture.
inline bool AllocateDepthTarget(vtkTextureObject* texture, int width, int height, int format)
{
  if (texture->GetHandle())
  {
    ResizeInPlace(texture, width, height);
    return false;
  }
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->AllocateDepth(width, height, format);
  return true;
}

// A stage of a pass as an event of the window's render timings (vtkRenderTimerLog, VTK's GL timer
// queries), nested in the events open when it starts and ended by Stop() or when it goes out of
// scope. Nothing is timed unless an application turns the timings on
// (window->GetRenderTimer()->LoggingEnabledOn(); mlaa-benchmark-gpu --stages). While they are
// on, each start and end of a stage waits for the GL work before it (WaitForCompletion), so that
// every stage is charged with its own work on any implementation: timestamps are taken when the
// GL queues them, which on llvmpipe is before its rasteriser has run the draws. Frames are slower
// then; the stages are for comparing with one another.
class TimedStage
{
public:
  TimedStage(vtkRenderWindow* window, const char* name)
    : Window(window)
  {
    if (window->GetRenderTimer()->GetLoggingEnabled())
    {
      window->WaitForCompletion();
      this->Event = window->GetRenderTimer()->StartScopedEvent(name);
      this->Open = true;
    }
  }
  ~TimedStage() { this->Stop(); }
  void Stop()
  {
    if (this->Open)
    {
      this->Window->WaitForCompletion();
      this->Event.Stop();
      this->Open = false;
    }
  }
  TimedStage(const TimedStage&) = delete;
  TimedStage& operator=(const TimedStage&) = delete;

private:
  vtkRenderWindow* Window;
  vtkRenderTimerLog::ScopedEventLogger Event;
  bool Open = false;
};

// Draws into the first `count` (1 or 2) colour attachments of the bound framebuffer `fbo`. VTK
// 9.1's state cache (vtkOpenGLState::vtkglDrawBuffers) compares only as many entries as are
// requested, not their number, so through vtkOpenGLFramebufferObject alone a switch from
// attachments {0, 1} to {0} is dropped (GL keeps drawing into both), and once GL draws into {0}
// while the cache holds {0, 1}, a switch back to two is dropped as well. The passes' work
// framebuffers switch between one and two outputs (the temporal history and its counts, the
// line lengths and the staircase counts), so they set their draw buffers here: through the cache,
// which keeps its first entry right, and then directly. (Seen as undefined counts in the temporal
// history, black 64 x 64 tiles on llvmpipe, and as a copy that wrote into its own source.)
inline void DrawToAttachments(vtkOpenGLFramebufferObject* fbo, unsigned int count)
{
  fbo->ActivateDrawBuffers(count);
  const GLenum buffers[2] = { GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1 };
  glDrawBuffers(static_cast<GLsizei>(std::min(count, 2u)), buffers);
}

inline vtkTextureObject* NewTexture(vtkOpenGLRenderWindow* renWin)
{
  vtkTextureObject* texture = vtkTextureObject::New();
  texture->SetContext(renWin);
  return texture;
}

inline vtkIdType TextureBytes(vtkTextureObject* texture, int bytesPerTexel)
{
  return texture && texture->GetHandle()
    ? static_cast<vtkIdType>(texture->GetWidth()) * texture->GetHeight() * bytesPerTexel
    : 0;
}

// The start of a depth mask in the bound framebuffer (the MLAA pass's change mask, the DLAA
// pass's corner candidates): colour and depth cleared to 0, then the depth test on with ALWAYS
// and depth writes, so that the fragments a marking draw keeps write their depth and the others
// leave 0. A later draw tested LESS with the quad at depth 0 then shades the marked pixels only.
inline void BeginDepthMask(vtkOpenGLState* ostate)
{
  ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
  ostate->vtkglClearDepth(0.0);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
}

// The state for writing a result into the target's viewport (x, y, width, height): colour writes
// on; with `over`, premultiplied "over" blending (result + (1 - its alpha) * what lower layers
// drew: where the renderer drew nothing, transparent black, the framebuffer keeps its pixels
// exactly; an opaque pixel replaces them, as without the pass), else no blending; with
// `writeDepth`, the depth test on with ALWAYS and depth writes (the fragment's depth is copied),
// else the depth test off (colour only).
inline void SetTargetWriteState(
  vtkOpenGLState* ostate, int x, int y, int width, int height, bool over, bool writeDepth)
{
  ostate->vtkglViewport(x, y, width, height);
  ostate->vtkglScissor(x, y, width, height);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (over)
  {
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  else
  {
    ostate->vtkglDisable(GL_BLEND);
  }
  if (writeDepth)
  {
    ostate->vtkglEnable(GL_DEPTH_TEST);
    ostate->vtkglDepthFunc(GL_ALWAYS);
    ostate->vtkglDepthMask(GL_TRUE);
  }
  else
  {
    ostate->vtkglDisable(GL_DEPTH_TEST);
  }
}

// The textures that one or more draws read, for as long as the object lives: Bind activates a
// texture (on a free unit of the window's pool; a texture already active keeps its unit) and
// points a program's sampler at it; when the object goes out of scope, on every path out of the
// caller, early returns included, the textures are deactivated, last first, freeing the units.
class ScopedTextures
{
public:
  ScopedTextures() = default;
  ScopedTextures(vtkShaderProgram* program,
    std::initializer_list<std::pair<const char*, vtkTextureObject*>> samplers)
  {
    for (const auto& sampler : samplers)
    {
      this->Bind(program, sampler.first, sampler.second);
    }
  }
  ~ScopedTextures()
  {
    for (auto texture = this->Textures.rbegin(); texture != this->Textures.rend(); ++texture)
    {
      (*texture)->Deactivate();
    }
  }
  ScopedTextures(const ScopedTextures&) = delete;
  ScopedTextures& operator=(const ScopedTextures&) = delete;

  // Activates `texture` until the end of the scope.
  void Activate(vtkTextureObject* texture)
  {
    texture->Activate();
    if (std::find(this->Textures.begin(), this->Textures.end(), texture) == this->Textures.end())
    {
      this->Textures.push_back(texture);
    }
  }
  // The same, and `program`'s sampler `name` reads it.
  void Bind(vtkShaderProgram* program, const char* name, vtkTextureObject* texture)
  {
    this->Activate(texture);
    program->SetUniformi(name, texture->GetTextureUnit());
  }

private:
  std::vector<vtkTextureObject*> Textures;
};

// One #define line of a shader variant.
inline std::string Define(const char* name, int value)
{
  return std::string("#define ") + name + " " + std::to_string(value) + "\n";
}
inline std::string Define(const char* name, bool defined)
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

// Makes each framebuffer object of `framebuffers` that is missing, and afresh all of them with
// `reset` (framebuffer objects remember their attachments: after new textures, start anew).
inline void PrepareFramebuffers(vtkOpenGLRenderWindow* renWin, bool reset,
  std::initializer_list<vtkOpenGLFramebufferObject**> framebuffers)
{
  for (vtkOpenGLFramebufferObject** fbo : framebuffers)
  {
    if (reset)
    {
      DeleteObject(*fbo, renWin);
    }
    if (!*fbo)
    {
      *fbo = vtkOpenGLFramebufferObject::New();
      (*fbo)->SetContext(renWin);
    }
  }
}

// Whether `predicate` holds for one of the props a render draws.
template <typename Predicate>
inline bool AnyProp(const vtkRenderState* s, Predicate predicate)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    if (predicate(s->GetPropArray()[i]))
    {
      return true;
    }
  }
  return false;
}
} // namespace vtkOpenGLAntialiasingPassInternals

#endif
