#!/usr/bin/env bash
# bench_frame_cpu.sh [--size N] [--seconds S] [--rounds R] NAME=LIBGL...
#
# glxgears' scene (bench/gears_cpu) drawn by each NAME=LIBGL in turn, round after round in one
# private Xvfb: LIBGL is a glpt libGL.so.1 (preloaded, raster mode) or "mesa" (the system
# libGL, llvmpipe). Per run: the frame rate and CPU microseconds per frame, of the program's
# thread and of the whole process (not the X server's). Then, per name, the medians and the
# median of the per-round ratios to the first name: on a machine whose speed drifts, runs next
# to each other are the fair comparison. Compare two glpt builds (copies of libGL.so.1) or glpt
# with Mesa, e.g.
#
#   bench/bench_frame_cpu.sh --rounds 8 mesa=mesa before=/tmp/before.so after=build/gl_shim/libGL.so.1
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
size=300
seconds=3
rounds=8
usage() { sed -n '2,14p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
args=()
while [ $# -gt 0 ]; do
  case $1 in
    --size) size=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    *=*) args+=("$1"); shift ;;
    *) echo "bench_frame_cpu: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
[ ${#args[@]} -ge 1 ] || { usage >&2; exit 2; }
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "bench_frame_cpu: bad --rounds '$rounds'" >&2; exit 2; }
program=${GEARS_CPU:-$repo/build/bench/gears_cpu}
[ -x "$program" ] || { echo "bench_frame_cpu: $program not built (scripts/build.sh)" >&2; exit 2; }
for a in "${args[@]}"; do
  lib=${a#*=}
  [ "$lib" = mesa ] || [ -f "$lib" ] || { echo "bench_frame_cpu: no such libGL: $lib" >&2; exit 2; }
done

if [ -z "${GLPT_BENCH_UNDER_XVFB:-}" ]; then
  GLPT_BENCH_UNDER_XVFB=1 exec "$repo/tests/e2e/with_xvfb.sh" "$0" --size "$size" \
    --seconds "$seconds" --rounds "$rounds" "${args[@]}"
fi

results=$(mktemp)
trap 'rm -f "$results"' EXIT
for round in $(seq 1 "$rounds"); do
  for a in "${args[@]}"; do
    name=${a%%=*}
    lib=${a#*=}
    if [ "$lib" = mesa ]; then
      line=$("$program" --seconds "$seconds" --size "$size")
    else
      line=$(env LD_PRELOAD="$(realpath "$lib")" GLPT_MODE=raster GLPT_QUIET=1 \
        "$program" --seconds "$seconds" --size "$size")
    fi
    echo "round $round $name $line" | tee -a "$results" >&2
  done
done
/usr/bin/env python3 - "$results" "${args[@]%%=*}" <<'PY'
import re, statistics, sys
rows, names = open(sys.argv[1]).read().split("\n"), sys.argv[2:]
runs = {}
for row in rows:
    m = re.match(r"round (\d+) (\S+) .*fps=([\d.]+) thread_us=([\d.]+) process_us=([\d.]+)", row)
    if m:
        runs.setdefault(m.group(2), {})[int(m.group(1))] = [float(m.group(i)) for i in (3, 4, 5)]
first = runs[names[0]]
for name in names:
    mine = runs[name]
    cols = []
    for k, label in enumerate(("fps", "thread_us", "process_us")):
        ratios = [mine[r][k] / first[r][k] for r in mine if r in first]
        cols.append("%s %.1f (x%.3f)" % (label, statistics.median(v[k] for v in mine.values()),
                                          statistics.median(ratios)))
    print("%-10s %s" % (name, "   ".join(cols)))
PY
echo "reproduce: bench/bench_frame_cpu.sh --size $size --seconds $seconds --rounds $rounds ${args[*]}"
