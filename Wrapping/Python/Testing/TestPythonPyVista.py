# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkmlaa with PyVista, the way its users write it: vtkmlaa.enable(plotter) on an offscreen
pyvista.Plotter, then plotter.screenshot(). Checked:

- the next screenshot is antialiased, with no explicit plotter.render(): edge pixels change,
  flat regions do not, and the image equals vtkImageMLAA's on the plain screenshot (within 2/255
  on at least 99.5 % of the pixels, as TestMLAAPassMatchesFilter requires);
- every method and mode: MLAA, DLAA, 4 samples, temporal with render_still(plotter) (closer to
  a supersampled screenshot than the single-frame pass), and every_renderer for subplots;
- enable() again replaces the pass and disable(plotter) removes it, each releasing the old
  pass's graphics resources (no "should have been released" warning: CTest fails the test on
  that text), and the screenshot is then the plain one again, exactly;
- PyVista's own effects (eye-dome lighting, SSAO, shadows, SSAA) compose: the effect's pass
  becomes the antialiasing pass's delegate, the screenshot differs from the effect's alone,
  disable() gives the effect back exactly, and temporal or multisampled modes refuse it with a
  ValueError that names the pass.

Skipped (exit 77) where PyVista is not installed (Debian 12; the Debian testing root has it).
Usage: TestPythonPyVista.py OUT_DIR"""
import os
import sys

import numpy

try:
    import pyvista
except ImportError as error:
    print("skipped: PyVista is not installed for this Python (%s)" % error)
    sys.exit(77)

import vtkmlaa
from vtkmlaa_testing import Checker, write_png

check = Checker()
out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out_dir, exist_ok=True)
pyvista.OFF_SCREEN = True
SIZE = (320, 240)


def plotter(shape=(1, 1)):
    p = pyvista.Plotter(off_screen=True, window_size=SIZE, shape=shape)
    p.render_window.SetMultiSamples(0)  # PyVista's default is MSAA: compare without it
    for index in range(shape[0] * shape[1]):
        p.subplot(index // shape[1], index % shape[1])
        p.set_background([0.1, 0.2, 0.4])
        p.add_mesh(pyvista.Sphere(theta_resolution=24, phi_resolution=16, center=(-0.6, 0, 0)),
                   color=[1.0, 0.8, 0.3], smooth_shading=True)
        p.add_mesh(pyvista.Cone(resolution=7, center=(0.7, 0, 0)), color=[0.9, 0.3, 0.3])
        p.camera_position = [(0, 0, 4.5), (0, 0, 0), (0, 1, 0)]
    return p


def shot(p, name):
    image = numpy.asarray(p.screenshot(return_img=True))[:, :, :3].astype(int)
    write_png(os.path.join(out_dir, name + ".png"), numpy.flipud(image).astype(numpy.uint8))
    return image


def changed(a, b):
    return int(numpy.count_nonzero(numpy.any(a != b, axis=2)))


def flat(image):
    """Pixels whose 3 x 3 neighbourhood has a single colour (no edge to antialias)."""
    padded = numpy.pad(image, ((1, 1), (1, 1), (0, 0)), mode="edge")
    same = numpy.ones(image.shape[:2], dtype=bool)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            shifted = padded[1 + dy:1 + dy + image.shape[0], 1 + dx:1 + dx + image.shape[1]]
            same &= numpy.all(shifted == image, axis=2)
    return same


def matches_filter(plain, result, method):
    # The screenshot's first row is the top; the filter's image row 0 is the bottom.
    reference = numpy.flipud(vtkmlaa.antialias_array(
        numpy.flipud(plain).astype(numpy.uint8), method=method)).astype(int)
    close = numpy.all(numpy.abs(reference - result) <= 2, axis=2)
    return float(close.mean())


# 1. MLAA on a plotter: the next screenshot is antialiased, without plotter.render().
p = plotter()
plain = shot(p, "pyvista-plain")
aa_pass = vtkmlaa.enable(p)
check(isinstance(aa_pass, vtkmlaa.vtkOpenGLMLAAPass) and p.renderer.GetPass() is aa_pass,
      "enable(plotter) installs an MLAA pass on the plotter's renderer")
mlaa = shot(p, "pyvista-mlaa")
check(changed(plain, mlaa) > 100, "the next screenshot is antialiased (%d pixels changed)"
      % changed(plain, mlaa))
check(not numpy.any(numpy.any(plain != mlaa, axis=2) & flat(plain)),
      "no pixel of a flat region changed")
share = matches_filter(plain, mlaa, "mlaa")
check(share >= 0.995, "the screenshot equals vtkImageMLAA's within 2/255 on %.2f %% of pixels"
      % (100 * share))

# 2. enable() again (another method) replaces the pass; disable() removes it.
dlaa_pass = vtkmlaa.enable(p, method="dlaa")
check(aa_pass.GetTargetMemorySize() == 0, "the replaced pass's targets were released")
dlaa = shot(p, "pyvista-dlaa")
check(changed(plain, dlaa) > 100 and changed(mlaa, dlaa) > 0, "DLAA replaces MLAA")
share = matches_filter(plain, dlaa, "dlaa")
check(share >= 0.995, "DLAA equals vtkImageDLAA within 2/255 on %.2f %% of pixels" % (100 * share))
check(vtkmlaa.disable(p) and p.renderer.GetPass() is None, "disable(plotter) removes the pass")
check(dlaa_pass.GetTargetMemorySize() == 0, "the removed pass's targets were released")
check(changed(plain, shot(p, "pyvista-disabled")) == 0, "without the pass, the plain screenshot")

# 3. 4 samples, and a converged still.
vtkmlaa.enable(p, multisamples=4)
samples = shot(p, "pyvista-4-samples")
check(changed(plain, samples) > 100 and changed(mlaa, samples) > 100,
      "multisamples=4 differs from the plain and from the single-sample screenshot")
temporal_pass = vtkmlaa.enable(p, temporal=True)
renders = vtkmlaa.render_still(p)
check(renders > 1, "render_still(plotter) rendered the still %d times" % renders)
still = shot(p, "pyvista-converged")
check(temporal_pass.GetTemporal() and changed(plain, still) > 100,
      "the converged still is antialiased")
vtkmlaa.disable(p)
reference_plotter = plotter()
reference_plotter.renderer.SetPass(None)
reference = numpy.asarray(reference_plotter.screenshot(return_img=True, scale=4))[:, :, :3]
reference = reference.reshape(SIZE[1], 4, SIZE[0], 4, 3).mean(axis=(1, 3))
reference_plotter.close()
errors = {name: float(numpy.abs(image - reference).mean())
          for name, image in (("plain", plain), ("mlaa", mlaa), ("converged", still))}
check(errors["converged"] < errors["mlaa"] < errors["plain"],
      "nearer a 4 x 4 supersampled screenshot: converged %.3f < MLAA %.3f < plain %.3f"
      % (errors["converged"], errors["mlaa"], errors["plain"]))
p.close()

# 4. Subplots: every_renderer puts a pass on each.
q = plotter(shape=(1, 2))
q_plain = shot(q, "pyvista-subplots-plain")
vtkmlaa.enable(q, every_renderer=True)
check(all(isinstance(r.GetPass(), vtkmlaa.vtkOpenGLMLAAPass) for r in q.renderers),
      "every_renderer=True: each subplot has a pass")
q_aa = shot(q, "pyvista-subplots-mlaa")
half = SIZE[0] // 2
check(changed(q_plain[:, :half], q_aa[:, :half]) > 50 and
      changed(q_plain[:, half:], q_aa[:, half:]) > 50, "both subplots are antialiased")
vtkmlaa.disable(q, every_renderer=True)
check(all(r.GetPass() is None for r in q.renderers), "disable(every_renderer=True)")
q.close()

# 5. PyVista's own effects compose with the pass (or refuse a mode that cannot wrap them).
effects = (
    ("eye-dome lighting", "vtkEDLShading", lambda p: p.enable_eye_dome_lighting()),
    ("SSAO", "vtkSSAOPass", lambda p: p.enable_ssao()),
    ("shadows", "vtkShadowMapPass", lambda p: p.enable_shadows()),
    ("SSAA", "vtkSSAAPass", lambda p: p.enable_anti_aliasing("ssaa")),
)
for label, class_name, turn_on in effects:
    p = plotter()
    turn_on(p)
    p.render_window.SetMultiSamples(0)
    effect = shot(p, "pyvista-%s" % class_name)
    effect_pass = p.renderer.GetPass()
    check(effect_pass is not None and class_name in vtkmlaa._pass_chain(effect_pass),
          "%s: PyVista installed %s" % (label, class_name))
    try:
        vtkmlaa.enable(p, temporal=True)
        check(False, "%s: temporal=True refused" % label)
    except ValueError as error:
        check(class_name in str(error), "%s: temporal=True refused, naming %s (%s)"
              % (label, class_name, error))
    check(p.renderer.GetPass() is effect_pass, "%s: the refusal changed nothing" % label)
    aa_pass = vtkmlaa.enable(p)
    check(aa_pass.GetDelegatePass() is effect_pass,
          "%s: the effect's pass is the antialiasing pass's delegate" % label)
    both = shot(p, "pyvista-%s-mlaa" % class_name)
    check(changed(effect, both) > 50, "%s: antialiased on top of the effect (%d pixels)"
          % (label, changed(effect, both)))
    check(vtkmlaa.disable(p) and p.renderer.GetPass() is effect_pass,
          "%s: disable() gives the effect its pass back" % label)
    check(changed(effect, shot(p, "pyvista-%s-again" % class_name)) == 0,
          "%s: the same screenshot as the effect alone again" % label)
    p.close()

check.finish()
