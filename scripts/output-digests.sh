#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# Prints one line per output, "NAME SHA-1 of the pixels", for a fixed set of inputs and option
# sets run through the mlaa tool (CPU filter) and the demo (GPU pass under Xvfb). Run it before
# and after a change that must not change any output, and compare:
#   scripts/output-digests.sh build > before.txt   (on the old commit)
#   scripts/output-digests.sh build > after.txt    (on the new one)
#   diff before.txt after.txt
# The inputs are derived from the committed render Testing/Data/mixed-320x240.png with oiiotool:
# 8- and 16-bit PNG, grey, grey + alpha, RGBA with a varying alpha, float TIFF, half EXR, and
# odd sizes (1 x 1, 1 x N, 17 x 9).
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="$(cd "${1:-$source_dir/build}" && pwd)"
mlaa="$build_dir/bin/mlaa"
demo="$build_dir/bin/mlaa-demo"
[ -x "$mlaa" ] || { echo "output-digests: no $mlaa (build first)" >&2; exit 2; }

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
src="$source_dir/Testing/Data/mixed-320x240.png"

# Inputs.
oiiotool "$src" -d uint8 -o "$work/rgb8.png"
oiiotool "$src" -d uint16 -o "$work/rgb16.png"
oiiotool "$src" --ch R -d uint8 -o "$work/grey8.png"
oiiotool "$src" --ch R,G --chnames Y,A -d uint8 -o "$work/greyalpha8.png"
oiiotool "$src" --ch R,G,B,B --chnames R,G,B,A -d uint8 -o "$work/rgba8.png"
oiiotool "$src" --ch R,G,B,=1.0 --chnames R,G,B,A -d uint8 -o "$work/rgbaconst8.png"
oiiotool "$src" -d float -o "$work/rgbfloat.tif"
oiiotool "$src" -d half -o "$work/rgbhalf.exr"
oiiotool "$src" --cut 17x9+100+100 -d uint8 -o "$work/odd8.png"
oiiotool "$src" --cut 1x1+160+120 -d uint8 -o "$work/one8.png"
oiiotool "$src" --cut 1x40+160+100 -d uint8 -o "$work/column8.png"
oiiotool "$src" --rotate 7 -d uint8 -o "$work/rotated8.png"
oiiotool "$src" --resize 640x480 --rotate 33 -d uint16 -o "$work/rotated16.png"
oiiotool "$src" --ch R,G,B --rotate 90 -d float -o "$work/rotatedfloat.tif"
oiiotool "$src" --ch G -d uint16 -o "$work/grey16.png"

option_sets=(
  "defaults:"
  "low:--preset low"
  "medium:--preset medium"
  "ultra:--preset ultra"
  "luma:--edges luma --threshold 0.05"
  "color:--edges color --max-search-steps 8 --diagonals off"
  "steps64:--max-search-steps 64"
  "reconstruction:--edges lab --reconstruction on"
  "chapter:--diagonals off --local-contrast 0 --dominant-blending off"
  "premultiplied:--alpha premultiplied"
  "edges:--debug edges"
  "weights:--debug weights"
  "valuerange:--value-range auto"
  "dlaa:--method dlaa"
  "dlaa-short:--method dlaa --long-edges off --dlaa-luma green"
)

for input in "$work"/*.png "$work"/*.tif "$work"/*.exr; do
  name="$(basename "$input")"
  ext="${name##*.}"
  for set in "${option_sets[@]}"; do
    label="${set%%:*}"
    read -r -a options <<<"${set#*:}"
    out="$work/out-$label-$name"
    if "$mlaa" "${options[@]}" "$input" "$out" 2>"$work/err"; then
      hash="$(oiiotool --info -v --hash "$out" | sed -n 's/.*SHA-1: *//p')"
      rm -f "$out"
    else
      hash="error:$(head -c 200 "$work/err" | tr '\n' ' ')"
    fi
    echo "$label/$name $hash"
  done
done

# The GPU pass, through the demo (each picture holds the plain render and the pass's result).
if [ -x "$demo" ]; then
  for scene in $("$demo" --list 2>/dev/null | awk -F: '{print $1}'); do
    out="$work/demo-$scene.png"
    if "$source_dir/scripts/with-xvfb.sh" "$demo" --scene "$scene" --output "$out" \
      >/dev/null 2>&1; then
      echo "demo/$scene $(oiiotool --info -v --hash "$out" | sed -n 's/.*SHA-1: *//p')"
    else
      echo "demo/$scene error"
    fi
  done
fi
