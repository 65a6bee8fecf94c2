#!/usr/bin/env bash
# bench_vertex_stream.sh [--libgl PATH] [--vertices N] [--rounds R]
#
# Issue 20's vertex-bound stream (bench/vertex_stream.c: N glNormal3f/glVertex3f pairs per frame
# as lit GL_TRIANGLES, 99 in 100 of zero area, a 64x64 window, glFinish after glEnd) drawn by
# real Mesa (llvmpipe, the system libGL) and glpt's raster mode, alternating R times in one
# private Xvfb. Prints every run, the medians in millions of vertices per second, the ratio
# glpt/Mesa (above 1: glpt is faster), then where glpt's frame goes (GLPT_STATS of one more run:
# capture_ms = the front end's recording of the calls, upload_ms = conversion and copy into GPU
# memory, raster_ms = the device's work: vertex shader, clipping, setup, the few pixels) per
# vertex, and the command.
#
#   --libgl PATH    glpt's libGL.so.1 (default: <repo>/build/gl_shim/libGL.so.1)
#   --vertices N    vertices per frame (default 300000)
#   --rounds R      Mesa/glpt pairs (default 5)
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
libgl=$repo/build/gl_shim/libGL.so.1
vertices=300000
rounds=5
usage() { sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case $1 in
    --libgl) libgl=$2; shift 2 ;;
    --vertices) vertices=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "bench_vertex_stream: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
libgl=$(realpath "$libgl")
program=${VERTEX_STREAM:-$repo/build/bench/vertex_stream}
[ -x "$program" ] && [ -f "$libgl" ] || { echo "bench_vertex_stream: build first" >&2; exit 2; }
echo "command: $0 --libgl $libgl --vertices $vertices --rounds $rounds"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"

"$repo/tests/e2e/with_xvfb.sh" bash -c '
  set -euo pipefail
  program=$1 libgl=$2 vertices=$3 rounds=$4
  for round in $(seq 1 "$rounds"); do
    echo "mesa $("$program" --vertices "$vertices")"
    echo "glpt $(GLPT_MODE=raster LD_PRELOAD="$libgl" "$program" --vertices "$vertices")"
  done
  GLPT_STATS=1 GLPT_MODE=raster LD_PRELOAD="$libgl" "$program" --vertices "$vertices" 2>&1 |
    grep "^glpt: frame=" | tail -10 | sed "s/^/stats /"' bench "$program" "$libgl" "$vertices" "$rounds" |
  /usr/bin/python3 -c '
import re, statistics, sys
rates = {"mesa": [], "glpt": []}
stages = {"capture_ms": [], "upload_ms": [], "raster_ms": [], "total_ms": []}
vertices = None
for line in sys.stdin:
    print(line.rstrip())
    who = line.split()[0]
    if who in rates:
        rates[who].append(float(re.search(r"mverts_per_s=([0-9.]+)", line).group(1)))
        vertices = int(re.search(r"vertices=([0-9]+)", line).group(1))
    elif who == "stats":
        for key in stages:
            m = re.search(key + r"=([0-9.]+)", line)
            if m: stages[key].append(float(m.group(1)))
mesa, glpt = statistics.median(rates["mesa"]), statistics.median(rates["glpt"])
print(f"median Mverts/s: Mesa {mesa:.2f}, glpt {glpt:.2f}; glpt/Mesa = {glpt / mesa:.2f}")
print("glpt per frame (GLPT_STATS, median of the last 10 frames of one run), ns per vertex:")
for key, values in stages.items():
    if values:
        ms = statistics.median(values)
        print(f"  {key} {ms:.2f} ms = {ms * 1e6 / vertices:.1f} ns/vertex")
'
