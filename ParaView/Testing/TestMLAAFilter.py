# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""The MLAAAntialiasing and DLAAAntialiasing filters on a distributed image: their output equals
that of vtkImageMLAA and vtkImageDLAA run outside ParaView (the main project's `mlaa` tool) on
the same whole image, with the default settings, custom settings and (MLAA) a preset, on one
rank and on several (the filters ask for their padding through the update extent, so pieces
have no seams)."""

import os

import numpy as np

import mlaa_pvtest as t

args = t.parse_arguments()

from paraview.simple import *  # noqa: E402,F403
from paraview import servermanager as sm  # noqa: E402

t.load_plugin(args.plugin, globals())
t.check(t.number_of_ranks() == args.ranks, "pvbatch runs on %d rank(s)" % args.ranks)

# An RGB image with aliased curved edges: thresholds of the Wavelet source, which ParaView
# splits across the ranks by extent.
whole = [-80, 79, -60, 59, 0, 0]
wavelet = Wavelet(WholeExtent=whole)
image = Calculator(Input=wavelet, ResultArrayName="rgb", ResultArrayType="Unsigned Char")
image.Function = "iHat*255*(RTData>130) + jHat*(200*(RTData>180)+40*(RTData<90)) + kHat*60"
if args.ranks > 1:
    piece = sm.Fetch(image).GetExtent()
    t.check(list(piece) != whole, "the image is split across the ranks (rank 0 has %s)" % (piece,))

extent, values = t.gather_image(image, os.path.join(args.output_dir, "input.pvti"), "rgb")
t.check(list(extent) == whole, "the gathered input is the whole image")
input_rows = t.as_rows(extent, values)
input_png = os.path.join(args.output_dir, "input.png")
t.write_png(input_png, input_rows)
flat = {MLAAAntialiasing: t.uniform_neighbourhoods(input_rows, 1),
        DLAAAntialiasing: t.uniform_neighbourhoods(input_rows, 10)}

cases = [
    ("defaults", MLAAAntialiasing, {}, []),
    ("custom", MLAAAntialiasing,
     dict(EdgeDetection="Luma", Threshold=0.05, MaxSearchSteps=4, DiagonalDetection=0,
          LocalContrastFactor=0, DominantDirectionBlending=0),
     ["--edges", "luma", "--threshold", "0.05", "--max-search-steps", "4", "--diagonals", "off",
      "--local-contrast", "0", "--dominant-blending", "off"]),
    ("corners", MLAAAntialiasing, dict(CornerExtrapolation=1), ["--corners", "on"]),
    ("ultra", MLAAAntialiasing, dict(QualityPreset="Ultra", Threshold=0.9), ["--preset", "ultra"]),
    ("max", MLAAAntialiasing, dict(QualityPreset="Max"), ["--preset", "max"]),
    ("dlaa-defaults", DLAAAntialiasing, {}, ["--method", "dlaa"]),
    ("dlaa-custom", DLAAAntialiasing,
     dict(Epsilon=0.05, Lambda=5, LumaFunction="Green", LongEdges=0),
     ["--method", "dlaa", "--dlaa-epsilon", "0.05", "--dlaa-lambda", "5", "--dlaa-luma", "green",
      "--long-edges", "off"]),
]
outputs = {}
for name, method, properties, tool_arguments in cases:
    mlaa = method(Input=image, Scalars=["POINTS", "rgb"], **properties)
    extent, values = t.gather_image(
        mlaa, os.path.join(args.output_dir, "mlaa-%s.pvti" % name), "rgb")
    rows = t.as_rows(extent, values)
    reference = t.run_tool(
        args.tool, tool_arguments, input_png,
        os.path.join(args.output_dir, "reference-%s.png" % name))
    t.check(list(extent) == whole and rows.dtype == np.uint8 and rows.shape[2] == 3,
            "%s: the output is a whole RGB byte image" % name)
    changed = np.any(rows != input_rows, axis=2)
    t.check(changed.sum() > 100, "%s: %d edge pixels are antialiased" % (name, changed.sum()))
    t.check(not np.any(changed & flat[method]), "%s: flat regions are unchanged (%d pixels)"
            % (name, flat[method].sum()))
    t.check(np.array_equal(rows, reference),
            "%s: the output equals vtkImage%sLAA's outside ParaView (max difference %d, %d "
            "pixels differ)" % (name, "D" if method == DLAAAntialiasing else "M",
                                t.max_difference(rows, reference),
                                np.any(rows != reference, axis=2).sum()))
    outputs[name] = rows
    Delete(mlaa)
    del mlaa
# CornerExtrapolation alone (off by default) changes the output: the property reaches the filter.
t.check(np.any(outputs["corners"] != outputs["defaults"]),
        "corners: CornerExtrapolation changes %d pixels of the defaults' output"
        % np.any(outputs["corners"] != outputs["defaults"], axis=2).sum())
