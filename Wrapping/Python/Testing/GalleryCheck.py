# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Checks for the tests of the Python gallery (Examples/Gallery/Python).

  GalleryCheck.py run [--status N] [--stderr TEXT] [--stdout TEXT] [--files F,F]
                      [--no-partial DIR] -- COMMAND...
      runs COMMAND; checks its exit status, that stderr/stdout contain TEXT, that the files
      exist, and that DIR holds no temporary ".*.partial.*" file
  GalleryCheck.py antialiased BEFORE AFTER MIN_CHANGED
      same size; at least MIN_CHANGED pixels differ; pixels equal to their four neighbours in
      BEFORE (no edge, nothing for MLAA to blend) are unchanged
  GalleryCheck.py filtered BEFORE AFTER METHOD [PRESET]
      AFTER is exactly what vtkImageMLAA/vtkImageDLAA (with PRESET) makes of BEFORE, and differs
      from BEFORE
  GalleryCheck.py npz FILE
      numpy_image.py --save FILE: before and after of the same shape and type, the edge
      antialiased, pixels without an edge unchanged
"""
import os
import re
import subprocess
import sys

import numpy

import vtkmlaa
from vtkmodules.vtkIOImage import vtkImageReader2Factory
from vtkmlaa_testing import image_to_numpy


def fail(message):
    print("FAILED: " + message, file=sys.stderr)
    sys.exit(1)


def read(path):
    reader = vtkImageReader2Factory.CreateImageReader2(path)
    if reader is None:
        fail(path + ": not readable")
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def edge_free(array):
    """Pixels equal to each of their four neighbours (the border pixels count as not)."""
    a = array.astype(int)
    flat = numpy.zeros(a.shape[:2], dtype=bool)
    same = lambda p, q: (p == q).all(axis=2)
    flat[1:-1, 1:-1] = (same(a[1:-1, 1:-1], a[:-2, 1:-1]) & same(a[1:-1, 1:-1], a[2:, 1:-1]) &
                        same(a[1:-1, 1:-1], a[1:-1, :-2]) & same(a[1:-1, 1:-1], a[1:-1, 2:]))
    return flat


def check_antialiased(before, after, min_changed, what):
    if before.shape != after.shape:
        fail("%s: sizes differ: %s and %s" % (what, before.shape, after.shape))
    changed = (before != after).any(axis=2)
    if changed.sum() < min_changed:
        fail("%s: %d pixels changed, expected at least %d" % (what, changed.sum(), min_changed))
    flat = edge_free(before)
    if changed[flat].any():
        fail("%s: %d pixels without an edge changed" % (what, changed[flat].sum()))
    print("%s: %d pixels changed, none of the %d without an edge"
          % (what, changed.sum(), flat.sum()))


def run(args):
    options, command = args[:args.index("--")], args[args.index("--") + 1:]
    expected = dict(zip(options[::2], options[1::2]))
    result = subprocess.run(command, capture_output=True, text=True)
    sys.stdout.write(result.stdout)
    sys.stderr.write(result.stderr)
    status = int(expected.get("--status", "0"))
    if result.returncode != status:
        fail("exit status %d, expected %d" % (result.returncode, status))
    for stream, text in (("--stderr", result.stderr), ("--stdout", result.stdout)):
        if stream in expected and expected[stream] not in text:
            fail("%s does not contain %r" % (stream[2:], expected[stream]))
    for path in filter(None, expected.get("--files", "").split(",")):
        if not os.path.isfile(path) or os.path.getsize(path) == 0:
            fail("not written: " + path)
    if "--no-partial" in expected:
        left = [n for n in os.listdir(expected["--no-partial"]) if re.match(r"\..*\.partial", n)]
        if left:
            fail("temporary files left: %s" % left)


def main(argv):
    command = argv[0]
    if command == "run":
        run(argv[1:])
    elif command == "antialiased":
        before, after = (image_to_numpy(read(p)) for p in argv[1:3])
        check_antialiased(before, after, int(argv[3]), argv[2])
    elif command == "filtered":
        before_image = read(argv[1])
        after = image_to_numpy(read(argv[2]))
        aa = vtkmlaa.vtkImageMLAA() if argv[3] == "mlaa" else vtkmlaa.vtkImageDLAA()
        if len(argv) > 4:
            aa.GetOptions().SetPreset(vtkmlaa.vtkMLAAOptions.GetPresetFromString(argv[4]))
        aa.SetInputData(before_image)
        aa.Update()
        expected = image_to_numpy(aa.GetOutput())
        before = image_to_numpy(before_image)
        if expected.shape != after.shape or not numpy.array_equal(expected, after):
            fail("%s is not %s of %s" % (argv[2], aa.GetClassName(), argv[1]))
        if numpy.array_equal(before, after):
            fail("%s equals its input" % argv[2])
        print("%s is exactly %s of %s" % (argv[2], aa.GetClassName(), argv[1]))
    elif command == "npz":
        data = numpy.load(argv[1])
        before, after = data["before"], data["after"]
        if before.dtype != after.dtype:
            fail("types differ: %s and %s" % (before.dtype, after.dtype))
        check_antialiased(before, after, 20, argv[1])
    else:
        fail("unknown check " + command)


if __name__ == "__main__":
    main(sys.argv[1:])
