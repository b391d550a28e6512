# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""vtkImageMLAA and vtkImageDLAA from Python on numpy data: exact values on the chapter's L and U
shapes (worked out independently below from the area formula of section 4.3), straight edges
and a rectangle's corner left alone, the same through vtkmlaa.antialias_array, and DLAA's shape, type and flat regions."""
import numpy

import vtkmlaa
from vtkmlaa import vtkImageDLAA, vtkImageMLAA
from vtkmlaa_testing import Checker, disk, image_to_numpy, numpy_to_image, quantize

check = Checker()


def l_area(p, length):
    """Area of an L shape for the p-th pixel from its crossing edge on a line of `length`."""
    if 2 * p + 2 <= length:
        return 0.5 * (1.0 - (2.0 * p + 1.0) / length)
    return 1.0 / (8.0 * length) if 2 * p + 1 == length else 0.0


def grey(width, height, white, dtype=numpy.uint8, top=255):
    """array[y, x] = top where white(x, y), else 0."""
    y, x = numpy.mgrid[0:height, 0:width]
    return numpy.where(white(x, y), top, 0).astype(dtype)


def run_mlaa(array, dominant=True):
    mlaa = vtkImageMLAA()
    mlaa.GetOptions().SetPresetToMedium()  # the settings the expected values assume
    mlaa.GetOptions().SetDominantDirectionBlending(dominant)
    mlaa.SetInputData(numpy_to_image(array))
    mlaa.Update()
    out = mlaa.GetOutput()
    check(out.GetScalarType() == mlaa.GetInput().GetScalarType(), "output scalar type")
    return image_to_numpy(out)[:, :, 0] if array.ndim == 2 else image_to_numpy(out)


def changed_only(before, after, allowed, what):
    mask = numpy.ones(before.shape[:2], dtype=bool)
    for x, y in allowed:
        mask[y, x] = False
    check(numpy.array_equal(before[mask], after[mask]), what + ": every other pixel unchanged")


# L shape: a line with a one-pixel step at one end and the border at the other. White rows 5 to 7
# and row 4 from x = 6 in a 16 x 8 black image: the lower outline steps down at x = 6. The line
# under row 4 (x >= 6) and the line over row 4 (x <= 5) both end at the step's crossing edge.
l_in = grey(16, 8, lambda x, y: (y >= 5) | ((x >= 6) & (y >= 4)))
for name, array in (("grey", l_in), ("RGB", numpy.repeat(l_in[:, :, None], 3, axis=2))):
    out = run_mlaa(array)
    pixel = (lambda x, y: out[y, x]) if out.ndim == 2 else (lambda x, y: out[y, x, 0])
    if out.ndim == 3:
        check((out == out[:, :, :1]).all(), name + " L: the channels stay equal")
    expected = {}
    for p in range(0, 10):  # white pixels over the lower line, up to the right border
        expected[(6 + p, 4)] = 255 - quantize(l_area(p, p + 17))
    for p in range(0, 6):  # black pixels under the upper line, up to the left border
        expected[(5 - p, 4)] = quantize(l_area(p, p + 17))
    check(expected[(6, 4)] == 135, "the corner's expected value is 135")
    for (x, y), value in sorted(expected.items()):
        check(pixel(x, y) == value,
              "%s L: pixel (%d, %d) is %d, expected %d" % (name, x, y, pixel(x, y), value))
    changed_only(array, out, expected.keys(), name + " L")

# A rectangle's corner (x >= 6, y >= 4): its sides lie on pixel boundaries and end at a corner
# and at the borders, with no step seen: left alone (issue 50).
corner = grey(16, 8, lambda x, y: (x >= 6) & (y >= 4))
check(numpy.array_equal(run_mlaa(corner), corner), "a rectangle's corner is left alone")

# The same L in float32 [0, 1]: the weights are 8-bit, so 1 - 120/255 at the corner.
l_float = run_mlaa(l_in.astype(numpy.float32) / 255.0)
check(abs(float(l_float[4, 6]) - (1.0 - quantize(8.0 / 17.0) / 255.0)) < 1e-6,
      "float L corner %r" % float(l_float[4, 6]))

# U shape: a white bar x = 4..7 on row 2 of a 12 x 6 black image. End pixels lose 3/8 to the
# black above and below (96/255; the vertical line dominates the side's 1/4): 159; inner pixels
# lose 1/8: 223. The chapter's blending averages the three blends at the ends:
# 255 (2 * 96 * 159 + 64 * 191) / 255^2 / (256 / 255) = 167.
u_in = grey(12, 6, lambda x, y: (y == 2) & (x >= 4) & (x <= 7))
u_out = run_mlaa(u_in)
check([int(v) for v in u_out[2, 4:8]] == [159, 223, 223, 159], "U: %s" % u_out[2, 4:8])
changed_only(u_in, u_out, [(4, 2), (5, 2), (6, 2), (7, 2)], "U")
u_chapter = run_mlaa(u_in, dominant=False)
check([int(v) for v in u_chapter[2, 4:8]] == [167, 223, 223, 167],
      "U, chapter's blending: %s" % u_chapter[2, 4:8])

# Straight edges are never blurred.
for white in (lambda x, y: x >= 5, lambda x, y: y >= 3):
    s_in = grey(11, 7, white)
    check(numpy.array_equal(run_mlaa(s_in), s_in), "a straight edge is left alone")

# antialias_array gives the same pixels, in the same layout and type.
aa = vtkmlaa.antialias_array(l_in, preset="medium")
check(aa.shape == l_in.shape and aa.dtype == l_in.dtype, "antialias_array: shape and type")
check(numpy.array_equal(aa, run_mlaa(l_in)), "antialias_array equals vtkImageMLAA")
check(numpy.array_equal(vtkmlaa.antialias_array(u_in, preset="medium",
                                                dominant_direction_blending=False), u_chapter),
      "antialias_array with an option")
# 16-bit data with 12 significant bits needs its value range, as the C++ API says.
l12 = numpy.where(l_in > 0, 4095, 0).astype(numpy.uint16)
check(numpy.array_equal(vtkmlaa.antialias_array(l12, preset="medium"), l12),
      "12-bit data in 16 bits: its edges are too faint without a value range")
aa12 = vtkmlaa.antialias_array(l12, preset="medium", value_range=(0, 4095))
check(aa12.dtype == numpy.uint16 and aa12[4, 6] == round(4095 * (1 - 120 / 255.0)),
      "12-bit data with value_range=(0, 4095): corner %d" % aa12[4, 6])

# DLAA on a disk: same shape and type, flat regions exactly as they were, the edge changed.
rgb = disk(64, 20.0, 3)
dlaa = vtkImageDLAA()
dlaa.SetInputData(numpy_to_image(rgb))
dlaa.Update()
d_out = image_to_numpy(dlaa.GetOutput())
check(d_out.shape == rgb.shape and d_out.dtype == rgb.dtype, "DLAA: shape and type")
y, x = numpy.mgrid[0:64, 0:64]
distance = numpy.abs(numpy.hypot(x + 0.5 - 32, y + 0.5 - 32) - 20.0)
far = distance > 12  # beyond the long-edge window (8) and the short-edge crosses (2)
check(numpy.array_equal(d_out[far], rgb[far]), "DLAA: flat regions unchanged")
check((d_out != rgb).any(axis=2).sum() > 50, "DLAA changes the disk's edge")
check(numpy.array_equal(vtkmlaa.antialias_array(rgb, method="dlaa"), d_out),
      "antialias_array(method='dlaa') equals vtkImageDLAA")

# MLAA on the same disk: only pixels next to an edge change.
m_out = vtkmlaa.antialias_array(rgb)
near = numpy.zeros(rgb.shape[:2], dtype=bool)
g = rgb[:, :, 0].astype(int)
near[:, 1:] |= g[:, 1:] != g[:, :-1]
near[:, :-1] |= g[:, 1:] != g[:, :-1]
near[1:, :] |= g[1:, :] != g[:-1, :]
near[:-1, :] |= g[1:, :] != g[:-1, :]
check(numpy.array_equal(m_out[~near], rgb[~near]), "MLAA: pixels without an edge unchanged")
check((m_out != rgb).any(axis=2).sum() > 50, "MLAA changes the disk's edge")

check.finish()
