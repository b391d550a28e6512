// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Scientific-visualization scenes used by the vtkMLAA tests, the demo, and the quality and speed
// benchmarks: shaded silhouettes, thin and thick lines, a wireframe, an iso-surface, glyphs, a
// texture, text with a scalar bar, a mixed scene, equal-luma colour bands, long nearly
// horizontal edges, sub-pixel thin structures and point clouds; and a few held-out scenes. One
// definition, so that every program measures and shows the same pictures.
#ifndef vtkMLAAScenes_h
#define vtkMLAAScenes_h

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkImageData;
class vtkRenderWindow;
class vtkRenderer;

namespace vtkMLAAScenes
{
/** Names of all scenes, in a fixed order: the set every benchmark and test measures. */
std::vector<std::string> Names();

/**
 * Names of the held-out scenes, in a fixed order: kinds of pictures the main set does not have
 * (a surface with its mesh edges, spheres over black, a height field with contour lines,
 * streamlines). No default list includes them, and nothing is tuned on them: they are there to
 * check that what the main set measures holds elsewhere (`mlaa-quality --scenes held-out`).
 * Describe and Build take their names too.
 */
std::vector<std::string> HeldOutNames();

/** A one-line description of a scene (empty for an unknown name). */
std::string Describe(const std::string& name);

/**
 * Whether every edge of scene `name` is a horizontal or vertical side (voxels seen straight on):
 * it has no staircase, and MLAA, which leaves sides without steps alone, has nothing to change
 * there, at any size (issue 50). False for an unknown name.
 */
bool AxisAligned(const std::string& name);

/**
 * Adds the actors of scene `name` to `renderer`, sets its background and camera. Returns false
 * for an unknown name.
 */
bool Build(const std::string& name, vtkRenderer* renderer);

/**
 * A render window for offscreen measurement: offscreen, no multisampling (MLAA and the reference
 * need single-sample renders), the given size.
 */
vtkSmartPointer<vtkRenderWindow> NewOffscreenWindow(int width, int height);

/** Renders `window` and returns its RGB (or RGBA when `alpha`) pixels, row 0 at the bottom. */
vtkSmartPointer<vtkImageData> Capture(vtkRenderWindow* window, bool alpha = false);
}

#endif
