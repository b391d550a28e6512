# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkmlaa in a long-lived Python process (labels python and soak), as a viewer, a notebook or a
pytest suite uses it (issue 49):
- enable() called again and again on the same renderer (method, temporal, multisamples changed,
  as a settings dialog does) while the application keeps every pass enable() returned, and
  renderer.SetPass(None) in between (passes dropped there): nothing printed (ctest fails on
  "should have been released"), and each pass that enable() replaced holds no target
  (GetTargetMemorySize() 0);
- a seeded session of 600 renders in four rounds that make the same changes (enable() with
  methods, presets, temporal and 4 samples, disable(), the window size) at random: resident
  memory grows by at most 1 MB in the smaller of the last two rounds' growths (a leak grows in
  each; the session grew by 308 MB when a replaced pass kept its targets).
Needs a display (ctest runs under scripts/with-xvfb.sh)."""
import ctypes
import random

import vtkmlaa
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow, vtkRenderer
from vtkmlaa_testing import Checker

check = Checker()


def resident_kilobytes():
    """The process's resident memory after glibc gives back what it holds free (malloc_trim), as
    TestAntialiasingPassLifetime reads it."""
    try:
        ctypes.CDLL(None).malloc_trim(0)
    except (OSError, AttributeError):
        pass
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
resident = [resident_kilobytes()]
aside = []
for round_ in range(4):
    # Each round makes the same changes, so that it builds no shader variant the first did not.
    generator.seed(49)
    vtkmlaa.enable(renderer)
    window.SetSize(320, 240)
    for i in range(150):
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
print("session of 600 renders: resident memory (kB) at the start and after each round of 150: %s;"
      " over the second half %d kB" % (" ".join(map(str, resident)), resident[4] - resident[2]))
# A leak grows in every round; a pool that grows to its size once does not grow again (steps of
# about 3 MB in one round are seen in some runs on VTK 9.6): the smaller growth of the last two
# rounds must be within 1 MB.
smaller = min(resident[3] - resident[2], resident[4] - resident[3])
check(smaller <= 1024, "resident memory grew by %d kB in the smaller of the last two rounds"
      % smaller)
check.finish()
