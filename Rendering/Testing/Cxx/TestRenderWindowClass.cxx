// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// The kind of window the rendering tests run in, and that the pass antialiases there. Where the
// environment names one (MLAA_EXPECTED_RENDER_WINDOW, set by CMake's
// vtkMLAA_EXPECTED_RENDER_WINDOW: vtkEGLRenderWindow in the Debian testing root, which has no X
// server), the window VTK's factory makes must be of that class, so that the other rendering
// tests are known to have run through it and not through a display found by chance. Then the
// MLAA pass must change the silhouettes' edges and match the CPU filter there.
#include "vtkAntialiasingRenderTestUtilities.h"

#include <cstdlib>
#include <string>

using namespace vtkMLAATest;

int TestRenderWindowClass(int, char*[])
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(200, 150);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkMLAAScenes::Build("silhouettes", renderer);
  auto plain = vtkMLAAScenes::Capture(window, false);

  const std::string actual = window->GetClassName();
  const char* expected = std::getenv("MLAA_EXPECTED_RENDER_WINDOW");
  std::cout << "render window: " << actual << " (expected: " << (expected ? expected : "any")
            << ")" << std::endl;
  if (expected && *expected && !MLAA_CHECK(actual == expected))
  {
    std::cerr << "the rendering tests run in a " << actual << ", not a " << expected << std::endl;
  }

  auto pass = UseMLAA(renderer);
  vtkNew<MessageObserver> messages;
  messages->Watch(pass);
  auto smooth = vtkMLAAScenes::Capture(window, false);
  MLAA_CHECK(Compare(plain, smooth).Count > 0);
  CheckParity(MLAAPassMethod(), window, renderer, pass, "in this window");
  pass->ReleaseGraphicsResources(window);
  MLAA_CHECK(messages->Errors.empty());
  return Result();
}
