# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""The plugin in the ParaView GUI: run as the GUI's start-up script,

    PV_PLUGIN_PATH=DIR paraview --script=TestMLAAGui.py

with MLAA_GUI_OUTPUT_DIR (where the screenshots go) and MLAA_TOOL (the main project's mlaa
tool, the reference) in the environment; CTest gives the GUI a settings file without the
welcome dialog. The plugin, loaded at start-up through PV_PLUGIN_PATH, gives the GUI's own
session the antialiasing properties in its ordinary render view (the one the GUI opens at
start-up) and the filters: with AntialiasingMethod MLAA, the view antialiases its screenshots
(edge pixels change, flat regions do not, and the image equals the mlaa tool's on the screenshot
with "None or FXAA" within 2/255), and MLAAAntialiasing runs.

The GUI keeps running after a start-up script, so this one ends the process itself with its
exit status (0: passed) after writing what it checked to result.txt in the output directory."""
import os
import traceback

output_dir = os.environ.get("MLAA_GUI_OUTPUT_DIR", ".")
os.makedirs(output_dir, exist_ok=True)
log = open(os.path.join(output_dir, "result.txt"), "w")


def say(message):
    log.write(message + "\n")
    log.flush()
    print(message, flush=True)


class Failed(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failed(message)
    say("ok: " + message)


def main():
    import numpy as np
    from paraview import simple
    import mlaa_pvtest

    # The render view the GUI opened at start-up, after loading the plugin: the ordinary
    # RenderView, with the plugin's antialiasing properties.
    view = simple.GetActiveView()
    check(view is not None and view.GetXMLName() == "RenderView" and
          view.GetProperty("AntialiasingMethod") is not None and
          view.AntialiasingMethod == "None or FXAA",
          "the GUI's own render view has AntialiasingMethod, None or FXAA by default")
    labels = view.GetProperty("AntialiasingMethod").Available
    check(labels == ["None or FXAA", "MLAA",
                     "DLAA (Andreev 2011, directionally localized antialiasing)"],
          "the method's labels in the GUI: %s" % labels)
    view.AntialiasingMethod = "MLAA"
    # The GUI's settings turn FXAA on in every render view (UseFXAA is 1 here): the view holds
    # it off while MLAA is on, so the MLAA screenshot is taken as the settings leave it; the
    # screenshot with MLAA off, the reference's input, must be the plain render.
    say("UseFXAA from the GUI's settings: %d" % view.UseFXAA)
    view.OrientationAxesVisibility = 0
    view.Background = [0.32, 0.34, 0.43]
    sphere = simple.Sphere(ThetaResolution=32, PhiResolution=32)
    display = simple.Show(sphere, view)
    display.AmbientColor = display.DiffuseColor = [0.95, 0.75, 0.2]
    simple.Render(view)

    mlaa_png = os.path.join(output_dir, "gui-mlaa.png")
    plain_png = os.path.join(output_dir, "gui-plain.png")
    # Screenshots at the view's own size (at another size ParaView renders again or resamples).
    size = list(view.ViewSize)
    simple.SaveScreenshot(mlaa_png, view, ImageResolution=size)
    view.AntialiasingMethod = "None or FXAA"
    view.UseFXAA = 0
    simple.Render(view)
    simple.SaveScreenshot(plain_png, view, ImageResolution=size)

    with_mlaa = mlaa_pvtest.read_png(mlaa_png)[:, :, :3].astype(int)
    plain = mlaa_pvtest.read_png(plain_png)[:, :, :3].astype(int)
    changed = np.any(with_mlaa != plain, axis=2)
    flat = mlaa_pvtest.uniform_neighbourhoods(plain[:, :, :3])
    check(changed.sum() > 100, "MLAA changed %d edge pixels" % changed.sum())
    check(not np.any(changed & flat), "no pixel of a flat region changed")
    reference = mlaa_pvtest.run_tool(os.environ["MLAA_TOOL"], [], plain_png,
                                     os.path.join(output_dir, "gui-tool.png"))[:, :, :3]
    difference = np.abs(reference.astype(int) - with_mlaa).max()
    check(difference <= 2, "the screenshot equals the mlaa tool's within 2/255, so FXAA did not "
          "stack (largest difference %d)" % difference)

    smooth = simple.MLAAAntialiasing(Input=simple.Wavelet())
    smooth.UpdatePipeline()
    check(smooth.GetDataInformation().GetNumberOfPoints() == 21 ** 3,
          "MLAAAntialiasing runs in the GUI's session")


status = 1
try:
    main()
    say("passed")
    status = 0
except Failed as failure:
    say("FAIL: %s" % failure)
except BaseException:  # mlaa_pvtest's checks end with SystemExit
    say("FAIL: " + traceback.format_exc())
log.close()
os._exit(status)
