# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Selection and picking in the MLAA render view: the cells that a surface selection (single
pixels and a rubber band, over the interior and along the silhouettes) returns are the same with
UseMLAA on and off, and the view still antialiases after a selection."""

import os

import numpy as np

import mlaa_pvtest as t

args = t.parse_arguments()

from paraview.simple import *  # noqa: E402,F403
from vtkmodules.vtkCommonCore import vtkCollection  # noqa: E402

t.load_plugin(args.plugin, globals())
t.check(t.number_of_ranks() == args.ranks, "pvbatch runs on %d rank(s)" % args.ranks)

view = CreateView("MLAARenderView")
size = [300, 300]
view.ViewSize = size
view.OrientationAxesVisibility = 0
view.UseFXAA = 0
sphere = Sphere(ThetaResolution=32, PhiResolution=32, Radius=0.5)
display = Show(sphere, view)
display.ColorArrayName = ["POINTS", ""]
ResetCamera(view)
Render(view)


def selected_cells(region):
    """(process, cell id) pairs of the cells that a surface-cell selection of `region` (x0, y0,
    x1, y1 in pixels) returns, sorted."""
    representations = vtkCollection()
    sources = vtkCollection()
    view.SMProxy.SelectSurfaceCells(region, representations, sources, False)
    pairs = []
    for i in range(sources.GetNumberOfItems()):
        # An ID selection source: its IDs are (process, cell id) pairs.
        prop = sources.GetItemAsObject(i).GetProperty("IDs")
        ids = [prop.GetElement(j) for j in range(prop.GetNumberOfElements())]
        pairs += [tuple(ids[j:j + 2]) for j in range(0, len(ids), 2)]
    return sorted(pairs)


def screenshot(name):
    path = os.path.join(args.output_dir, name)
    SaveScreenshot(path, view, ImageResolution=size, TransparentBackground=0)
    return t.read_png(path)[:, :, :3]


# Pixels over the sphere's interior, on its silhouette (the sphere spans about the middle 60 %
# of the view) and just outside it, and a rubber band across the silhouette.
centre = size[0] // 2
regions = [[centre, centre, centre, centre]]
regions += [[x, centre, x, centre] for x in range(30, 80)]
regions += [[centre, y, centre, y] for y in range(220, 270)]
regions += [[60, 60, 140, 140]]

view.UseMLAA = 0
before = screenshot("mlaa-off.png")
plain = [selected_cells(r) for r in regions]
view.UseMLAA = 1
on = screenshot("mlaa-on.png")
with_mlaa = [selected_cells(r) for r in regions]
after = screenshot("mlaa-on-after-selection.png")

t.check(len(plain[0]) == 1, "a pixel over the sphere picks one cell (%s)" % (plain[0],))
t.check(sum(1 for cells in plain if cells) > 20 and sum(1 for cells in plain if not cells) > 5,
        "the pixels pick cells on the sphere and none beside it")
t.check(len(plain[-1]) > 10, "the rubber band selects %d cells" % len(plain[-1]))
mismatches = [(r, a, b) for r, a, b in zip(regions, plain, with_mlaa) if a != b]
t.check(not mismatches, "every selection returns the same cells with MLAA on and off %s"
        % (mismatches[:3],))
t.check(np.any(on != before), "the view antialiases")
t.check(np.array_equal(after, on), "the view antialiases as before after a selection")
