# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""The MLAA render view: with UseMLAA on, the screenshot is antialiased (edge pixels change,
flat regions do not) and equals, within 2/255, vtkImageMLAA run outside ParaView (the `mlaa`
tool, which the project's tests hold equal to the GPU pass within 2/255) on the screenshot with
UseMLAA off; the same for UseDLAA and vtkImageDLAA; UseMLAA off gives the plain image; FXAA
never stacks with MLAA; AntialiasingTemporal changes edges only, and off gives the single-frame
image back. The screenshots are
kept in the output directory for TestMLAARanks.py, which compares one rank with two."""

import os

import numpy as np

import mlaa_pvtest as t

args = t.parse_arguments()

from paraview.simple import *  # noqa: E402,F403

t.load_plugin(args.plugin, globals())
t.check(t.number_of_ranks() == args.ranks, "pvbatch runs on %d rank(s)" % args.ranks)

view = CreateView("MLAARenderView")
t.check(view.UseMLAA == 1, "UseMLAA is on by default")
size, sphere = t.show_view_scene(view)
if args.ranks > 1:
    t.check_split(sphere, args.ranks, "sphere")


def screenshot(name):
    path = os.path.join(args.output_dir, name)
    SaveScreenshot(path, view, ImageResolution=size, TransparentBackground=0)
    rows = t.read_png(path)
    return path, rows[:, :, :3]


# ParaView's settings may turn FXAA on for every render view (in this view it only applies while
# UseMLAA is off): the plain image has none.
view.UseFXAA = 0
view.UseMLAA = 0
off_path, off = screenshot("mlaa-off.png")
view.UseMLAA = 1
on_path, on = screenshot("mlaa-on.png")

changed = np.any(on != off, axis=2)
flat = t.uniform_neighbourhoods(off)
t.check(changed.sum() > 200, "%d edge pixels are antialiased" % changed.sum())
t.check(t.max_difference(on[flat], off[flat]) == 0, "flat regions are unchanged")

reference = t.run_tool(args.tool, [], off_path, os.path.join(args.output_dir, "reference.png"))
difference = t.max_difference(on, reference[:, :, :3])
t.check(difference <= 2,
        "the view's image equals vtkImageMLAA's on the plain screenshot within 2/255 "
        "(max difference %d)" % difference)

# DLAA, with UseMLAA off: the same checks against the tool's --method dlaa (DLAA reads up to 10
# pixels away, so "flat" is wider).
view.UseMLAA = 0
view.UseDLAA = 1
_, dlaa = screenshot("dlaa-on.png")
changed = np.any(dlaa != off, axis=2)
t.check(changed.sum() > 200, "DLAA: %d edge pixels are antialiased" % changed.sum())
wide_flat = t.uniform_neighbourhoods(off, 10)
t.check(t.max_difference(dlaa[wide_flat], off[wide_flat]) == 0, "DLAA: flat regions are unchanged")
reference = t.run_tool(args.tool, ["--method", "dlaa"], off_path,
                       os.path.join(args.output_dir, "reference-dlaa.png"))
difference = t.max_difference(dlaa, reference[:, :, :3])
t.check(difference <= 2,
        "DLAA: the view's image equals vtkImageDLAA's on the plain screenshot within 2/255 "
        "(max difference %d)" % difference)
view.UseMLAA = 1
_, both = screenshot("mlaa-and-dlaa-on.png")
t.check(np.array_equal(both, on), "with UseMLAA and UseDLAA on, MLAA is used")
view.UseDLAA = 0

# Temporal antialiasing (issue 23): a still render renders AntialiasingConvergedFrames times,
# jittered and averaged: edges change from the single-frame MLAA image, flat regions do not; off
# again, the single-frame image comes back.
t.check(view.AntialiasingTemporal == 0 and view.AntialiasingConvergedFrames == 16,
        "temporal: off by default, 16 frames")
view.AntialiasingTemporal = 1
_, temporal = screenshot("mlaa-temporal.png")
changed = np.any(temporal != on, axis=2)
t.check(changed.sum() > 200, "temporal: %d edge pixels differ from single-frame MLAA"
        % changed.sum())
# (5 x 5 flat: the jitter moves edges by up to half a pixel, and the first render of the
# average is antialiased by MLAA.)
flat5 = t.uniform_neighbourhoods(off, 2)
t.check(t.max_difference(temporal[flat5], off[flat5]) == 0,
        "temporal: flat regions are unchanged (max difference %d)"
        % t.max_difference(temporal[flat5], off[flat5]))
view.SMProxy.UpdatePropertyInformation()
t.check(view.SMProxy.GetProperty("AntialiasingTemporalInfo").GetElement(0) == 1,
        "temporal: the property reaches the view's passes")
view.AntialiasingTemporal = 0
_, single = screenshot("mlaa-temporal-off.png")
t.check(np.array_equal(single, on), "temporal off: the single-frame MLAA image again")

# FXAA asked for while MLAA is on does not stack: the image stays the MLAA one.
view.UseFXAA = 1
_, with_fxaa = screenshot("mlaa-on-fxaa-asked.png")
t.check(np.array_equal(with_fxaa, on), "FXAA does not stack with MLAA")
# ... and applies again once MLAA is off.
view.UseMLAA = 0
_, fxaa_only = screenshot("fxaa-only.png")
t.check(np.any(fxaa_only != off), "FXAA applies when MLAA is off")
view.UseFXAA = 0
_, plain_again = screenshot("mlaa-off-again.png")
t.check(np.array_equal(plain_again, off), "UseMLAA off gives the plain image again")

# A screenshot with a transparent background (under IceT the pass sees the composited image over
# transparent black): the background stays transparent, and the antialiased silhouette has no
# halo. Composited over black and over white, every partly transparent pixel lies between the
# object's colour and that backdrop (within 2/255): no fringe of the background colour or of
# black. Only the orange sphere: its colour alone borders the background.
for source in list(GetSources().values()):
    Hide(source, view)
alone = Show(sphere, view)
view.UseMLAA = 1
path = os.path.join(args.output_dir, "mlaa-transparent.png")
SaveScreenshot(path, view, ImageResolution=size, TransparentBackground=1)
rgba = t.read_png(path).astype(np.float64)
t.check(rgba.shape[2] == 4 and rgba[0, 0, 3] == 0 and rgba[-1, -1, 3] == 0,
        "the background stays transparent with MLAA on")
alpha = rgba[:, :, 3:4] / 255.0
partial = (alpha[:, :, 0] > 0) & (alpha[:, :, 0] < 1)
t.check(partial.sum() > 100, "%d silhouette pixels are partly transparent" % partial.sum())
colour = np.array([0.9, 0.6, 0.1]) * 255.0
for backdrop in (0.0, 255.0):
    composite = rgba[:, :, :3] * alpha + backdrop * (1.0 - alpha)
    low = np.minimum(colour, backdrop) - 2.0
    high = np.maximum(colour, backdrop) + 2.0
    outside = np.any((composite < low) | (composite > high), axis=2) & partial
    t.check(not outside.any(), "over %s, no halo: %d pixels outside the object's colour and the "
            "backdrop" % ("black" if backdrop == 0 else "white", outside.sum()))
