#!/usr/bin/env python3
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
"""Writes the seed corpora of the fuzz targets: Testing/Fuzz/corpus/<target>/, a few KB each.

    Testing/Fuzz/make-corpus.py BUILD_FUZZ_DIR

Each seed is a case the targets should reach at once rather than search for: images with
edges (staircases, a checker) of every scalar type, 1 to 4 components, odd, one-pixel, wide
and 3D extents, NaN and infinities, and the options of both filters; image files of the
formats the tool reads (written by oiiotool from a staircase made here), with command lines.
The byte layouts are those the targets' file comments describe. Inputs that fuzzing found
failing are kept in findings/<target>/ and copied in as "finding-NAME". BUILD_FUZZ_DIR (scripts/fuzz.sh
builds it) gives mlaa_tool_fuzzer, which lists the options and extensions it picks from, so
that seeds name options and extensions, not their places in the target. Old seeds are
replaced, with the same bytes but for the GIF and SGI files: OpenImageIO 2.4's writers of
those put bytes it never initialised into the file (in SGI's header, what look like pointers).
"""

import os
import shutil
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))

# mlaa_filter_fuzzer.cxx: ScalarTypes, with struct formats.
TYPES = ["char", "signed char", "unsigned char", "short", "unsigned short", "int",
         "unsigned int", "long", "unsigned long", "long long", "unsigned long long", "float",
         "double", "vtkIdType"]
FORMATS = "bbBhHiIqQqQfdq"


def staircase(w, h, d, slope):
    """Palette indices (0/1) of a shape with a slanted edge, x fastest."""
    return [1 if y * slope + z < x else 0
            for z in range(d) for y in range(h) for x in range(w)]


