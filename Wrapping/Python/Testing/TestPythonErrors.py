# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Bad input from Python gives VTK errors or Python exceptions, never a crash: an image without
scalars or with 5 components makes vtkImageMLAA and vtkImageDLAA report an error and give an
empty output; vtkmlaa.antialias_array raises ValueError for arrays that are not images and
RuntimeError when the filter fails; enable() refuses what it does not know (see also
TestPythonOptionsAndDocs)."""
import numpy

import vtkmlaa
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmlaa_testing import Checker, ErrorRecorder, numpy_to_image

check = Checker()

no_scalars = vtkImageData()
no_scalars.SetDimensions(8, 8, 1)
five = numpy_to_image(numpy.zeros((6, 6, 5), dtype=numpy.uint8))
for filter_class in (vtkmlaa.vtkImageMLAA, vtkmlaa.vtkImageDLAA):
    for what, image in (("no scalars", no_scalars), ("5 components", five)):
        aa = filter_class()
        errors = ErrorRecorder(aa)
        aa.SetInputData(image)
        aa.Update()
        name = "%s on an image with %s" % (filter_class.__name__, what)
        check(len(errors.messages) >= 1, name + ": an error is reported")
        print(name + ": " + " | ".join(m.strip() for m in errors.messages))
        check(aa.GetOutput().GetPointData().GetScalars() is None or
              aa.GetOutput().GetNumberOfPoints() == 0, name + ": empty output")
    # The same filter still works on good input afterwards.
    aa.SetInputData(numpy_to_image(numpy.zeros((6, 6, 3), dtype=numpy.uint8)))
    aa.Update()
    check(aa.GetOutput().GetPointData().GetScalars() is not None, "good input after bad")

for array, error in ((numpy.zeros((4, 4, 5), numpy.uint8), ValueError),
                     (numpy.zeros((4,), numpy.uint8), ValueError),
                     (numpy.zeros((4, 4), bool), ValueError),
                     (numpy.array([["a", "b"]]), ValueError)):
    try:
        vtkmlaa.antialias_array(array)
        check(False, "antialias_array(%s %s) raises" % (array.dtype, array.shape))
    except error as e:
        print("antialias_array(%s %s): %s" % (array.dtype, array.shape, e))
# Depth edges without a depth image: the filter's own error, as a Python exception.
try:
    vtkmlaa.antialias_array(numpy.zeros((8, 8, 3), numpy.uint8), edge_detection="depth")
    check(False, "depth edges without a depth image raise RuntimeError")
except RuntimeError as e:
    check("depth" in str(e).lower(), "the RuntimeError carries the VTK error: %s" % e)
for kwargs in ({"preset": "best"}, {"method": "smaa"}, {"search": 3}):
    try:
        vtkmlaa.antialias_array(numpy.zeros((8, 8), numpy.uint8), **kwargs)
        check(False, "antialias_array(%s) raises ValueError" % kwargs)
    except ValueError:
        pass

check.finish()
