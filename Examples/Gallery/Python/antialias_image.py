#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Gallery: antialias an image file with vtkImageMLAA (or vtkImageDLAA), from Python.

    antialias_image.py INPUT OUTPUT [--preset low|medium|high|ultra|max] [--method mlaa|dlaa]

Reads INPUT with the VTK reader that recognises it (PNG, JPEG, BMP, PNM, ...), antialiases it
and writes OUTPUT in the format its extension names (.png, .jpg, .bmp, .pnm). Use it when you
have renders or screenshots on disk: the few lines to copy are read -> filter -> write. Exit
status 1 when the input cannot be read or the output cannot be written, 2 for bad arguments.
The `mlaa` command-line tool does the same for more formats (TIFF, EXR) with OpenImageIO.
"""
import argparse
import os
import sys

import vtkmlaa
from vtkmodules.vtkCommonCore import VTK_STRING
from vtkmodules.vtkIOImage import (vtkBMPWriter, vtkImageReader2Factory, vtkJPEGWriter,
                                   vtkPNGWriter, vtkPNMWriter)


def reader_for(path):
    """The VTK reader that recognises the file's contents and its extension, or None. (Both:
    a TGA file has no signature, so VTK's TGA reader claims any file.)"""
    reader = vtkImageReader2Factory.CreateImageReader2(path)
    if reader is None:
        return None
    extension = os.path.splitext(path)[1].lower()
    if not extension or extension not in reader.GetFileExtensions().lower().split():
        return None
    reader.SetFileName(path)
    return reader


WRITERS = {".png": vtkPNGWriter, ".jpg": vtkJPEGWriter, ".jpeg": vtkJPEGWriter,
           ".bmp": vtkBMPWriter, ".pnm": vtkPNMWriter, ".ppm": vtkPNMWriter,
           ".pgm": vtkPNMWriter}


class ErrorCounter:
    """VTK reports errors as ErrorEvent and does not raise; this counts (and prints) the
    errors and warnings of the objects it watches."""

    def __init__(self):
        self.count = 0

    def watch(self, obj):
        obj.AddObserver("ErrorEvent", self._report)
        obj.AddObserver("WarningEvent", self._report)

    def _report(self, caller, event, message=None):
        self.count += 1
        print(str(message).strip(), file=sys.stderr)

    _report.CallDataType = VTK_STRING


def write_image(port, path, errors):
    """Writes an algorithm's output to path, in the format of its extension, through a
    temporary file renamed when complete (a failure never leaves half an image). Returns
    whether it worked."""
    directory, name = os.path.split(path)
    extension = os.path.splitext(name)[1].lower()
    if extension not in WRITERS:
        print("%s: unknown extension (use %s)" % (path, ", ".join(sorted(WRITERS))),
              file=sys.stderr)
        return False
    temporary = os.path.join(directory, "." + name + ".partial" + extension)
    writer = WRITERS[extension]()
    before = errors.count
    errors.watch(writer)
    writer.SetInputConnection(port)
    writer.SetFileName(temporary)
    writer.Write()  # updates the pipeline upstream: read, antialias, write
    if errors.count == before and writer.GetErrorCode() == 0:
        try:
            os.replace(temporary, path)
            return True
        except OSError as error:
            print("%s: %s" % (path, error), file=sys.stderr)
    if os.path.exists(temporary):
        os.remove(temporary)
    print(path + ": not written", file=sys.stderr)
    return False


def make_filter(method, preset):
    """vtkImageMLAA or vtkImageDLAA, with a preset (MLAA only; the default is `high`)."""
    if method == "dlaa":
        if preset is not None:
            raise ValueError("DLAA has no presets")
        return vtkmlaa.vtkImageDLAA()
    aa = vtkmlaa.vtkImageMLAA()
    if preset is not None:
        value = vtkmlaa.vtkMLAAOptions.GetPresetFromString(preset)
        if value < 0:
            raise ValueError("%s: not a preset (%s)" % (preset, ", ".join(vtkmlaa.PRESETS)))
        aa.GetOptions().SetPreset(value)
    return aa


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("input")
    parser.add_argument("output")
    parser.add_argument("--preset", help="low, medium, high (the default), ultra or max (MLAA)")
    parser.add_argument("--method", choices=vtkmlaa.METHODS, default="mlaa")
    args = parser.parse_args(argv)
    try:
        aa = make_filter(args.method, args.preset)
    except ValueError as error:
        print(error, file=sys.stderr)
        return 2

    # 1. Read: the factory picks the reader from the file's contents.
    reader = reader_for(args.input)
    if reader is None:
        print(args.input + ": not an image file VTK can read", file=sys.stderr)
        return 1

    # 2. Antialias, 3. write (the writer updates the pipeline).
    errors = ErrorCounter()
    errors.watch(reader)
    errors.watch(aa)
    aa.SetInputConnection(reader.GetOutputPort())
    if not write_image(aa.GetOutputPort(), args.output, errors):
        return 1
    out = aa.GetOutput()
    width, height, _ = out.GetDimensions()
    print("wrote %s (%dx%d, %d channels, %s)" % (args.output, width, height,
                                                 out.GetNumberOfScalarComponents(),
                                                 args.method.upper()))
    return 0


if __name__ == "__main__":
    sys.exit(main())
