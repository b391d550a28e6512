# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""MLAA and DLAA in ParaView's ordinary render view ("RenderView"), as the plugin extends it:
- the view is the plugin's class, its "Antialiasing Options" group holds AntialiasingMethod,
  AntialiasingKeepAlpha, AntialiasingMultiSamples, AntialiasingSampleShading, MLAALineLengths
  and the MLAA and DLAA
  settings, and the method's GUI
  label names DLAA as "DLAA (Andreev 2011, directionally localized antialiasing)";
- AntialiasingMethod "None or FXAA" (the default) gives the plain image; MLAA gives, within
  2/255, the `mlaa` tool's result on the plain screenshot (edge pixels change, flat regions do
  not), with the defaults and with a preset; DLAA the same with --method dlaa; FXAA asked for
  does not stack; MLAALineLengths reaches the pass and gives the same image with each method;
- AntialiasingMultiSamples 4: on one rank another image than single-sample MLAA's (flat regions
  unchanged); under IceT single-sample MLAA's image (the composited image has one sample);
  AntialiasingSampleShading (on by default) reaches the view, and off changes the image on one
  rank and nothing under IceT;
- AntialiasingKeepAlpha reaches both passes; off, transparent screenshots (which ParaView
  derives from renders over white and over black) have antialiased silhouette alpha; on, one
  process's result changes, and under IceT nothing does;
- backgrounds: a gradient is handled on one rank and under IceT (the image equals the tool's on
  the plain screenshot); a texture is handled on one rank and, under IceT, refused with a
  warning (the image is left plain); a sky box likewise;
- views of other classes built on RenderView's proxy take the properties without error."""

import os

import numpy as np

import mlaa_pvtest as t

args = t.parse_arguments()

from paraview.simple import *  # noqa: E402,F403
from paraview import servermanager as sm  # noqa: E402

t.load_plugin(args.plugin, globals())
t.check(t.number_of_ranks() == args.ranks, "pvbatch runs on %d rank(s)" % args.ranks)

DLAA_LABEL = "DLAA (Andreev 2011, directionally localized antialiasing)"

view = CreateRenderView()
t.check(view.GetXMLName() == "RenderView", "the ordinary render view")
t.check(view.GetClientSideObject().GetClassName() == "vtkMLAARenderView",
        "its object is the plugin's vtkMLAARenderView (the object-factory override)")
t.check(view.AntialiasingMethod == "None or FXAA" and view.AntialiasingKeepAlpha == 0 and
        view.MLAALineLengths == "Automatic" and view.MLAAQualityPreset == "Custom",
        "defaults: AntialiasingMethod None or FXAA, AntialiasingKeepAlpha off, MLAALineLengths "
        "Automatic, MLAAQualityPreset Custom")
domain = view.GetProperty("AntialiasingMethod").SMProperty.GetDomain("enum")
entries = [domain.GetEntryText(i) for i in range(domain.GetNumberOfEntries())]
t.check(entries == ["None or FXAA", "MLAA", DLAA_LABEL],
        "the method's entries (GUI labels): %s" % entries)
groups = {}
for i in range(view.SMProxy.GetNumberOfPropertyGroups()):
    group = view.SMProxy.GetPropertyGroup(i)
    groups.setdefault(group.GetXMLLabel(), []).extend(
        view.SMProxy.GetPropertyName(group.GetProperty(j))
        for j in range(group.GetNumberOfProperties()))
antialiasing = groups.get("Antialiasing Options", [])
expected = ["AntialiasingMethod", "AntialiasingKeepAlpha", "AntialiasingMultiSamples",
            "AntialiasingSampleShading", "MLAALineLengths", "MLAAQualityPreset",
            "MLAAThreshold", "MLAAEdgeDetection", "DLAALambda", "DLAALongEdges"]
t.check(all(name in antialiasing for name in expected),
        "the view's Antialiasing Options group holds %s (it has %d properties)"
        % (", ".join(expected), len(antialiasing)))
undocumented = [name for name in antialiasing
                if view.SMProxy.GetProperty(name).GetDocumentation() is None or
                not view.SMProxy.GetProperty(name).GetDocumentation().GetDescription().strip()]
t.check(not undocumented, "every property of the group has help text (undocumented: %s)"
        % undocumented)
documentation = view.GetProperty("AntialiasingMethod").SMProperty.GetDocumentation()
t.check(documentation is not None and DLAA_LABEL[:-1] in " ".join(
            documentation.GetDescription().split()),
        "AntialiasingMethod has help text (Documentation) naming DLAA in full")

