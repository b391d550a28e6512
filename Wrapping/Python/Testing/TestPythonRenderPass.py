# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""The render pass from Python: a small scene rendered offscreen without antialiasing and with
vtkmlaa.enable(renderer), saved to PNG; the pass changes edge pixels, leaves pixels without an
edge alone, and gives the image vtkImageMLAA gives on the screenshot without antialiasing (within
2/255 on at least 99.5 % of the pixels, as the C++ test TestMLAAPassMatchesFilter requires), also
with translucent geometry, depth peeling off and on (issue 21); with temporal=True, render_still
gives a converged still closer to a supersampled reference than the single-frame pass (issue 23);
with multisamples=4 (MLAA's SampleAreas and DLAA's ShortEdgesFromSamples off), the pass equals
the filter run on each plain sample image (pass.SetDebugSample), averaged, and half and half with
the plain samples' average where they differ (issue 22), every sample is shaded unless
sample_shading=False, and bad multisamples values raise ValueError.
Needs a display (ctest runs under scripts/with-xvfb.sh). Usage: TestPythonRenderPass.py OUT_DIR"""
import os
import sys

import numpy

import vtkmlaa
from vtkmodules.vtkFiltersSources import vtkConeSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkWindowToImageFilter)
from vtkmlaa_testing import Checker, image_to_numpy, numpy_to_image, write_png

check = Checker()
out_dir = sys.argv[1] if len(sys.argv) > 1 else "."
os.makedirs(out_dir, exist_ok=True)


def scene():
    renderer = vtkRenderer()
    renderer.SetBackground(0.1, 0.2, 0.4)
    for source, position, colour in ((vtkSphereSource(), (-0.6, 0, 0), (1.0, 0.8, 0.3)),
                                     (vtkConeSource(), (0.7, 0, 0), (0.9, 0.3, 0.3))):
        if isinstance(source, vtkSphereSource):
            source.SetThetaResolution(24)
            source.SetPhiResolution(16)
        else:
            source.SetResolution(7)
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.SetPosition(*position)
        actor.GetProperty().SetColor(*colour)
        actor.RotateZ(17)
        renderer.AddActor(actor)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(300, 200)
    window.AddRenderer(renderer)
    renderer.ResetCamera()
    return window, renderer


def screenshot(window):
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    return image_to_numpy(grab.GetOutput())


def within(a, b, tolerance=2):
    return (numpy.abs(a.astype(int) - b.astype(int)) <= tolerance).all(axis=2).mean()


window, renderer = scene()
window.SetMultiSamples(0)
plain = screenshot(window)
check(plain.shape == (200, 300, 3), "screenshot shape %s" % (plain.shape,))

for method, filter_class in (("mlaa", vtkmlaa.vtkImageMLAA), ("dlaa", vtkmlaa.vtkImageDLAA)):
    window, renderer = scene()
    window.SetMultiSamples(8)
    aa_pass = vtkmlaa.enable(renderer, method=method)
    check(window.GetMultiSamples() == 0, method + ": enable turns multisampling off")
    shot = screenshot(window)
    path = os.path.join(out_dir, "TestPythonRenderPass-%s.png" % method)
    write_png(path, shot[::-1])  # PNG rows from the top, as the window shows them
    check(os.path.getsize(path) > 1000, method + ": wrote " + path)

    changed = (shot != plain).any(axis=2)
    check(changed.sum() > 200, "%s changes %d edge pixels" % (method, changed.sum()))
    if method == "mlaa":
        # A pixel equal to its four neighbours has no edge: MLAA leaves it alone.
        g = plain.astype(int)
        flat = numpy.zeros(changed.shape, dtype=bool)
        flat[1:-1, 1:-1] = ((g[1:-1, 1:-1] == g[:-2, 1:-1]).all(axis=2) &
                            (g[1:-1, 1:-1] == g[2:, 1:-1]).all(axis=2) &
                            (g[1:-1, 1:-1] == g[1:-1, :-2]).all(axis=2) &
                            (g[1:-1, 1:-1] == g[1:-1, 2:]).all(axis=2))
        check(flat.sum() > 0.5 * flat.size, "the scene has flat regions")
        check(not changed[flat].any(), "mlaa: %d flat pixels changed" % changed[flat].sum())

    aa = filter_class()
    aa.SetInputData(numpy_to_image(plain))
    aa.Update()
    expected = image_to_numpy(aa.GetOutput())
    share = within(shot, expected)
    print("%s: pass vs %s on the screenshot: %.4f %% of pixels within 2/255"
          % (method, filter_class.__name__, 100 * share))
    check(share >= 0.995, "%s: pass and filter agree on %.4f of the pixels" % (method, share))

    check(vtkmlaa.disable(renderer), method + ": disable")
    check((screenshot(window) == plain).all(), method + ": after disable, the plain image again")
    window.Finalize()


def translucent_scene():
    """Three overlapping spheres, one opaque and two translucent, on white (issue 21)."""
    window, renderer = scene()
    renderer.RemoveAllViewProps()
    renderer.SetBackground(1, 1, 1)
    for centre, opacity, colour in (((-0.5, 0, -0.6), 1.0, (0.9, 0.3, 0.2)),
                                    ((0, 0, 0), 0.4, (0.2, 0.5, 0.9)),
                                    ((0.5, 0.1, 0.5), 0.5, (0.3, 0.8, 0.3))):
        source = vtkSphereSource()
        source.SetCenter(*centre)
        source.SetThetaResolution(32)
        source.SetPhiResolution(24)
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(*colour)
        actor.GetProperty().SetOpacity(opacity)
        renderer.AddActor(actor)
    window.SetMultiSamples(0)
    renderer.ResetCamera()
    renderer.GetActiveCamera().Azimuth(30)
    return window, renderer


# Translucent geometry: enable() draws it as the renderer does on its own (order-independent
# translucency, or depth peeling with UseDepthPeeling), so the pass still gives the filter's
# result on the renderer's own screenshot.
for method in ("mlaa", "dlaa"):
    for peeling in (False, True):
        window, renderer = translucent_scene()
        renderer.SetUseDepthPeeling(peeling)
        plain = screenshot(window)
        vtkmlaa.enable(renderer, method=method)
        shot = screenshot(window)
        expected = vtkmlaa.antialias_array(plain, method=method)
        share = within(shot, expected)
        what = "%s, translucent spheres, depth peeling %s" % (method, "on" if peeling else "off")
        print("%s: %.4f %% of pixels within 2/255 of the filter" % (what, 100 * share))
        check(share >= 0.995, "%s: pass and filter agree on %.4f of the pixels" % (what, share))
        check((shot != plain).any(axis=2).sum() > 100, what + ": antialiased")
        vtkmlaa.disable(renderer)
        window.Finalize()

# Temporal antialiasing (issue 23): enable(..., temporal=True) and render_still give a converged
# still, closer to an 8 x 8 supersampled reference than the single-frame pass.
def reference(window, renderer, samples=8):
    camera = renderer.GetActiveCamera()
    centre = camera.GetWindowCenter()
    width, height = window.GetSize()
    total = None
    for j in range(samples):
        for i in range(samples):
            camera.SetWindowCenter(centre[0] + 2.0 * ((i + 0.5) / samples - 0.5) / width,
                                   centre[1] + 2.0 * ((j + 0.5) / samples - 0.5) / height)
            shot = screenshot(window).astype(float)
            total = shot if total is None else total + shot
    camera.SetWindowCenter(*centre)
    return total / (samples * samples)


def aar(none, result, ref):
    aliased = (numpy.abs(none - ref) > 4).any(axis=2)
    return 1.0 - ((result - ref)[aliased] ** 2).sum() / ((none - ref)[aliased] ** 2).sum()


for method in ("mlaa", "dlaa"):
    window, renderer = scene()
    window.SetMultiSamples(0)
    plain = screenshot(window).astype(float)
    ref = reference(window, renderer)
    single_pass = vtkmlaa.enable(renderer, method=method)
    check(not single_pass.GetTemporal(), method + ": temporal is off by default")
    single = screenshot(window).astype(float)
    vtkmlaa.disable(renderer)
    aa_pass = vtkmlaa.enable(renderer, method=method, temporal=True)
    check(aa_pass.GetTemporal(), method + ": enable(temporal=True)")
    renders = vtkmlaa.render_still(renderer)
    converged = screenshot(window).astype(float)
    print("%s: render_still: %d renders, %d accumulated; AAR single-frame %.3f, temporal %.3f"
          % (method, renders, aa_pass.GetAccumulatedFrames(), aar(plain, single, ref),
             aar(plain, converged, ref)))
    check(renders == 16 and aa_pass.GetAccumulatedFrames() == 16,
          method + ": render_still accumulates 16 frames (screenshot()'s renders hold the still)")
    check(numpy.array_equal(screenshot(window).astype(float), converged),
          method + ": a converged still holds: another screenshot is the same image")
    check(aar(plain, converged, ref) > max(0.9, aar(plain, single, ref)),
          method + ": the converged still is closer to the reference")
    check(vtkmlaa.render_still(renderer, frames=4) == 1, method + ": already converged: 1 render")
    vtkmlaa.disable(renderer)
    check(vtkmlaa.render_still(renderer) == 1, method + ": without a pass: 1 render")


# Multisampled: the method on each sample set, averaged.
for method in ("mlaa", "dlaa"):
    window, renderer = scene()
    vtkmlaa.enable(renderer, method=method)
    single = screenshot(window)
    vtkmlaa.disable(renderer)
    aa_pass = vtkmlaa.enable(renderer, method=method, multisamples=4)
    # The filter has one sample per pixel: compared without MLAA's per-sample areas and with
    # DLAA's short-edge blur on every sample image.
    if method == "mlaa":
        aa_pass.SampleAreasOff()
    else:
        aa_pass.ShortEdgesFromSamplesOff()
    shot = screenshot(window)
    samples = aa_pass.GetRenderedMultiSamples()
    check(aa_pass.GetMultiSamples() == 4 and samples >= 2,
          "%s: multisamples=4 sets the pass (%d samples used)" % (method, samples))
    check(window.GetMultiSamples() == 0, method + ": the window's own multisampling is off")
    sample_images = []
    for s in range(samples):
        aa_pass.SetDebugSample(s)
        sample_images.append(screenshot(window))
    aa_pass.SetDebugSample(-1)
    # The filter on each sample, averaged; where a pixel's samples differ, half and half with
    # the plain samples' average (the pass's resolve).
    filtered = numpy.mean([vtkmlaa.antialias_array(image, method=method).astype(float)
                           for image in sample_images], axis=0)
    plain_average = numpy.mean([image.astype(float) for image in sample_images], axis=0)
    differ = numpy.zeros(plain_average.shape[:2], dtype=bool)
    for image in sample_images[1:]:
        differ |= (image != sample_images[0]).any(axis=2)
    expected = numpy.where(differ[:, :, None], 0.5 * (filtered + plain_average), filtered)
    share = within(shot, numpy.round(expected))
    print("%s, multisamples=4: %.4f %% of pixels within 2/255 of the filter per sample, resolved"
          % (method, 100 * share))
    check(share >= 0.995, "%s: multisampled pass and filter agree on %.4f" % (method, share))
    check((shot != single).any(axis=2).sum() > 100, method + ": differs from the single-sample pass")
    check(aa_pass.GetSampleShading() and aa_pass.GetRenderedSampleShading(),
          method + ": every sample shaded by default")
    vtkmlaa.disable(renderer)
    # sample_shading=False: multisampling's own shading, once per pixel (the option of the pass).
    aa_pass = vtkmlaa.enable(renderer, method=method, multisamples=4, sample_shading=False)
    screenshot(window)
    check(not aa_pass.GetSampleShading() and not aa_pass.GetRenderedSampleShading(),
          method + ": sample_shading=False shades once per pixel")
    vtkmlaa.disable(renderer)
    for bad in (-1, 17, 2.5, True, "4"):
        try:
            vtkmlaa.enable(renderer, method=method, multisamples=bad)
            check(False, "%s: multisamples=%r accepted" % (method, bad))
        except ValueError:
            pass
    check(renderer.GetPass() is None, method + ": a refused enable() leaves no pass")
    window.Finalize()

check.finish()
