# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""The vtkmlaa package's surface: every wrapped class importable from vtkmlaa (and from its
extension modules), docstrings from the C++ class comments, the options and presets as the C++
classes define them, and enable()'s validation of its arguments."""
import inspect
import os
import re
import sys
import warnings

import vtkmlaa
from vtkmlaa import (vtkDLAAOptions, vtkImageAntialiasingAlgorithm, vtkImageDLAA, vtkImageMLAA,
                     vtkMLAAAreaTexture, vtkMLAAOptions, vtkMLAATopology,
                     vtkOpenGLAntialiasingPass, vtkOpenGLDLAAPass, vtkOpenGLMLAAPass)
from vtkmodules.vtkCommonExecutionModel import vtkImageAlgorithm
from vtkmodules.vtkRenderingOpenGL2 import vtkImageProcessingPass
from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer
from vtkmlaa_testing import Checker

check = Checker()

# The public classes of each module, as its CMakeLists.txt lists them (`set(classes ...)`), so
# that a class added to a module and not wrapped fails here. Usage: this script SOURCE_DIR
source_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..", "..")


def listed_classes(directory):
    with open(os.path.join(source_dir, directory, "CMakeLists.txt")) as f:
        match = re.search(r"set\(classes\s+([^)]*)\)", f.read())
    return match.group(1).split() if match else []


classes = {"vtkFiltersMLAA": listed_classes("Filters"),
           "vtkRenderingMLAA": listed_classes("Rendering")}
check("vtkImageMLAA" in classes["vtkFiltersMLAA"] and
      "vtkOpenGLMLAAPass" in classes["vtkRenderingMLAA"], "the class lists were read: %s" % classes)
for module_name, names in classes.items():
    module = getattr(vtkmlaa, module_name)
    check(module.__name__ == "vtkmlaa." + module_name, "module name " + module.__name__)
    for name in names:
        cls = getattr(module, name, None)
        check(cls is not None and cls is getattr(vtkmlaa, name, None),
              "vtkmlaa.%s is vtkmlaa.%s.%s" % (name, module_name, name))
        check(name in vtkmlaa.__all__, name + " in __all__")
wrapped = sorted(n for n in vtkmlaa.__all__ if n.startswith("vtk"))
check(wrapped == sorted(sum(classes.values(), [])), "exactly the public classes: %s" % wrapped)
for internal in ("vtkMLAAStages", "vtkDLAAStages", "vtkOpenGLAntialiasingPassInternals"):
    check(not hasattr(vtkmlaa, internal), internal + " is not wrapped")

# The classes compose with VTK's.
check(issubclass(vtkImageMLAA, vtkImageAntialiasingAlgorithm), "vtkImageMLAA's base")
check(issubclass(vtkImageAntialiasingAlgorithm, vtkImageAlgorithm), "an image algorithm")
check(issubclass(vtkOpenGLMLAAPass, vtkOpenGLAntialiasingPass), "vtkOpenGLMLAAPass's base")
check(issubclass(vtkOpenGLAntialiasingPass, vtkImageProcessingPass), "an image pass")
for cls in (vtkImageMLAA, vtkImageDLAA, vtkOpenGLMLAAPass, vtkOpenGLDLAAPass, vtkMLAAOptions,
            vtkDLAAOptions, vtkMLAAAreaTexture, vtkMLAATopology):
    check(cls().GetClassName() == cls.__name__, cls.__name__ + "() creates its class")

# Docstrings come from the header comments.
check("morphological antialiasing" in (vtkImageMLAA.__doc__ or "").lower(),
      "vtkImageMLAA.__doc__ describes MLAA")
check("Andreev" in (vtkDLAAOptions.__doc__ or ""), "vtkDLAAOptions.__doc__ cites the talk")
# "DLAA" alone now mostly means a learned method: the package says which one it is.
check("DLAA (Andreev 2011, directionally localized antialiasing)" in " ".join(
    (vtkmlaa.__doc__ or "").split()), "vtkmlaa.__doc__ says which DLAA")
check("preset" in (vtkMLAAOptions.SetPreset.__doc__ or "").lower(),
      "method docstrings: vtkMLAAOptions.SetPreset")
check("Threshold" in inspect.getdoc(vtkMLAAOptions), "help() text of vtkMLAAOptions")
check("enable" in vtkmlaa.__doc__ and "PyVista" in vtkmlaa.enable.__doc__,
      "the package documents enable()")