def checker(w, h, d, size):
    return [((x // size) + (y // size) + z) % 4 for z in range(d) for y in range(h) for x in range(w)]


def pack_indices(indices):
    out = bytearray()
    for i in range(0, len(indices), 4):
        byte = 0
        for k, v in enumerate(indices[i:i + 4]):
            byte |= (v & 3) << (2 * k)
        out.append(byte)
    return bytes(out)


def filter_seed(type_name, comps, w, h, d, palette, indices, dlaa=False, streamed=False,
                value_range=None, damage=0, depth=None, origin=(0, 0, 0), preset=2,
                threshold=26, local_contrast=5, edges=0, steps=16, switches=0b00101,
                debug=0, dlaa_fields=(25, 20, 0, 0), sub=(2, 200, 1, 200, 0, 1)):
    """Bytes in mlaa_filter_fuzzer's layout. `palette`: tuples of `comps` values."""
    t = TYPES.index(type_name)
    flags = (1 if dlaa else 0) | (2 if streamed else 0) | (4 if value_range else 0) | 8
    flags |= damage << 4
    if depth is not None:
        flags |= 64
    out = bytearray([flags, t, comps - 1])
    out += struct.pack("<HHB", w - 1, h - 1, d - 1)
    out += struct.pack("<bbb", *origin)
    out += bytes([preset, threshold, local_contrast, edges, steps - 1, switches, debug])
    out += bytes(dlaa_fields)
    lo, hi = value_range if value_range else (0.0, 1.0)
    out += struct.pack("<dd", lo, hi)
    out += bytes(sub)
    out += bytes([0])  # depth image type: float
    out.append(len(palette) - 1)
    fmt = "<" + FORMATS[t] * comps
    for colour in palette:
        out += struct.pack(fmt, *colour)
    out += pack_indices(indices)
    if depth is not None:
        out += struct.pack("<%df" % len(depth), *depth)
    return bytes(out)


def filter_seeds():
    nan, inf = float("nan"), float("inf")
    seeds = {}
    w, h = 24, 16
    stairs = staircase(w, h, 1, 3)
    seeds["uchar-rgb-staircase"] = filter_seed(
        "unsigned char", 3, w, h, 1, [(20, 30, 40), (250, 240, 200)], stairs)
    seeds["uchar-rgba-dlaa-long-edges"] = filter_seed(
        "unsigned char", 4, w, h, 1, [(255, 0, 0, 0), (0, 0, 255, 255)], stairs, dlaa=True,
        dlaa_fields=(10, 30, 1, 1))
    seeds["ushort-grey-ultra-streamed"] = filter_seed(
        "unsigned short", 1, w, h, 1, [(0,), (65535,)], stairs, preset=3, streamed=True,
        sub=(5, 9, 3, 7, 0, 0))
    seeds["ushort-12bit-value-range"] = filter_seed(
        "unsigned short", 2, w, h, 1, [(0, 4095), (4095, 4095)], stairs,
        value_range=(0.0, 4095.0))
    seeds["float-rgba-nan-inf"] = filter_seed(
        "float", 4, w, h, 1, [(0.0, 0.0, 0.0, 1.0), (1.0, 0.5, 0.2, 1.0), (nan, 0.0, 0.0, 1.0),
                              (inf, -inf, 0.0, 0.0)], checker(w, h, 1, 3))
    seeds["double-3d-odd-lab-reconstruction"] = filter_seed(
        "double", 3, 7, 5, 3, [(0.1, 0.2, 0.3), (0.9, 0.8, 0.1), (0.5, 0.5, 0.9)],
        checker(7, 5, 3, 1), edges=3, switches=0b10111, preset=4, origin=(-3, 5, -1))
    seeds["char-one-pixel"] = filter_seed("char", 1, 1, 1, 1, [(5,)], [0])
    seeds["short-wide-color-edges-corners"] = filter_seed(
        "short", 3, 300, 6, 1, [(-32768, 0, 32767), (32767, 0, -32768)], staircase(300, 6, 1, 50),
        edges=1, preset=4, steps=128, switches=0b00011)
    seeds["int-debug-edges"] = filter_seed(
        "int", 1, w, h, 1, [(-2**31,), (2**31 - 1,)], stairs, debug=1)
    seeds["uint-debug-weights"] = filter_seed(
        "unsigned int", 2, w, h, 1, [(0, 2**32 - 1), (2**32 - 1, 2**32 - 1)], stairs, debug=2)
    seeds["longlong-extremes"] = filter_seed(
        "long long", 1, w, h, 1, [(-2**63,), (2**63 - 1,)], stairs)
    seeds["ulonglong-extremes-dlaa"] = filter_seed(
        "unsigned long long", 3, w, h, 1, [(0, 0, 0), (2**64 - 1, 2**63, 1)], stairs, dlaa=True)
    seeds["float-depth-edges"] = filter_seed(
        "float", 3, w, h, 1, [(0.5, 0.5, 0.5)], [0] * (w * h), edges=2,
        depth=[0.2 if v else 0.8 for v in stairs])
    seeds["five-components-refused"] = filter_seed(
        "unsigned char", 5, 4, 4, 1, [(1, 2, 3, 4, 5)], [0] * 16)
    seeds["short-scalars-refused"] = filter_seed(
        "unsigned char", 1, 4, 4, 1, [(1,), (2,)], [0, 1] * 8, damage=1)
    seeds["empty-value-range-refused"] = filter_seed(
        "float", 1, 4, 4, 1, [(0.0,), (1.0,)], [0, 1] * 8, value_range=(1.0, 1.0))
    return seeds


def write_ppm(path, w, h, pixel):
    with open(path, "wb") as f:
        f.write(b"P6\n%d %d\n255\n" % (w, h))
        for y in range(h):
            for x in range(w):
                f.write(bytes(pixel(x, y)))


def write_pfm(path, w, h, grey):
    """A one-channel PFM (little-endian floats, bottom row first)."""
    with open(path, "wb") as f:
        f.write(b"Pf\n%d %d\n-1.0\n" % (w, h))
        for y in reversed(range(h)):
            f.write(struct.pack("<%df" % w, *[grey(x, y) for x in range(w)]))


def tool_seeds(fuzzer):
    env = dict(os.environ, MLAA_FUZZ_LIST="1")
    lines = subprocess.run([fuzzer], env=env, check=True, capture_output=True,
                           text=True).stdout.splitlines()
    names, inputs, outputs = (line.split() for line in lines[:3])
    oiiotool = shutil.which("oiiotool")
    if not oiiotool:
        sys.exit("make-corpus: needs oiiotool (openimageio-tools)")

    def option(name, a=0, b=0):
        return bytes([names.index(name), a, b])

    # (name, input extension, oiiotool arguments after the staircase, output extension,
    #  output exists before, options): a, b pick a value (mlaa_tool_fuzzer.cxx, OptionArgs).
    cases = [
        ("png8-rgb", "png", ["-d", "uint8"], "png", False, []),
        ("png8-rgba-dlaa", "png", ["--ch", "R,G,B,A=0.5", "-d", "uint8"], "tif", False,
         [option("--method", 1)]),
        ("tif16-grey-ultra", "tif", ["--ch", "R", "-d", "uint16"], "exr", False,
         [option("--preset", 3)]),
        ("exr-half-rgba-auto-range", "exr", ["--ch", "R,G,B,A=1", "-d", "half"], "exr", False,
         [option("--value-range", 0)]),
        ("jpg-lab-reconstruction", "jpg", ["-d", "uint8"], "png", False,
         [option("--edges", 3), option("--reconstruction", 0)]),
        ("pnm-debug-edges-existing-output", "pnm", [], "jpg", True, [option("--debug", 1)]),
        ("pfm-float", "pfm", None, "tif", False, [option("--threshold", 40)]),
        ("png-to-bmp", "png", ["-d", "uint8"], "bmp", False, [option("--max-search-steps", 0, 3)]),
        ("tga-rgba-premultiplied", "tga", ["--ch", "R,G,B,A=0.7", "-d", "uint8"], "tga", False,
         [option("--alpha", 2)]),
        ("hdr", "hdr", [], "hdr", False, []),
        ("tif-float-max-pixels-refused", "tif", ["-d", "float"], "png", True,
         [option("--max-pixels", 0, 99)]),
        ("png-grey-depth-edges", "png", ["--ch", "R", "-d", "uint8"], "png", False,
         [option("--edges", 2), option("--depth-image")]),
        ("sgi-dlaa-options", "sgi", ["-d", "uint8"], "sgi", False,
         [option("--method", 1), option("--dlaa-luma", 1), option("--long-edges", 0),
          option("--dlaa-lambda", 200)]),
        ("gif", "gif", ["-d", "uint8"], "png", False, [option("--diagonals", 1)]),
        ("ico", "ico", ["-d", "uint8"], "png", False, [option("--corners", 0)]),
        ("png-one-pixel", "png", ["--resize", "1x1", "-d", "uint8"], "png", False, []),
        ("heic", "heic", ["-d", "uint8"], "png", False, []),
    ]
    seeds = {}
    with tempfile.TemporaryDirectory() as tmp:
        source = os.path.join(tmp, "staircase.ppm")
        write_ppm(source, 20, 12,
                  lambda x, y: (230, 200, 40) if 3 * y < x + 2 else (20, 40, 120))
        for name, ext, args, out_ext, existing, opts in cases:
            path = os.path.join(tmp, name + "." + ext)
            if args is None:  # no writer for .pfm: written here
                write_pfm(path, 20, 12, lambda x, y: 0.9 if 3 * y < x + 2 else 0.1)
            else:
                subprocess.run([oiiotool, "--nosoftwareattrib", source, "--attrib", "DateTime",
                                "2026:01:01 00:00:00"] + args + ["-o", path], check=True,
                               capture_output=True)
            with open(path, "rb") as f:
                data = f.read()
            header = bytes([inputs.index(ext), outputs.index(out_ext), 1 if existing else 0,
                            len(opts)])
            seeds[name] = header + b"".join(opts) + data
    return seeds


def write(target, seeds):
    directory = os.path.join(HERE, "corpus", target)
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    # Inputs that fuzzing found failing, kept as they were found (findings/<target>/): each
    # stays a regression test once fixed.
    findings = os.path.join(HERE, "findings", target)
    if os.path.isdir(findings):
        for name in sorted(os.listdir(findings)):
            with open(os.path.join(findings, name), "rb") as f:
                seeds["finding-" + name] = f.read()
    total = 0
    for name, data in sorted(seeds.items()):
        with open(os.path.join(directory, name), "wb") as f:
            f.write(data)
        total += len(data)
    print("make-corpus: %s: %d seeds, %d bytes" % (target, len(seeds), total))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[2].strip())
    fuzzer = os.path.join(sys.argv[1], "bin", "mlaa_tool_fuzzer")
    write("mlaa_filter_fuzzer", filter_seeds())
    write("mlaa_tool_fuzzer", tool_seeds(fuzzer))


if __name__ == "__main__":
    main()
