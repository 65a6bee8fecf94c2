#!/usr/bin/env bash
# bench_readback.sh [--libgl PATH]... [--rounds N] [--iterations K]
#
# What a small draw followed by glReadPixels costs (the loop of conformance tests such as
# piglit's gl-1.0-blend-func, which reads back 55,104 times), and its two halves: glReadPixels
# with nothing drawn since the last read, and the draw with glFinish. bench/gl_readback (built in
# build/bench) runs each mode against real Mesa (the system libGL: llvmpipe) and each glpt
# libGL.so.1 given (GLPT_MODE=raster, LD_PRELOAD), alternating within every round in one private
# Xvfb so all see the same machine load. Prints each run, the median microseconds per iteration
# per library and mode, the ratio to Mesa, and the command.
#
#   --libgl PATH    a glpt libGL.so.1; repeat to compare builds (default: <repo>/build/gl_shim)
#   --rounds N      runs per library and mode (default 5)
#   --iterations K  iterations per run (default 2000, after 50 warm-up iterations)
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
libgls=()
rounds=5
iterations=2000
usage() { sed -n '2,15p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case $1 in
    --libgl) libgls+=("$(realpath "$2")"); shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --iterations) iterations=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *) echo "bench_readback: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
[ ${#libgls[@]} -gt 0 ] || libgls=("$repo/build/gl_shim/libGL.so.1")
program=${GL_READBACK:-$repo/build/bench/gl_readback}
[ -x "$program" ] || { echo "bench_readback: build $program first" >&2; exit 2; }
for lib in "${libgls[@]}"; do
  [ -f "$lib" ] || { echo "bench_readback: no $lib" >&2; exit 2; }
done
echo "command: $0 ${libgls[*]/#/--libgl } --rounds $rounds --iterations $iterations"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"

"$repo/tests/e2e/with_xvfb.sh" bash -c '
  set -euo pipefail
  program=$1 rounds=$2 iterations=$3; shift 3
  for round in $(seq 1 "$rounds"); do
    for mode in draw_read read draw_finish; do
      us=$("$program" --mode "$mode" --iterations "$iterations" | sed -n "s/.*us_per_iteration=\([0-9.]*\).*/\1/p")
      echo "run mesa $mode $us"
      for lib in "$@"; do
        us=$(GLPT_MODE=raster LD_PRELOAD="$lib" "$program" --mode "$mode" --iterations "$iterations" |
          sed -n "s/.*us_per_iteration=\([0-9.]*\).*/\1/p")
        echo "run $lib $mode $us"
      done
    done
  done' bench "$program" "$rounds" "$iterations" "${libgls[@]}" | tee /dev/stderr |
  /usr/bin/python3 -c '
import statistics, sys
runs = {}
for line in sys.stdin:
    parts = line.split()
    if len(parts) == 4 and parts[0] == "run" and parts[3]:
        runs.setdefault((parts[1], parts[2]), []).append(float(parts[3]))
libs = []
for lib, _ in runs:
    if lib not in libs: libs.append(lib)
print("| library | draw + glReadPixels (us) | glReadPixels alone | draw + glFinish |")
print("|---|---|---|---|")
for lib in libs:
    cells = []
    for mode in ("draw_read", "read", "draw_finish"):
        median = statistics.median(runs[(lib, mode)])
        mesa = statistics.median(runs[("mesa", mode)])
        cells.append(f"{median:.1f}" + ("" if lib == "mesa" else f" ({median / mesa:.1f}x Mesa)"))
    print(f"| {lib} | " + " | ".join(cells) + " |")
'