# Options and presets, named as the C++ class names them.
options = vtkMLAAOptions()
check(options.GetPreset() == vtkMLAAOptions.HIGH, "the defaults are the high preset")
options.SetPresetToLow()
check(options.GetPreset() == vtkMLAAOptions.LOW and options.GetMaxSearchSteps() == 4,
      "SetPresetToLow")
options.SetThreshold(0.2)
check(options.GetPreset() == -1, "an option set after a preset overrides it")
check(vtkmlaa.PRESETS == ("low", "medium", "high", "ultra", "max"), "PRESETS %s" % (vtkmlaa.PRESETS,))
options.SetPresetToMax()
check(options.GetPreset() == vtkMLAAOptions.MAX and options.GetReconstruction(), "SetPresetToMax")
for preset in vtkmlaa.PRESETS:
    check(vtkMLAAOptions.GetPresetAsString(vtkMLAAOptions.GetPresetFromString(preset)) == preset,
          "preset name round trip " + preset)
check(vtkMLAAOptions.GetEdgeDetectionFromString("luma") == vtkMLAAOptions.LUMA, "edge names")
check(vtkDLAAOptions.GetLumaFunctionFromString("green") == vtkDLAAOptions.GREEN, "luma names")
shared = vtkMLAAOptions()
shared.SetPresetToUltra()
mlaa, mlaa_pass = vtkImageMLAA(), vtkOpenGLMLAAPass()
mlaa.SetOptions(shared)
mlaa_pass.SetOptions(shared)
check(mlaa.GetOptions() is shared and mlaa_pass.GetOptions() is shared, "one shared options")

# enable() and disable() on a renderer (nothing is rendered here). A renderer outside a window
# gets the pass and a warning (its window's multisampling is not known yet).
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    vtkmlaa.enable(vtkRenderer())
check(len(caught) == 1 and "SetMultiSamples(0)" in str(caught[0].message),
      "enable() warns about a renderer without a window")
window = vtkRenderWindow()
renderer = vtkRenderer()
window.AddRenderer(renderer)
check(window.GetMultiSamples() > 0, "a window multisamples by default")
with warnings.catch_warnings():
    warnings.simplefilter("error")
    vtkmlaa.enable(renderer)
check(window.GetMultiSamples() == 0, "enable turns the window's multisampling off")
p = vtkmlaa.enable(renderer, preset="ultra", threshold=0.08, max_search_steps=24,
                   edge_detection="luma", KeepAlpha=True)
check(isinstance(p, vtkOpenGLMLAAPass) and renderer.GetPass() is p, "enable installs the pass")
o = p.GetOptions()
check(abs(o.GetThreshold() - 0.08) < 1e-12 and o.GetMaxSearchSteps() == 24 and
      o.GetEdgeDetection() == vtkMLAAOptions.LUMA and p.GetKeepAlpha(),
      "enable applies the options after the preset")
check(p.GetDelegatePass().GetClassName() == "vtkRenderStepsPass", "the delegate")
p = vtkmlaa.enable(renderer, "DLAA", lambda_=5, luma_function="green")
check(isinstance(p, vtkOpenGLDLAAPass) and renderer.GetPass() is p and
      p.GetOptions().GetLumaFunction() == vtkDLAAOptions.GREEN and
      p.GetOptions().GetLambda() == 5, "enable(method='dlaa') and its options (lambda_: Lambda)")
check(vtkmlaa.disable(renderer) and renderer.GetPass() is None, "disable removes the pass")
check(not vtkmlaa.disable(renderer), "disable without a pass")

for kwargs, error in (({"preset": "extreme"}, ValueError),
                      ({"method": "fxaa"}, ValueError),
                      ({"thresold": 0.1}, ValueError),
                      ({"debug": True}, ValueError),
                      ({"threshold": "low"}, ValueError),
                      ({"threshold": 3.0}, ValueError),
                      ({"edge_detection": "sobel"}, ValueError),
                      ({"method": "dlaa", "preset": "high"}, ValueError)):
    try:
        vtkmlaa.enable(renderer, **kwargs)
        check(False, "enable(%s) raises %s" % (kwargs, error.__name__))
    except error as e:
        check(str(e) != "", "enable(%s): %s" % (kwargs, e))
try:
    vtkmlaa.enable("renderer")
    check(False, "enable on a string raises TypeError")
except TypeError:
    pass
check(renderer.GetPass() is None, "a refused enable() leaves the renderer alone")

check.finish()
