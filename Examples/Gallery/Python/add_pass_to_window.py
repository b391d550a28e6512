#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Gallery: add MLAA to an existing VTK application, from Python.

    add_pass_to_window.py [--output FILE.png] [--without-mlaa]

A small application of the usual shape (a wireframe sphere, a cone, a text overlay, an
interactor). The one line marked "MLAA" is all that antialiasing needs: vtkmlaa.enable()
puts a vtkOpenGLMLAAPass around the renderer's usual render steps and turns multisampling off.
Text and other 2D overlays are drawn after the antialiasing, untouched. With a PyVista-style
plotter the same line is vtkmlaa.enable(plotter.renderer).

With --output the window renders once offscreen and the picture is written to FILE.png instead
of opening an interactive window; --without-mlaa leaves the pass out (to compare).
"""
import argparse
import sys

import vtkmlaa
from vtkmodules.vtkFiltersSources import vtkConeSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderWindowInteractor, vtkRenderer,
                                         vtkTextActor, vtkWindowToImageFilter)
import vtkmodules.vtkInteractionStyle  # noqa: F401 (the interactor's default style)
import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text rendering)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--output", help="render offscreen once and write this PNG")
    parser.add_argument("--without-mlaa", action="store_true", help="leave the pass out")
    args = parser.parse_args(argv)

    # The existing application: a wireframe sphere, a cone and a title.
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(24)
    sphere.SetPhiResolution(16)
    sphere_mapper = vtkPolyDataMapper()
    sphere_mapper.SetInputConnection(sphere.GetOutputPort())
    sphere_actor = vtkActor()
    sphere_actor.SetMapper(sphere_mapper)
    sphere_actor.GetProperty().SetRepresentationToWireframe()
    sphere_actor.GetProperty().SetColor(0.1, 0.1, 0.1)

    cone = vtkConeSource()
    cone.SetResolution(40)
    cone.SetCenter(1.2, 0.0, 0.0)
    cone_mapper = vtkPolyDataMapper()
    cone_mapper.SetInputConnection(cone.GetOutputPort())
    cone_actor = vtkActor()
    cone_actor.SetMapper(cone_mapper)
    cone_actor.GetProperty().SetColor(0.9, 0.45, 0.1)

    title = vtkTextActor()
    title.SetInput("vtkmlaa.enable(renderer)")
    title.GetTextProperty().SetFontSize(18)
    title.GetTextProperty().SetColor(0.0, 0.0, 0.0)
    title.SetDisplayPosition(10, 10)

    renderer = vtkRenderer()
    renderer.AddActor(sphere_actor)
    renderer.AddActor(cone_actor)
    renderer.AddActor2D(title)
    renderer.SetBackground(1.0, 1.0, 1.0)
    renderer.GetActiveCamera().Azimuth(20.0)
    renderer.ResetCamera()

    window = vtkRenderWindow()
    window.AddRenderer(renderer)
    window.SetSize(400, 300)

    if not args.without_mlaa:
        vtkmlaa.enable(renderer)  # MLAA (the `high` preset; see help(vtkmlaa.enable))
    else:
        window.SetMultiSamples(0)  # the same aliased render, for comparison

    if not args.output:
        interactor = vtkRenderWindowInteractor()
        interactor.SetRenderWindow(window)
        window.Render()
        interactor.Start()
        return 0

    window.SetOffScreenRendering(1)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    writer.SetFileName(args.output)
    writer.Write()
    if writer.GetErrorCode() != 0:
        print(args.output + ": not written", file=sys.stderr)
        return 1
    print("wrote %s (%s)" % (args.output,
                             "no antialiasing" if args.without_mlaa else "MLAA"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
