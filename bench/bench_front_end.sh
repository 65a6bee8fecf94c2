#!/usr/bin/env bash
# bench_front_end.sh [--libgl PATH] [--triangles N] [--frames F] [--rounds R]
#
# Geometry submission speed of glpt's raster mode against real Mesa (llvmpipe, the system
# libGL), in the same private Xvfb, alternating Mesa and glpt R times for each mode of
# bench/gl_throughput (immediate, arrays, elements, vbo; N small lit triangles per frame):
#   submit_ms  the frame's GL calls alone: for immediate mode, the vertex capture of the front end
#   frame_ms   the whole frame, glFinish and swap included
# Prints every run, the median per mode and implementation, the ratios Mesa/glpt (above 1: glpt
# is faster) and the command to reproduce. Not a test: run it on an idle machine.
#
#   --libgl PATH    glpt's libGL.so.1 (default: <repo>/build/gl_shim/libGL.so.1)
#   --triangles N   triangles per frame (default 100000)
#   --frames F      measured frames per run (default 20)
#   --rounds R      Mesa/glpt pairs per mode (default 3)
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${GLPT_BUILD_DIR:-$repo/build}
libgl=$build/gl_shim/libGL.so.1
triangles=100000
frames=20
rounds=3
usage() { sed -n '2,17p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case $1 in
    --libgl) libgl=$2; shift 2 ;;
    --triangles) triangles=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "bench_front_end: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
for n in "$triangles" "$frames" "$rounds"; do
  [[ $n =~ ^[1-9][0-9]*$ ]] || { echo "bench_front_end: bad number '$n'" >&2; exit 2; }
done
libgl=$(realpath "$libgl" 2>/dev/null || echo "$libgl")
[ -f "$libgl" ] || { echo "bench_front_end: libGL not found: $libgl (build first)" >&2; exit 2; }
program=$build/bench/gl_throughput
[ -x "$program" ] || { echo "bench_front_end: $program not built" >&2; exit 2; }

if [ -z "${GLPT_BENCH_UNDER_XVFB:-}" ]; then
  GLPT_BENCH_UNDER_XVFB=1 exec "$repo/tests/e2e/with_xvfb.sh" "$0" --libgl "$libgl" \
    --triangles "$triangles" --frames "$frames" --rounds "$rounds"
fi

results=$(mktemp)
trap 'rm -f "$results"' EXIT
for mode in immediate arrays elements vbo; do
  for ((round = 1; round <= rounds; ++round)); do
    for impl in mesa glpt; do
      if [ "$impl" = mesa ]; then
        line=$("$program" --mode "$mode" --triangles "$triangles" --frames "$frames")
      else
        line=$(LD_PRELOAD=$libgl GLPT_MODE=raster GLPT_QUIET=1 "$program" --mode "$mode" \
          --triangles "$triangles" --frames "$frames")
      fi
      echo "$impl $line"
      echo "$impl $line" >>"$results"
    done
  done
done

echo
python3 - "$results" <<'EOF'
import re, statistics, sys
runs = {}
for line in open(sys.argv[1]):
    impl, rest = line.split(" ", 1)
    f = dict(kv.split("=") for kv in rest.split())
    runs.setdefault((f["mode"], impl), []).append((float(f["submit_ms"]), float(f["frame_ms"])))
print(f"{'mode':10} {'Mesa submit':>12} {'glpt submit':>12} {'ratio':>6}   {'Mesa frame':>11} {'glpt frame':>11} {'ratio':>6}")
for mode in ("immediate", "arrays", "elements", "vbo"):
    m, g = runs[(mode, "mesa")], runs[(mode, "glpt")]
    ms, gs = statistics.median(x[0] for x in m), statistics.median(x[0] for x in g)
    mf, gf = statistics.median(x[1] for x in m), statistics.median(x[1] for x in g)
    print(f"{mode:10} {ms:10.2f}ms {gs:10.2f}ms {ms / gs:6.2f}   {mf:9.2f}ms {gf:9.2f}ms {mf / gf:6.2f}")
EOF
echo
echo "reproduce: bench/bench_front_end.sh --triangles $triangles --frames $frames --rounds $rounds"