size = [400, 300]
view.ViewSize = size
view.OrientationAxesVisibility = 0
view.UseColorPaletteForBackground = 0
view.Background = [0.32, 0.34, 0.43]
view.UseFXAA = 0  # ParaView's settings may turn it on for every view: the plain image has none

sphere = Sphere(ThetaResolution=64, PhiResolution=64, Radius=0.5)
scene = []
for source, colour in ((sphere, [0.9, 0.6, 0.1]),
                       (Cone(Resolution=7, Center=[0.7, 0.2, 0.0], Radius=0.35), [0.2, 0.8, 0.3]),
                       (Sphere(Center=[-0.55, 0.45, 0.0], Radius=0.2), [0.03, 0.03, 0.04])):
    scene.append(source)
    display = Show(source, view)
    display.ColorArrayName = ['POINTS', '']
    display.AmbientColor = colour
    display.DiffuseColor = colour
    display.Ambient = 1.0
    display.Diffuse = 0.0
if args.ranks > 1:
    t.check_split(sphere, args.ranks, "sphere")
view.CameraPosition = [0.4, 0.5, 4.0]
view.CameraFocalPoint = [0.0, 0.0, 0.0]
view.CameraViewUp = [0.2, 1.0, 0.0]
view.CameraViewAngle = 30


def server_value(name, of=None):
    """An information property of a view (default: `view`): what its server object holds."""
    proxy = (of or view).SMProxy
    proxy.UpdatePropertyInformation()
    return proxy.GetProperty(name).GetElement(0)


def screenshot(name, transparent=0):
    path = os.path.join(args.output_dir, name)
    SaveScreenshot(path, view, ImageResolution=size, TransparentBackground=transparent)
    rows = t.read_png(path)
    return path, (rows if transparent else rows[:, :, :3])


def check_against_tool(label, image, plain_path, plain, tool_arguments, radius=1, flat=0):
    """image is the tool's result on the plain screenshot within 2/255, with edge pixels changed
    and flat regions not (by more than `flat`)."""
    changed = np.any(image != plain, axis=2)
    t.check(changed.sum() > 200, "%s: %d edge pixels are antialiased" % (label, changed.sum()))
    uniform = t.uniform_neighbourhoods(plain, radius)
    difference = t.max_difference(image[uniform], plain[uniform])
    t.check(difference <= flat, "%s: flat regions are unchanged (max difference %d)"
            % (label, difference))
    reference = t.run_tool(args.tool, tool_arguments, plain_path, os.path.join(
        args.output_dir, "reference-%s.png" % label.replace(" ", "-")))[:, :, :3]
    difference = t.max_difference(image, reference)
    t.check(difference <= 2, "%s: the view's image equals the mlaa tool's on the plain "
            "screenshot within 2/255 (max difference %d)" % (label, difference))


plain_path, plain = screenshot("none.png")
view.AntialiasingMethod = "MLAA"
_, mlaa = screenshot("mlaa.png")
check_against_tool("MLAA", mlaa, plain_path, plain, [])
view.MLAAQualityPreset = "Low"
_, low = screenshot("mlaa-low.png")
t.check(np.any(low != mlaa), "MLAAQualityPreset Low changes %d pixels of the image"
        % np.any(low != mlaa, axis=2).sum())
check_against_tool("MLAA Low", low, plain_path, plain, ["--preset", "low"])
view.MLAAQualityPreset = "Custom"

# The line-length methods reach the pass and give the same image (32 search steps or more would
# make Automatic choose recursive doubling; the defaults' 16 the search loop).
for name in ("SearchLoop", "RecursiveDoubling", "Automatic"):
    view.MLAALineLengths = name
    _, image = screenshot("mlaa-%s.png" % name)
    value = server_value("MLAALineLengthsInfo")
    t.check(value == ["Automatic", "SearchLoop", "RecursiveDoubling"].index(name) and
            np.array_equal(image, mlaa),
            "MLAALineLengths %s reaches the pass (%d) and gives the same image" % (name, value))

view.UseFXAA = 1
_, with_fxaa = screenshot("mlaa-fxaa-asked.png")
t.check(np.array_equal(with_fxaa, mlaa), "FXAA asked for does not stack with MLAA")
view.AntialiasingMethod = "None or FXAA"
_, fxaa = screenshot("fxaa.png")
t.check(np.any(fxaa != plain), "None or FXAA with UseFXAA on: FXAA applies")
view.UseFXAA = 0

