#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Gallery: antialias a numpy array (an image you computed, or one from another library).

    numpy_image.py [--save FILE.npz]

Makes an aliased picture in numpy (a tilted half-plane, hard-edged), antialiases it with one
call, vtkmlaa.antialias_array(), and prints a small crop of the edge before and after. The
result is a new array of the same shape and type. The same by hand, for a VTK pipeline:
numpy_support.numpy_to_vtk() into a vtkImageData, vtkImageMLAA, numpy_support.vtk_to_numpy().
--save writes both arrays (before, after) to FILE.npz.
"""
import argparse
import sys

import numpy

import vtkmlaa


def tilted_edge(height=24, width=32):
    """RGB uint8, array[y, x]: white where y < height / 2 + (x - width / 2) / 3, black
    elsewhere; the line of slope 1/3 between them is a staircase of 3-pixel steps."""
    y, x = numpy.mgrid[0:height, 0:width]
    inside = y < height / 2.0 + (x - width / 2.0) / 3.0
    grey = numpy.where(inside, 255, 0).astype(numpy.uint8)
    return numpy.repeat(grey[:, :, None], 3, axis=2)


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--save", help="write the arrays before and after to this .npz file")
    args = parser.parse_args(argv)

    before = tilted_edge()
    after = vtkmlaa.antialias_array(before, preset="high")  # <- the antialiasing

    rows, columns = slice(9, 15), slice(12, 22)
    numpy.set_printoptions(linewidth=120)
    print("before (red channel, rows %d-%d, columns %d-%d):" % (
        rows.start, rows.stop - 1, columns.start, columns.stop - 1))
    print(before[rows, columns, 0])
    print("after:")
    print(after[rows, columns, 0])
    changed = int((after != before).any(axis=2).sum())
    print("%d pixels changed, shape %s, dtype %s" % (changed, after.shape, after.dtype))
    if args.save:
        numpy.savez(args.save, before=before, after=after)
    return 0


if __name__ == "__main__":
    sys.exit(main())
