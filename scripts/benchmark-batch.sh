#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# Frames per second of `mlaa --output-dir` (one process for the whole batch) against the same
# work done by running `mlaa INPUT OUTPUT` once per file, on synthetic aliased frames.
#   scripts/benchmark-batch.sh [FRAMES [WIDTH HEIGHT [MLAA]]]
# Defaults: 100 frames of 1920 x 1080 (8-bit RGB PNG), build/bin/mlaa. Needs /usr/bin/python3
# with numpy and oiiotool (scripts/install-deps.sh installs both). MLAA_OPTIONS adds options to
# both ways (e.g. --preset high), MLAA_BATCH_OPTIONS to the batch only (e.g. --jobs 1). Not a
# test: it takes minutes.
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
frames="${1:-100}"
width="${2:-1920}"
height="${3:-1080}"
mlaa="${4:-$source_dir/build/bin/mlaa}"
read -r -a options <<<"${MLAA_OPTIONS:-}"
read -r -a batch_options <<<"${MLAA_BATCH_OPTIONS:-}"

[ -x "$mlaa" ] || { echo "benchmark-batch: no mlaa executable at $mlaa" >&2; exit 1; }
work="$(mktemp -d "${TMPDIR:-/tmp}/mlaa-benchmark.XXXXXX")"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/frames" "$work/batch" "$work/single"

# Frames of an animation: discs moving over a gradient, a slanted wavy band and thin dark
# lines, drawn without antialiasing (every pixel is inside or outside), so every frame is
# different and full of staircases.
/usr/bin/python3 - "$frames" "$width" "$height" "$work/frames" <<'EOF'
import sys
import numpy as np
count, w, h, folder = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
y, x = np.mgrid[0:h, 0:w].astype(np.float32)
base = np.stack([x / w * 180 + 30, y / h * 160 + 40, (x + y) / (w + h) * 120 + 60], -1)
for f in range(count):
    t = f / max(count, 1)
    image = base.copy()
    for k in range(14):
        cx = (0.08 * w + k * 0.07 * w + 0.2 * w * t) % w
        cy = h * (0.2 + 0.05 * (k % 13)) + 0.1 * h * np.sin(6.28 * t + k)
        r = h * (0.055 + 0.011 * (k % 4))
        image[(x - cx) ** 2 + ((y - cy) * 1.3) ** 2 < r * r] = [(k * 53) % 256, (k * 97) % 256,
                                                                 (k * 31 + 100) % 256]
    band = (y - 0.55 * h) < (0.3 + 0.2 * t) * (x - 0.1 * w) + 0.04 * h * np.sin(x / 90.0)
    image[band & (y > 0.52 * h) & (x > 0.05 * w)] = [240, 230, 40]
    for k in range(6):
        line = np.abs((y - 0.74 * h - 0.028 * h * k) - 0.12 * (k + 1) * (x - w / 2) * (0.5 + t))
        image[line < 1.0 + 0.5 * k] = [20, 20, 20]
    with open("%s/frame.%04d.ppm" % (folder, f + 1), "wb") as out:
        out.write(b"P6 %d %d 255\n" % (w, h) + np.clip(image, 0, 255).astype(np.uint8).tobytes())
EOF
oiiotool --frames "1-$frames" "$work/frames/frame.#.ppm" -o "$work/frames/frame.#.png"
rm -f "$work/frames/"*.ppm
inputs=("$work/frames/"*.png)

now() { date +%s.%N; }
since() { awk -v a="$1" -v b="$(now)" 'BEGIN { printf "%.3f", b - a }'; }
echo "benchmark-batch: ${#inputs[@]} frames of ${width}x${height}, $(nproc) processors," \
  "load average $(cut -d' ' -f1-3 /proc/loadavg)"

start="$(now)"
"$mlaa" "${options[@]}" "${batch_options[@]}" --quiet --output-dir "$work/batch" "${inputs[@]}"
batch_seconds="$(since "$start")"

start="$(now)"
for input in "${inputs[@]}"; do
  "$mlaa" "${options[@]}" "$input" "$work/single/$(basename "$input")"
done
single_seconds="$(since "$start")"

# Both ways must write the same files.
for input in "${inputs[@]}"; do
  name="$(basename "$input")"
  cmp -s "$work/batch/$name" "$work/single/$name" ||
    { echo "benchmark-batch: $name differs between the two ways" >&2; exit 1; }
done

awk -v n="${#inputs[@]}" -v b="$batch_seconds" -v s="$single_seconds" 'BEGIN {
  printf "batch (--output-dir):   %7.2f s  %6.2f frames/s\n", b, n / b
  printf "one mlaa per file:      %7.2f s  %6.2f frames/s\n", s, n / s
  printf "batch / per file:       %7.2f x\n", s / b
}'
echo "benchmark-batch: load average after $(cut -d' ' -f1-3 /proc/loadavg)"
