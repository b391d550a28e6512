# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""The filters' UseValueRange and ValueRange properties, on a distributed image: 12-bit values
stored in 16-bit integers (0 to 4095). With the type's default range (0 to 65535) their edges
are 16 times fainter than they are: MLAA finds none above its threshold (the output is the
input), DLAA blends them less. With ValueRange 0 4095 the output differs from that and equals,
value for value, the `mlaa` tool's with --value-range 0 4095 on the same whole image (MLAA and
DLAA); with the type's range it equals the tool's without the option, and turning
UseValueRange off again gives that back."""

import os

import numpy as np

import mlaa_pvtest as t

args = t.parse_arguments()

from paraview.simple import *  # noqa: E402,F403

t.load_plugin(args.plugin, globals())
t.check(t.number_of_ranks() == args.ranks, "pvbatch runs on %d rank(s)" % args.ranks)

whole = [-80, 79, -60, 59, 0, 0]
image = Calculator(Input=Wavelet(WholeExtent=whole), ResultArrayName="grey",
                   ResultArrayType="Unsigned Short")
image.Function = "4095*(RTData>130) - 2000*(RTData>200) + 900*(RTData<90)"
extent, values = t.gather_image(image, os.path.join(args.output_dir, "input.pvti"), "grey")
input_rows = t.as_rows(extent, values)
t.check(input_rows.dtype == np.uint16 and int(input_rows.max()) == 4095,
        "the input is 12-bit data in 16-bit integers (max %d)" % input_rows.max())
input_png = os.path.join(args.output_dir, "input.png")
t.write_png(input_png, input_rows)

for name, filter_type, tool_arguments in (
        ("mlaa", MLAAAntialiasing, []),
        ("dlaa", DLAAAntialiasing, ["--method", "dlaa"])):
    smooth = filter_type(Input=image, Scalars=["POINTS", "grey"])
    t.check(smooth.UseValueRange == 0 and list(smooth.ValueRange) == [0.0, 1.0],
            "%s: UseValueRange is off by default, ValueRange 0 1" % name)
    _, values = t.gather_image(smooth, os.path.join(args.output_dir, name + "-type.pvti"), "grey")
    type_rows = t.as_rows(extent, values)
    reference = t.run_tool(args.tool, tool_arguments, input_png,
                           os.path.join(args.output_dir, "reference-%s-type.png" % name))
    t.check(np.array_equal(type_rows, reference),
            "%s: with the type's range the output equals the mlaa tool's without --value-range"
            % name)
    if filter_type == MLAAAntialiasing:
        t.check(np.array_equal(type_rows, input_rows),
                "%s: with the type's range (0 to 65535) no edge is found: the output is the input"
                % name)

    smooth.UseValueRange = 1
    smooth.ValueRange = [0, 4095]
    _, values = t.gather_image(smooth, os.path.join(args.output_dir, name + "-12bit.pvti"),
                               "grey")
    rows = t.as_rows(extent, values)
    reference = t.run_tool(args.tool, tool_arguments + ["--value-range", "0", "4095"], input_png,
                           os.path.join(args.output_dir, "reference-%s.png" % name))
    changed = np.any(rows != input_rows, axis=2).sum()
    t.check(changed > 100, "%s: with ValueRange 0 4095, %d edge pixels are antialiased"
            % (name, changed))
    t.check(np.any(rows != type_rows), "%s: ValueRange changes %d pixels of the output"
            % (name, np.any(rows != type_rows, axis=2).sum()))
    t.check(rows.dtype == np.uint16 and np.array_equal(rows, reference),
            "%s: the output equals the mlaa tool's with --value-range 0 4095 (max difference %d)"
            % (name, t.max_difference(rows, reference)))

    smooth.UseValueRange = 0
    _, values = t.gather_image(smooth, os.path.join(args.output_dir, name + "-again.pvti"),
                               "grey")
    t.check(np.array_equal(t.as_rows(extent, values), type_rows),
            "%s: UseValueRange off gives the type's range back" % name)
    Delete(smooth)
    del smooth
