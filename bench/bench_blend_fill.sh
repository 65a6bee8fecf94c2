#!/usr/bin/env bash
# bench_blend_fill.sh [--size WxH] [--layers N] [--rounds R] [LIBGL]
#
# What blending costs per pixel: bench/blend_fill (N window-sized quads a frame, each blended
# with one of four blend states) under real Mesa (llvmpipe), under glpt's raster mode as it
# runs by default (a blend state blends in the fragment shader in the first records that use it,
# then in the pipeline: RasterRenderer::shader_blends) and with the pipeline's blending only
# (GLPT_VK_NO_SHADER_BLEND=1), alternating within each of R rounds (default 5) in one private
# Xvfb. Prints each run and the median frame time (the first two frames of each run left out)
# and blended megapixels per second per setting, and the command. LIBGL: glpt's libGL.so.1
# (default <repo>/build/gl_shim/libGL.so.1). Not a test.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
size=640x480
layers=16
rounds=5
while [ $# -gt 0 ]; do
  case $1 in
    --size) size=$2; shift 2 ;;
    --layers) layers=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    -h|--help) sed -n '2,11p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) break ;;
  esac
done
libgl=$(realpath "${1:-$repo/build/gl_shim/libGL.so.1}")
program=${GLPT_BUILD_DIR:-$repo/build}/bench/blend_fill
[ -x "$program" ] || { echo "bench_blend_fill: build $program first" >&2; exit 2; }
[ -f "$libgl" ] || { echo "bench_blend_fill: no $libgl" >&2; exit 2; }
echo "command: bench/bench_blend_fill.sh --size $size --layers $layers --rounds $rounds $libgl"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
"$repo/tests/e2e/with_xvfb.sh" bash -c '
  set -euo pipefail
  program=$1 libgl=$2 size=$3 layers=$4 rounds=$5
  args=(--size "$size" --layers "$layers" --frames 30)
  for round in $(seq 1 "$rounds"); do
    echo "run mesa $("$program" "${args[@]}")"
    echo "run glpt $(GLPT_MODE=raster GLPT_QUIET=1 LD_PRELOAD="$libgl" "$program" "${args[@]}")"
    echo "run glpt_pipeline_blend $(GLPT_VK_NO_SHADER_BLEND=1 GLPT_MODE=raster GLPT_QUIET=1 \
      LD_PRELOAD="$libgl" "$program" "${args[@]}")"
  done
' _ "$program" "$libgl" "$size" "$layers" "$rounds" | tee /dev/stderr | /usr/bin/env python3 -c '
import re, statistics, sys
runs = {}
for line in sys.stdin:
    m = re.match(r"run (\S+) frame_ms=([0-9.]+) mpixels_per_s=([0-9.]+)", line)
    if m: runs.setdefault(m.group(1), []).append((float(m.group(2)), float(m.group(3))))
mesa = statistics.median(r[0] for r in runs["mesa"])
for name, rs in runs.items():
    ms = statistics.median(r[0] for r in rs)
    print("%-20s frame %8.3f ms  %8.1f Mpixels/s  frame time / Mesa %.2f" % (
        name, ms, statistics.median(r[1] for r in rs), ms / mesa))
'
