# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkmlaa in a long-lived Python process (labels python and soak), as a viewer, a notebook or a
pytest suite uses it (issue 49):
- enable() called again and again on the same renderer (method, temporal, multisamples changed,
  as a settings dialog does) while the application keeps every pass enable() returned, and
  renderer.SetPass(None) in between (passes dropped there): nothing printed (ctest fails on
  "should have been released"), and each pass that enable() replaced holds no target
  (GetTargetMemorySize() 0);
- a seeded session of 600 renders that also toggles disable() and the window size at random, whose
  second half makes the first half's changes again: resident memory grows by at most 2 MB over
  the second half (it grew by 308 MB when a replaced pass kept its targets).
Needs a display (ctest runs under scripts/with-xvfb.sh)."""
import random

import vtkmlaa
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer
from vtkmlaa_testing import Checker

check = Checker()


def resident_kilobytes():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return -1


renderer = vtkRenderer()
sphere = vtkSphereSource()
sphere.SetThetaResolution(24)
sphere.SetPhiResolution(16)
mapper = vtkPolyDataMapper()
mapper.SetInputConnection(sphere.GetOutputPort())
actor = vtkActor()
actor.SetMapper(mapper)
renderer.AddActor(actor)
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(320, 240)
window.AddRenderer(renderer)
renderer.ResetCamera()

# Every pass enable() returned, kept by the application: a replaced pass must release its targets
# all the same.
kept = []
for i in range(40):
    if i % 4 == 3:
        renderer.SetPass(None)
    else:
        aa_pass = vtkmlaa.enable(renderer, method=vtkmlaa.METHODS[i % 2], temporal=(i % 3 == 1),
                                 multisamples=4 if i % 3 == 2 else 0)
        if i % 4 != 2:
            kept.append(aa_pass)  # replaced by enable() next
        del aa_pass
    window.Render()
held = [p for p in kept if p.GetTargetMemorySize() > 0]
check(not held, "passes replaced by enable() hold no target: %d of %d do" % (len(held), len(kept)))
del kept

generator = random.Random()
sizes = ((320, 240), (160, 120), (333, 211), (97, 61))
resident = []
aside = []
for half in range(2):
    generator.seed(49)
    vtkmlaa.enable(renderer)
    window.SetSize(320, 240)
    for i in range(300):
        change = generator.randrange(6)
        if change == 0:
            method = generator.choice(vtkmlaa.METHODS)
            preset = generator.choice(vtkmlaa.PRESETS) if method == "mlaa" else None
            temporal = generator.random() < 0.3
            aside = [vtkmlaa.enable(renderer, method=method, preset=preset, temporal=temporal,
                                    multisamples=0 if temporal else generator.choice((0, 4)))]
        elif change == 1:
            vtkmlaa.disable(renderer)
        elif change == 2:
            window.SetSize(*generator.choice(sizes))
        elif change == 3:
            renderer.GetActiveCamera().Azimuth(generator.choice((-0.5, 0.5)))
        window.Render()
    vtkmlaa.enable(renderer)
    window.SetSize(320, 240)
    window.Render()
    resident.append(resident_kilobytes())
grown = resident[1] - resident[0]
print("session of 600 renders: resident memory %d -> %d kB (half, end)" % tuple(resident))
check(grown <= 2048, "resident memory grew by %d kB over the second half" % grown)
check.finish()
