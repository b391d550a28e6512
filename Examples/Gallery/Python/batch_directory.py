#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Gallery: antialias every image of a directory (frames of an animation, a folder of
screenshots), from Python.

    batch_directory.py INPUT_DIR OUTPUT_DIR [--preset low|medium|high|ultra|max] [--method mlaa|dlaa]

Each PNG, JPEG, BMP or PNM file of INPUT_DIR goes through one filter, set up once and reused,
into OUTPUT_DIR under the same name and format (through a temporary file renamed when complete).
A file that fails is reported by name and the rest go on; the exit status is 1 if any failed,
2 for bad arguments (the input directory is refused as the output). `mlaa --output-dir` does
this with all cores and more formats.
"""
import argparse
import os
import sys

from antialias_image import ErrorCounter, WRITERS, make_filter, reader_for, write_image


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("input_dir")
    parser.add_argument("output_dir")
    parser.add_argument("--preset", help="low, medium, high (the default), ultra or max (MLAA)")
    parser.add_argument("--method", choices=("mlaa", "dlaa"), default="mlaa")
    args = parser.parse_args(argv)
    if not os.path.isdir(args.input_dir):
        print(args.input_dir + ": not a directory", file=sys.stderr)
        return 2
    os.makedirs(args.output_dir, exist_ok=True)
    if os.path.samefile(args.input_dir, args.output_dir):
        print(args.output_dir + ": cannot be the output directory (it is the input directory)",
              file=sys.stderr)
        return 2

    # One filter for all files: its options (and the area texture they select) are set up once.
    try:
        aa = make_filter(args.method, args.preset)
    except ValueError as error:
        print(error, file=sys.stderr)
        return 2
    errors = ErrorCounter()
    errors.watch(aa)

    inputs = sorted(name for name in os.listdir(args.input_dir)
                    if os.path.isfile(os.path.join(args.input_dir, name)) and
                    os.path.splitext(name)[1].lower() in WRITERS)
    failed = 0
    for name in inputs:
        source = os.path.join(args.input_dir, name)
        target = os.path.join(args.output_dir, name)
        reader = reader_for(source)
        if reader is None:
            print(source + ": not an image file VTK can read", file=sys.stderr)
            ok = False
        else:
            errors.watch(reader)
            aa.SetInputConnection(reader.GetOutputPort())
            ok = write_image(aa.GetOutputPort(), target, errors)
            aa.RemoveAllInputConnections(0)  # release the reader
        if not ok:
            print(source + ": failed", file=sys.stderr)
            failed += 1
            continue
        print("%s -> %s" % (source, target))
    print("%d of %d images antialiased" % (len(inputs) - failed, len(inputs)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
