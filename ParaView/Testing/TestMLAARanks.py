# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""One rank against two: the MLAA view's MLAA and DLAA screenshots of TestMLAAView.py on one rank
and on two ranks agree within 2/255, except where the plain (UseMLAA off) screenshots already
differ (compositing itself, and the methods' reach around such pixels)."""

import os

import numpy as np

import mlaa_pvtest as t

args = t.parse_arguments(lambda p: p.add_argument("--compare", nargs=2, required=True,
                                                  help="the two runs' output directories"))
one, two = args.compare
off = [t.read_png(os.path.join(d, "mlaa-off.png"))[:, :, :3] for d in (one, two)]

compositing = np.any(off[0] != off[1], axis=2)
print("pixels where compositing differs: %d" % compositing.sum())
t.check(compositing.sum() < 0.01 * compositing.size,
        "the plain screenshots of one and two ranks nearly agree")
# MLAA moves colour along lines of up to 2 * MaxSearchSteps pixels (DLAA less far); where the
# plain images differ, what lies within that reach may differ too.
reach = 32
near = compositing.copy()
ys, xs = np.nonzero(compositing)
for y, x in zip(ys, xs):
    near[max(0, y - reach):y + reach + 1, max(0, x - reach):x + reach + 1] = True
t.check((~near).sum() > 0.5 * near.size, "most of the image is compared")
for method, name in (("MLAA", "mlaa-on.png"), ("DLAA", "dlaa-on.png")):
    on = [t.read_png(os.path.join(d, name))[:, :, :3] for d in (one, two)]
    difference = np.abs(on[0].astype(np.int32) - on[1].astype(np.int32)).max(axis=2)
    measured = ("max difference %d, %d pixels differ by more than 2/255, of %d away from "
                "compositing differences" % (difference[~near].max(),
                                             np.sum(difference[~near] > 2), (~near).sum()))
    t.check(not np.any(difference[~near] > 2),
            "%s: the screenshots of one and two ranks agree within 2/255 (%s)" % (method, measured))
