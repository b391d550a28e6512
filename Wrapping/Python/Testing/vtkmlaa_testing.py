# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Helpers shared by the Python tests of the vtkmlaa package: numpy <-> vtkImageData, PNG files,
synthetic images, and a recorder of VTK errors."""
import math
import sys

import numpy
from vtkmodules.util import numpy_support
from vtkmodules.vtkCommonCore import VTK_STRING
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter


def numpy_to_image(array):
    """A (rows, columns[, components]) array as a vtkImageData; array[y, x] is pixel (x, y)."""
    array = numpy.asarray(array)
    rows, columns = array.shape[:2]
    components = 1 if array.ndim == 2 else array.shape[2]
    image = vtkImageData()
    image.SetDimensions(columns, rows, 1)
    flat = numpy.ascontiguousarray(array).reshape(rows * columns, components)
    image.GetPointData().SetScalars(numpy_support.numpy_to_vtk(flat, deep=True))
    return image


def image_to_numpy(image):
    """The scalars of a 2D vtkImageData as a (rows, columns, components) array (a copy)."""
    scalars = image.GetPointData().GetScalars()
    if scalars is None:
        raise ValueError("the image has no scalars")
    columns, rows, _ = image.GetDimensions()
    return numpy_support.vtk_to_numpy(scalars).reshape(
        rows, columns, scalars.GetNumberOfComponents()).copy()


def write_png(path, array):
    writer = vtkPNGWriter()
    writer.SetFileName(str(path))
    writer.SetInputData(numpy_to_image(array))
    writer.Write()


def read_png(path):
    reader = vtkPNGReader()
    reader.SetFileName(str(path))
    reader.Update()
    return image_to_numpy(reader.GetOutput())


def quantize(area):
    """An area as the 8-bit weight the filter stores (round half away from zero, as lround)."""
    return int(math.floor(255.0 * area + 0.5))


def disk(size=64, radius=20.0, components=3):
    """A white disk on black with hard (aliased) edges, uint8."""
    y, x = numpy.mgrid[0:size, 0:size]
    inside = (x + 0.5 - size / 2.0) ** 2 + (y + 0.5 - size / 2.0) ** 2 <= radius ** 2
    grey = numpy.where(inside, 255, 0).astype(numpy.uint8)
    return numpy.repeat(grey[:, :, None], components, axis=2)


class ErrorRecorder:
    """Observes ErrorEvent on a VTK object and keeps the messages (instead of printing them)."""

    def __init__(self, obj):
        self.messages = []
        obj.AddObserver("ErrorEvent", self._on_error)

    def _on_error(self, caller, event, message=None):
        self.messages.append(str(message))

    _on_error.CallDataType = VTK_STRING


class Checker:
    """Counts failed checks; each failure is printed with its description."""

    def __init__(self):
        self.failures = 0

    def __call__(self, condition, description):
        if not condition:
            self.failures += 1
            print("FAILED: " + description, file=sys.stderr)
        return condition

    def finish(self):
        if self.failures:
            print("%d check(s) failed" % self.failures, file=sys.stderr)
            sys.exit(1)
        print("all checks passed")
