# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""The properties of the MLAAAntialiasing filter, the ordinary render view (which the plugin
extends), the older MLAA render view and the DLAAAntialiasing filter: their defaults are
vtkMLAAOptions's and vtkDLAAOptions's own (read back from the server objects through the options
proxies' information properties), and QualityPreset replaces the quality settings while it is
chosen, whatever order the properties are set in, and gives them back under Custom. A state file
keeps the render view's antialiasing."""

import mlaa_pvtest as t

args = t.parse_arguments()

from paraview.simple import *  # noqa: E402,F403

t.load_plugin(args.plugin, globals())

settings = ["Threshold", "LocalContrastFactor", "EdgeDetection", "MaxSearchSteps",
            "DiagonalDetection", "CornerExtrapolation", "DominantDirectionBlending",
            "Reconstruction", "PremultipliedAlpha", "DebugOutput"]


def effective(options_proxy):
    """The settings in effect in the server's vtkPVMLAAOptions."""
    options_proxy.UpdatePropertyInformation()
    return {name: options_proxy.GetProperty(name + "Info").GetElement(0) for name in settings}


def property_values(options_proxy):
    return {name: options_proxy.GetProperty(name).GetElement(0) for name in settings}


def preset_values(preset):
    """The quality settings of a preset, as vtkMLAAOptions's class description lists them."""
    return {
        "Low": dict(Threshold=0.15, EdgeDetection=0, MaxSearchSteps=4, DiagonalDetection=0,
                    CornerExtrapolation=0),
        "Ultra": dict(Threshold=0.05, EdgeDetection=3, MaxSearchSteps=32, DiagonalDetection=1,
                      CornerExtrapolation=0),
    }[preset]


def close(a, b):
    return abs(a - b) < 1e-9


image = Wavelet()
mlaa = MLAAAntialiasing(Input=image)
view = CreateView("MLAARenderView")
render_view = CreateView("RenderView")
# The options proxy of each is the one its exposed properties belong to.
for label, proxy, options, prefix in (
        ("filter", mlaa, mlaa.GetProperty("Threshold").SMProperty.GetParent(), ""),
        ("render view", render_view,
         render_view.GetProperty("MLAAThreshold").SMProperty.GetParent(), "MLAA"),
        ("MLAA view", view, view.GetProperty("MLAAThreshold").SMProperty.GetParent(), "MLAA")):
    defaults = property_values(options)
    in_effect = effective(options)
    t.check(all(close(defaults[n], in_effect[n]) for n in settings),
            "%s: the properties' defaults are vtkMLAAOptions's (%s)" % (label, in_effect))
    t.check(proxy.GetPropertyValue(prefix + "QualityPreset") == "Custom",
            "%s: QualityPreset is Custom" % label)

    # A preset and a setting set together, the setting first and then the other way round.
    for order in ("setting first", "preset first"):
        if order == "setting first":
            proxy.SetPropertyWithName(prefix + "Threshold", 0.3)
            proxy.SetPropertyWithName(prefix + "QualityPreset", "Low")
        else:
            proxy.SetPropertyWithName(prefix + "QualityPreset", "Low")
            proxy.SetPropertyWithName(prefix + "Threshold", 0.3)
        proxy.UpdateVTKObjects()
        in_effect = effective(options)
        expected = preset_values("Low")
        t.check(all(close(in_effect[n], v) for n, v in expected.items()),
                "%s, %s: the Low preset is in effect (%s)" % (label, order, in_effect))
        proxy.SetPropertyWithName(prefix + "QualityPreset", "Custom")
        proxy.UpdateVTKObjects()
        in_effect = effective(options)
        t.check(close(in_effect["Threshold"], 0.3) and in_effect["EdgeDetection"] == 3 and
                in_effect["MaxSearchSteps"] == 16,
                "%s, %s: Custom gives the settings back (%s)" % (label, order, in_effect))
        proxy.SetPropertyWithName(prefix + "Threshold", defaults["Threshold"])

    # CornerExtrapolation (off by default and in every preset) reaches the options under
    # Custom; it is kept on for Ultra below, which must turn it off.
    t.check(in_effect["CornerExtrapolation"] == 0, "%s: CornerExtrapolation is off by default"
            % label)
    proxy.SetPropertyWithName(prefix + "CornerExtrapolation", 1)
    proxy.UpdateVTKObjects()
    in_effect = effective(options)
    t.check(in_effect["CornerExtrapolation"] == 1,
            "%s: CornerExtrapolation on reaches the options (%s)" % (label, in_effect))

    proxy.SetPropertyWithName(prefix + "QualityPreset", "Ultra")
    proxy.SetPropertyWithName(prefix + "DebugOutput", "Edges")
    proxy.UpdateVTKObjects()
    in_effect = effective(options)
    t.check(all(close(in_effect[n], v) for n, v in preset_values("Ultra").items()) and
            in_effect["DebugOutput"] == 1,
            "%s: Ultra and DebugOutput apply together (%s)" % (label, in_effect))
    proxy.SetPropertyWithName(prefix + "QualityPreset", "Custom")
    proxy.UpdateVTKObjects()
    in_effect = effective(options)
    t.check(in_effect["CornerExtrapolation"] == 1 and close(in_effect["Threshold"],
                                                            defaults["Threshold"]),
            "%s: Custom gives CornerExtrapolation back (%s)" % (label, in_effect))

# The DLAA filter's settings: its properties' defaults are vtkDLAAOptions's.
dlaa = DLAAAntialiasing(Input=image)
dlaa_options = dlaa.GetProperty("Epsilon").SMProperty.GetParent()
dlaa_options.UpdatePropertyInformation()
dlaa_settings = ["Epsilon", "Lambda", "LumaFunction", "LongEdges"]
defaults = {n: dlaa_options.GetProperty(n).GetElement(0) for n in dlaa_settings}
in_effect = {n: dlaa_options.GetProperty(n + "Info").GetElement(0) for n in dlaa_settings}
t.check(all(close(defaults[n], in_effect[n]) for n in dlaa_settings),
        "DLAA filter: the properties' defaults are vtkDLAAOptions's (%s)" % in_effect)
dlaa.Lambda = 7.5
dlaa.LumaFunction = "Green"
dlaa.UpdatePipeline()
dlaa_options.UpdatePropertyInformation()
t.check(close(dlaa_options.GetProperty("LambdaInfo").GetElement(0), 7.5) and
        dlaa_options.GetProperty("LumaFunctionInfo").GetElement(0) == 1,
        "DLAA filter: the properties reach vtkImageDLAA's options")

# The GUI's name for the method: the DLAA filter's help (its tooltip in the Filters menu) names
# it in full once, since "DLAA" most often means a learned method of the same initials now.
short_help = dlaa.SMProxy.GetDocumentation().GetShortHelp()
t.check("DLAA (Andreev 2011, directionally localized antialiasing)" in short_help,
        "DLAA filter: its short help names the method in full (%r)" % short_help)

# A state file keeps the render view's antialiasing: saved, the session reset, loaded back.
import os  # noqa: E402
state = os.path.join(args.output_dir, "render-view.pvsm")
dlaa_label = "DLAA (Andreev 2011, directionally localized antialiasing)"
render_view.AntialiasingMethod = dlaa_label
render_view.DLAALambda = 6.5
render_view.MLAALineLengths = "RecursiveDoubling"
SetActiveView(render_view)
SaveState(state)
ResetSession()
t.check(not [v for v in GetViews() if v.GetXMLName() == "RenderView" and
             v.GetProperty("AntialiasingMethod") is not None and v.DLAALambda == 6.5],
        "after ResetSession no view has the saved settings")
LoadState(state)
restored = [v for v in GetViews() if v.GetXMLName() == "RenderView" and v.DLAALambda == 6.5]
t.check(len(restored) == 1 and restored[0].AntialiasingMethod == dlaa_label and
        restored[0].MLAALineLengths == "RecursiveDoubling",
        "the state file restores AntialiasingMethod, DLAALambda and MLAALineLengths")
restored[0].SMProxy.UpdatePropertyInformation()
t.check(restored[0].SMProxy.GetProperty("MLAALineLengthsInfo").GetElement(0) == 2,
        "... and they reach the restored view's object")