view.AntialiasingMethod = DLAA_LABEL
view.DLAALambda = 5
_, dlaa = screenshot("dlaa.png")
check_against_tool("DLAA", dlaa, plain_path, plain, ["--method", "dlaa", "--dlaa-lambda", "5"],
                   radius=10)
view.DLAALambda = 3

# AntialiasingMultiSamples: on one rank the view renders 4 samples per pixel and MLAA runs on
# each sample set (another image than single-sample MLAA's; flat regions unchanged); under IceT
# MLAA runs on the composited image, one sample per pixel, so the image is single-sample MLAA's.
view.AntialiasingMethod = "MLAA"
view.AntialiasingMultiSamples = "4"
_, mlaa_samples = screenshot("mlaa-4-samples.png")
t.check(server_value("AntialiasingMultiSamplesInfo") == 4,
        "AntialiasingMultiSamples 4 reaches the view")
if args.ranks == 1:
    differs = np.any(mlaa_samples != mlaa, axis=2).sum()
    t.check(differs > 100, "4 samples: %d pixels differ from single-sample MLAA" % differs)
    uniform = t.uniform_neighbourhoods(plain, 2)
    difference = t.max_difference(mlaa_samples[uniform], plain[uniform])
    t.check(difference == 0, "4 samples: flat regions are unchanged (max difference %d)"
            % difference)
else:
    t.check(np.array_equal(mlaa_samples, mlaa),
            "under IceT, AntialiasingMultiSamples gives single-sample MLAA's image")
# AntialiasingSampleShading off: each pixel shaded once for all its samples (on by default).
t.check(server_value("AntialiasingSampleShadingInfo") == 1, "AntialiasingSampleShading is on")
view.AntialiasingSampleShading = 0
_, mlaa_pixel_shaded = screenshot("mlaa-4-samples-pixel-shaded.png")
t.check(server_value("AntialiasingSampleShadingInfo") == 0,
        "AntialiasingSampleShading 0 reaches the view")
if args.ranks == 1:
    differs = np.any(mlaa_pixel_shaded != mlaa_samples, axis=2).sum()
    t.check(differs > 0, "4 samples shaded per pixel: %d pixels differ from shaded per sample"
            % differs)
else:
    t.check(np.array_equal(mlaa_pixel_shaded, mlaa),
            "under IceT, AntialiasingSampleShading changes nothing (single-sample MLAA)")
view.AntialiasingSampleShading = 1
view.AntialiasingMultiSamples = "Off"
_, mlaa_again = screenshot("mlaa-again.png")
t.check(np.array_equal(mlaa_again, mlaa), "AntialiasingMultiSamples Off: single-sample MLAA again")

view.AntialiasingMethod = "None or FXAA"
_, plain_again = screenshot("none-again.png")
t.check(np.array_equal(plain_again, plain), "None or FXAA gives the plain image back")

# AntialiasingKeepAlpha. ParaView's screenshots with TransparentBackground never read the
# window's alpha: they render the view over white and over black and derive alpha from the two.
# With KeepAlpha off (the default) MLAA runs on both opaque renders, so the silhouettes of the
# orange sphere get partial alpha. KeepAlpha reaches both passes; on one process it changes the
# result (the pass then finds edges in the window's alpha, 0 on the background); under IceT the
# background is put under the image first, so alpha is 1 everywhere and it changes nothing.
for source in scene:
    Hide(source, view)
Show(sphere, view)
view.AntialiasingMethod = "MLAA"
alpha = {}
for keep in (0, 1):
    view.AntialiasingKeepAlpha = keep
    _, rgba = screenshot("mlaa-transparent-keepalpha-%d.png" % keep, transparent=1)
    t.check(rgba.shape[2] == 4 and rgba[0, 0, 3] == 0 and rgba[-1, -1, 3] == 0,
            "KeepAlpha %d: the background is transparent" % keep)
    alpha[keep] = rgba[:, :, 3]
    t.check(server_value("AntialiasingKeepAlphaInfo") == keep,
            "AntialiasingKeepAlpha %d reaches both passes" % keep)
partial = np.sum((alpha[0] > 0) & (alpha[0] < 255))
t.check(partial > 100, "KeepAlpha off: %d partly transparent silhouette pixels" % partial)
changed = np.sum(alpha[1] != alpha[0])
if args.ranks == 1:
    t.check(changed > 100, "KeepAlpha on changes %d pixels of the alpha channel" % changed)
