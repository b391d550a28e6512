# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""What the plugin's pvbatch tests share: their arguments, loading the plugin, gathering a
distributed image on the first rank, image files, running the `mlaa` tool, and comparisons.

Every test is run as `pvbatch [--mpi] TEST.py --plugin MLAA.so --output-dir DIR --ranks N ...`;
only the first rank runs the script (pvbatch's default), the others serve it."""

import argparse
import os
import subprocess
import sys

import numpy as np

from paraview import servermanager as sm
from paraview import simple
from vtkmodules.numpy_interface import dataset_adapter as dsa
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkIOXML import vtkXMLPImageDataReader
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData


def parse_arguments(extra=None):
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True, help="the MLAA plugin library")
    parser.add_argument("--output-dir", required=True, help="where the test writes its files")
    parser.add_argument("--ranks", type=int, required=True, help="the number of MPI ranks")
    parser.add_argument("--tool", help="the mlaa tool of the main project's build")
    if extra:
        extra(parser)
    args = parser.parse_args()
    os.makedirs(args.output_dir, exist_ok=True)
    return args


def fail(message):
    print("FAIL: " + message, flush=True)
    sys.exit(1)


def check(condition, message):
    if not condition:
        fail(message)
    print("ok: " + message, flush=True)


def load_plugin(path, namespace):
    """Loads the plugin as the README says, and checks that this run has the ranks it should."""
    simple.LoadPlugin(path, remote=False, ns=namespace)


def show_view_scene(view):
    """The MLAA view tests' scene in `view`, an MLAARenderView (TestMLAAView.py, and
    TestMLAAClientServer.py, which compares a server's screenshots with the built-in session's):
    flat-shaded objects (no lighting: each is one colour, so flat regions are truly flat) over a
    background that is neither black nor white, seen by a fixed camera, 400 x 300 pixels. Under
    IceT the pass works on the composited image, whose background is transparent: a wrong alpha
    convention would leave halos of the wrong colour around the silhouettes, and the nearly black
    sphere would have no edges at all against the transparent black IceT composites over.
    Returns the view's size and the large sphere (split across the ranks when there are
    several)."""
    size = [400, 300]
    view.ViewSize = size
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [0.32, 0.34, 0.43]
    sphere = simple.Sphere(ThetaResolution=64, PhiResolution=64, Radius=0.5)
    for source, colour in (
            (sphere, [0.9, 0.6, 0.1]),
            (simple.Cone(Resolution=7, Center=[0.7, 0.2, 0.0], Radius=0.35), [0.2, 0.8, 0.3]),
            (simple.Box(Center=[-0.6, -0.4, 0.2], XLength=0.5, YLength=0.3), [0.95, 0.95, 0.95]),
            (simple.Sphere(Center=[-0.55, 0.45, 0.0], Radius=0.2), [0.03, 0.03, 0.04])):
        display = simple.Show(source, view)
        display.ColorArrayName = ['POINTS', '']
        display.AmbientColor = colour
        display.DiffuseColor = colour
        display.Ambient = 1.0
        display.Diffuse = 0.0
    view.CameraPosition = [0.4, 0.5, 4.0]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.2, 1.0, 0.0]
    view.CameraParallelProjection = 0
    view.CameraViewAngle = 30
    return size, sphere


def process_id_range(source):
    """The range of the ids of the ranks that hold `source`'s points, from the data information
    of ParaView 6's ProcessIds filter (point array PointProcessIds) or of ParaView 5.11's
    ProcessIdScalars (ProcessId), which 6 no longer has. (On 6.1, Fetch() of ProcessIds on two
    ranks drops the array, so the data information is read, which covers every rank.)"""
    if hasattr(simple, "ProcessIds"):
        ids, name = simple.ProcessIds(Input=source), "PointProcessIds"
    else:
        ids, name = simple.ProcessIdScalars(Input=source), "ProcessId"
    ids.UpdatePipeline()
    return tuple(ids.PointData[name].GetRange())


def check_split(source, ranks, what):
    """Checks that the data of `source` lies on every one of `ranks` ranks (process ids 0 to
    ranks - 1), so that IceT composites it."""
    owners = process_id_range(source)
    check(owners == (0.0, ranks - 1.0),
          "the %s is split across the ranks (process ids %s), so IceT composites" % (what, owners))


def number_of_ranks():
    return sm.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()


def gather_image(proxy, path, array):
    """The whole image that `proxy` produces across the ranks, as (extent, numpy array of
    `array`): written piece by piece by the ranks with ParaView's parallel writer (.pvti), then
    read back whole here. (servermanager.Fetch gives only the first rank's piece of an image.)"""
    simple.SaveData(path, proxy=proxy)
    # Every rank has written its piece once it has served a request made after the save: a
    # Fetch gathers from all of them.
    sm.Fetch(proxy)
    reader = vtkXMLPImageDataReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    values = dsa.WrapDataObject(image).PointData[array]
    if not isinstance(values, np.ndarray):
        fail("%s has no point array %s" % (path, array))
    return image.GetExtent(), np.array(values)


def as_rows(extent, values):
    """A point array of a 2D image as rows (y, x, components), row 0 at the bottom (VTK)."""
    width = extent[1] - extent[0] + 1
    height = extent[3] - extent[2] + 1
    return values.reshape(height, width, -1)


def write_png(path, rows):
    """Writes (y, x, components) uint8 rows, row 0 at the bottom, as a PNG (top row first)."""
    height, width, components = rows.shape
    image = vtkImageData()
    image.SetDimensions(width, height, 1)
    array = numpy_to_vtk(np.ascontiguousarray(rows.reshape(-1, components)), deep=1)
    array.SetName("rgb")
    image.GetPointData().SetScalars(array)
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def read_png(path):
    """A PNG as (y, x, components) uint8 rows, row 0 at the bottom."""
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    if image.GetNumberOfPoints() == 0:
        fail("cannot read " + path)
    dims = image.GetDimensions()
    values = np.array(dsa.WrapDataObject(image).PointData[0])
    return values.reshape(dims[1], dims[0], -1)


def run_tool(tool, arguments, source, target):
    """Runs the main project's `mlaa` tool (vtkImageMLAA built against the system VTK, outside
    ParaView) on a PNG file."""
    if not tool or not os.path.isfile(tool):
        fail("the mlaa tool is needed (--tool): %r" % tool)
    command = [tool] + arguments + [source, target]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        fail("%s failed: %s" % (" ".join(command), result.stderr.strip()))
    return read_png(target)


def uniform_neighbourhoods(rows, radius=1):
    """True where every pixel within `radius` (a square) holds the pixel's own value (image border
    excluded): pixels an antialiasing filter that reads no farther must leave alone. MLAA
    blends a pixel with its four neighbours only across an edge: radius 1. DLAA reads the
    5-pixel crosses of pixels up to 8 away along x and y: radius 10."""
    height, width, _ = rows.shape
    r = radius
    centre = rows[r:height - r, r:width - r]
    same = np.ones(centre.shape[:2], dtype=bool)
    for dy in range(-r, r + 1):
        for dx in range(-r, r + 1):
            neighbour = rows[r + dy:height - r + dy, r + dx:width - r + dx]
            same &= np.all(neighbour == centre, axis=2)
    mask = np.zeros((height, width), dtype=bool)
    mask[r:height - r, r:width - r] = same
    return mask


def max_difference(a, b):
    return int(np.max(np.abs(a.astype(np.int32) - b.astype(np.int32))))
