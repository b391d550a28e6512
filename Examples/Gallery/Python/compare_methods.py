#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Gallery: compare antialiasing methods side by side on one scene, from Python.

    compare_methods.py [--output FILE.png] [--size WxH] [--zoom N]

Renders one scene (a lit sphere's silhouette behind a wireframe grid) with no antialiasing,
VTK's FXAA, 4x multisampling, MLAA and DLAA (vtkmlaa.enable), each labelled, and writes one
picture: the renders in a row, and under each its crop of the same region magnified N times
(nearest neighbour, so the pixels stay visible), where MLAA changed the most pixels. Replace
build_scene() with your own actors to compare on your data. The C++ version is
Examples/Gallery/CompareMethods.cxx.
"""
import argparse
import sys

import numpy as np

import vtkmlaa
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text rendering)

METHODS = ["none", "FXAA", "4x MSAA", "MLAA", "DLAA"]


def actor_of(source):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def build_scene(renderer):
    """The scene: a lit sphere and, in front of its lower left, a tilted wireframe grid."""
    sphere = vtkSphereSource()
    sphere.SetCenter(0.4, 0.2, 0.0)
    sphere.SetRadius(0.8)
    sphere.SetThetaResolution(64)
    sphere.SetPhiResolution(64)
    sphere_actor = actor_of(sphere)
    sphere_actor.GetProperty().SetColor(0.85, 0.35, 0.2)

    grid = vtkPlaneSource()
    grid.SetResolution(10, 10)
    grid.SetOrigin(-1.3, -1.1, 0.9)
    grid.SetPoint1(0.5, -1.35, 0.9)
    grid.SetPoint2(-1.1, 0.6, 0.9)
    grid_actor = actor_of(grid)
    grid_actor.GetProperty().SetRepresentationToWireframe()
    grid_actor.GetProperty().SetColor(0.1, 0.2, 0.45)

    renderer.AddActor(sphere_actor)
    renderer.AddActor(grid_actor)
    renderer.SetBackground(0.93, 0.93, 0.9)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Zoom(1.4)


def render(method, width, height):
    """The scene rendered offscreen with `method`, labelled, as an (height, width, 3) array
    whose first row is the bottom of the picture (VTK's order)."""
    renderer = vtkRenderer()
    build_scene(renderer)
    label = vtkTextActor()
    label.SetInput(method)
    text = label.GetTextProperty()
    text.SetFontSize(16)
    text.SetBold(True)
    text.SetColor(1.0, 1.0, 1.0)
    text.SetBackgroundColor(0.0, 0.0, 0.0)
    text.SetBackgroundOpacity(0.75)
    label.SetDisplayPosition(6, 6)
    renderer.AddActor2D(label)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(width, height)
    window.AddRenderer(renderer)
    window.SetMultiSamples(4 if method == "4x MSAA" else 0)
    if method == "FXAA":
        renderer.UseFXAAOn()
    elif method in ("MLAA", "DLAA"):
        vtkmlaa.enable(renderer, method=method.lower())
    window.Render()

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    pixels = numpy_support.vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    result = pixels.reshape(height, width, -1)[:, :, :3].copy()
    if method in ("MLAA", "DLAA"):
        vtkmlaa.disable(renderer)  # releases the pass's GPU resources with the window
    return result


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--output", default="mlaa-gallery-compare.png")
    parser.add_argument("--size", default="300x225", help="WxH of each render (at least 64x64)")
    parser.add_argument("--zoom", type=int, default=3, help="magnification of the crops (2-16)")
    args = parser.parse_args(argv)
    try:
        width, height = (int(v) for v in args.size.split("x"))
    except ValueError:
        parser.error(f"--size {args.size}: expected WxH")
    if width < 64 or height < 64 or not 2 <= args.zoom <= 16:
        parser.error("--size must be at least 64x64 and --zoom 2 to 16")

    renders = {method: render(method, width, height) for method in METHODS}

    # The crop: 1/zoom of the width and height, where MLAA changed the most pixels, searched
    # on a coarse grid above the label.
    cw, ch = width // args.zoom, height // args.zoom
    changed = np.any(renders["none"] != renders["MLAA"], axis=2)
    step_x, step_y = max(1, cw // 4), max(1, ch // 4)
    candidates = [(changed[y:y + ch, x:x + cw].sum(), x, y)
                  for y in range(height // 8, height - ch + 1, step_y)
                  for x in range(0, width - cw + 1, step_x)]
    _, x0, y0 = max(candidates, key=lambda c: (c[0], -c[2], -c[1]))

    def magnify(image):
        crop = image[y0:y0 + ch, x0:x0 + cw]
        big = crop.repeat(args.zoom, axis=0).repeat(args.zoom, axis=1)
        out = np.zeros_like(image)  # the crop fills a render's size (black if not divisible)
        out[:big.shape[0], :big.shape[1]] = big
        return out

    top = np.concatenate([renders[m] for m in METHODS], axis=1)
    bottom = np.concatenate([magnify(renders[m]) for m in METHODS], axis=1)
    picture = np.ascontiguousarray(np.concatenate([bottom, top], axis=0))  # bottom row first

    image = vtkImageData()
    image.SetDimensions(picture.shape[1], picture.shape[0], 1)
    image.GetPointData().SetScalars(numpy_support.numpy_to_vtk(picture.reshape(-1, 3), deep=True))
    writer = vtkPNGWriter()
    writer.SetInputData(image)
    writer.SetFileName(args.output)
    writer.Write()
    if writer.GetErrorCode() != 0:
        print(f"{args.output}: not written", file=sys.stderr)
        return 1
    print(f"wrote {args.output} ({picture.shape[1]}x{picture.shape[0]}): "
          f"{' | '.join(METHODS)}, crops of {cw}x{ch} pixels at ({x0}, {y0}) "
          f"magnified {args.zoom} times")
    return 0


if __name__ == "__main__":
    sys.exit(main())