else:
    t.check(changed == 0, "under IceT KeepAlpha changes nothing (the background is under the "
            "image)")
view.AntialiasingKeepAlpha = 0
for source in scene:
    Show(source, view)

# Backgrounds. A gradient: handled on one rank and under IceT.
view.BackgroundColorMode = "Gradient"
view.Background2 = [0.75, 0.8, 0.9]
view.AntialiasingMethod = "None or FXAA"
gradient_path, gradient_plain = screenshot("gradient-none.png")
t.check(np.any(gradient_plain[0] != gradient_plain[-1]), "the gradient is drawn")
view.AntialiasingMethod = "MLAA"
_, gradient_mlaa = screenshot("gradient-mlaa.png")
# Under IceT the view draws the gradient under the composited image itself, and its rounding
# differs from the renderer's by 1/255 on some rows (measured): flat regions within 1.
check_against_tool("MLAA gradient", gradient_mlaa, gradient_path, gradient_plain, [],
                   flat=1 if args.ranks > 1 else 0)

# A texture: handled on one rank; under IceT it cannot be put under the composited image, and
# the view refuses with a warning, leaving the image plain.
texture_png = os.path.join(args.output_dir, "texture.png")
ys, xs = np.mgrid[0:64, 0:64]
checker = (((ys // 8) + (xs // 8)) % 2).astype(np.uint8)
t.write_png(texture_png, np.stack([60 + 80 * checker, 70 + 60 * checker,
                                   90 + 40 * checker], axis=2).astype(np.uint8))
view.BackgroundTexture = CreateTexture(texture_png)
view.BackgroundColorMode = "Texture"
warnings = []


def on_warning(caller, event, message=None):
    warnings.append(message)


from vtkmodules.util.misc import calldata_type  # noqa: E402
from vtkmodules.util.vtkConstants import VTK_STRING  # noqa: E402
on_warning = calldata_type(VTK_STRING)(on_warning)
observer = view.GetClientSideObject().AddObserver("WarningEvent", on_warning)
view.AntialiasingMethod = "None or FXAA"
texture_path, texture_plain = screenshot("texture-none.png")
view.AntialiasingMethod = "MLAA"
_, texture_mlaa = screenshot("texture-mlaa.png")
if args.ranks == 1:
    check_against_tool("MLAA texture", texture_mlaa, texture_path, texture_plain, [])
    t.check(not warnings, "one rank: no warning about the texture")
else:
    t.check(np.array_equal(texture_mlaa, texture_plain),
            "under IceT, with a texture background, the image is left without MLAA")
    t.check(len(warnings) == 1 and "textured or sky-box background" in warnings[0],
            "... and the view says why, once: %r" % (warnings[:1],))
# A sky box (the same texture on a sphere around the scene): the same on several ranks.
view.BackgroundColorMode = "Skybox"
view.AntialiasingMethod = "None or FXAA"
skybox_path, skybox_plain = screenshot("skybox-none.png")
view.AntialiasingMethod = "MLAA"
_, skybox_mlaa = screenshot("skybox-mlaa.png")
if args.ranks > 1:
    t.check(np.array_equal(skybox_mlaa, skybox_plain) and len(warnings) == 2 and
            "textured or sky-box background" in warnings[1],
            "under IceT, with a sky box, the image is left without MLAA, with a warning")
else:
    check_against_tool("MLAA sky box", skybox_mlaa, skybox_path, skybox_plain, [])
    t.check(not warnings, "one rank: no warning about the sky box")
view.GetClientSideObject().RemoveObserver(observer)

# Views of other classes whose proxies are built on RenderView's (ParaView's Eye-Dome Lighting,
# orthographic-slice and multi-slice views) inherit the properties; on them the properties do
# nothing, and no error is reported (CTest fails the test on "ERR|").
for name in ("RenderViewWithEDL", "OrthographicSliceView", "MultiSlice"):
    other = CreateView(name)
    other.ViewSize = [100, 80]
    other.AntialiasingMethod = "MLAA"
    other.AntialiasingKeepAlpha = 1
    other.MLAAThreshold = 0.2
    Show(sphere, other)
    Render(other)
    t.check(other.GetClientSideObject().GetClassName() != "vtkMLAARenderView" and
            server_value("AntialiasingKeepAlphaInfo", other) == 0,
            "%s (%s): the properties are there and inert" % (
                name, other.GetClientSideObject().GetClassName()))
    Delete(other)
