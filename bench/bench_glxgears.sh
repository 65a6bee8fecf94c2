#!/usr/bin/env bash
# bench_glxgears.sh [--libgl PATH] [--size WxH] [--frames N] [--warmup K] [--no-png]
#
# Runs the unmodified /usr/bin/glxgears under glpt (LD_PRELOAD) in a private Xvfb with a virtual
# clock (shared/tools/detclock.c, preloaded before libGL, so the gears animate identically on
# every run), collects the per-frame "glpt: key=value ..." lines that GLPT_STATS=1 prints, skips
# the first K frames as warm-up and prints the median of every *_ms field, the median wall-clock
# time per frame (measured here, from the arrival of consecutive stats lines) and Mrays/s, plus
# the command lines that reproduce the run.
#
#   --libgl PATH  glpt's libGL.so.1 (default: $GLPT_LIBGL, else <repo>/build/gl_shim/libGL.so.1)
#   --size WxH    glxgears window size (default 300x300)
#   --frames N    frames measured (default 20)
#   --warmup K    frames skipped first (default 3)
#   --no-png      do not set GLPT_OUTPUT (by default frames go to PNGs in a temporary directory,
#                 as in the end-to-end tests, so present_ms includes the PNG write)
# Environment: GLXGEARS (default /usr/bin/glxgears), DETCLOCK_SRC (default
# <repo>/../shared/tools/detclock.c), DETCLOCK_STEP_US (passed to detclock), BENCH_LINE_TIMEOUT_S
# (default 300: the longest wait for one frame's stats line).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
libgl=${GLPT_LIBGL:-$repo/build/gl_shim/libGL.so.1}
size=300x300
frames=20
warmup=3
png=1
usage() { sed -n '2,19p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case $1 in
    --libgl) libgl=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --warmup) warmup=$2; shift 2 ;;
    --no-png) png=0; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "bench_glxgears: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
[[ $size =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || { echo "bench_glxgears: bad --size '$size'" >&2; exit 2; }
[[ $frames =~ ^[1-9][0-9]*$ ]] || { echo "bench_glxgears: bad --frames '$frames'" >&2; exit 2; }
[[ $warmup =~ ^[1-9][0-9]*$ ]] ||
  { echo "bench_glxgears: bad --warmup '$warmup' (>= 1: the first measured frame's wall time needs a predecessor)" >&2; exit 2; }
libgl=$(realpath "$libgl" 2>/dev/null || echo "$libgl")
[ -f "$libgl" ] || { echo "bench_glxgears: libGL not found: $libgl (build it, or pass --libgl)" >&2; exit 2; }
glxgears=${GLXGEARS:-/usr/bin/glxgears}
detclock_src=${DETCLOCK_SRC:-$repo/../shared/tools/detclock.c}
[ -f "$detclock_src" ] || { echo "bench_glxgears: detclock.c not found: $detclock_src" >&2; exit 2; }
line_timeout=${BENCH_LINE_TIMEOUT_S:-300}

if [ -z "${GLPT_BENCH_UNDER_XVFB:-}" ]; then
  args=(--libgl "$libgl" --size "$size" --frames "$frames" --warmup "$warmup")
  [ "$png" = 1 ] || args+=(--no-png)
  GLPT_BENCH_UNDER_XVFB=1 exec "$repo/tests/e2e/with_xvfb.sh" "$0" "${args[@]}"
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/glpt-bench.XXXXXX")
pid=""
# shellcheck disable=SC2317  # called from the EXIT trap
cleanup() {
  exec 3<&- 2>/dev/null || true
  if [ -n "$pid" ]; then
    kill "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  fi
  rm -rf "$tmp"
}
trap cleanup EXIT

gcc -shared -fPIC -O2 -o "$tmp/detclock.so" "$detclock_src"
envs=(LD_PRELOAD="$tmp/detclock.so:$libgl" GLPT_STATS=1)
if [ "$png" = 1 ]; then
  mkdir "$tmp/frames"
  envs+=(GLPT_OUTPUT="$tmp/frames")
fi
[ -z "${DETCLOCK_STEP_US:-}" ] || envs+=(DETCLOCK_STEP_US="$DETCLOCK_STEP_US")
total=$((warmup + frames))

mkfifo "$tmp/stderr.fifo"
env "${envs[@]}" "$glxgears" -geometry "$size" >"$tmp/stdout.log" 2>"$tmp/stderr.fifo" &
pid=$!
exec 3<"$tmp/stderr.fifo"
n=0
: >"$tmp/stats.txt"
: >"$tmp/stderr.log"
while [ "$n" -lt "$total" ]; do
  rc=0
  IFS= read -r -t "$line_timeout" line <&3 || rc=$?
  if [ "$rc" != 0 ]; then
    why="glxgears exited"
    [ "$rc" -le 128 ] || why="no output from glxgears for ${line_timeout}s"
    echo "bench_glxgears: $why after $n of $total stats lines; stderr tail:" >&2
    tail -n 30 "$tmp/stderr.log" >&2 || true
    exit 1
  fi
  now=$EPOCHREALTIME  # bash's own clock: not affected by detclock, which only glxgears loads
  printf '%s\n' "$line" >>"$tmp/stderr.log"
  if [[ $line == "glpt: "*" frame="* || $line == "glpt: frame="* ]]; then
    printf '%s %s\n' "$now" "$line" >>"$tmp/stats.txt"
    n=$((n + 1))
  fi
done
kill "$pid" 2>/dev/null || true
exec 3<&-
wait "$pid" 2>/dev/null || true
pid=""

bench_cmd="$here/bench_glxgears.sh --libgl $libgl --size $size --frames $frames --warmup $warmup$([ "$png" = 1 ] || echo ' --no-png')"
run_cmd="env $(printf '%q ' "${envs[@]}" | sed "s|$tmp|\$TMP|g")$glxgears -geometry $size   # under Xvfb, detclock.so = gcc -shared -fPIC -O2 $detclock_src"
python3 - "$tmp/stats.txt" "$warmup" "$size" "$libgl" "$bench_cmd" "$run_cmd" <<'PY'
import statistics
import sys

path, warmup, size, libgl, bench_cmd, run_cmd = sys.argv[1:]
warmup = int(warmup)
rows = []  # (arrival time in s, {key: value})
for line in open(path):
    stamp, rest = line.split(" ", 1)
    fields = {}
    for token in rest.split()[1:]:  # drop "glpt:"
        if "=" in token:
            k, v = token.split("=", 1)
            fields[k] = v
    rows.append((float(stamp), fields))

measured = rows[warmup:]
def median_of(key):
    vals = []
    for _, f in measured:
        try:
            vals.append(float(f[key]))
        except (KeyError, ValueError):
            pass
    return (statistics.median(vals), len(vals)) if vals else (None, 0)

wall_ms = [(rows[i][0] - rows[i - 1][0]) * 1000.0 for i in range(warmup, len(rows))]
wall = statistics.median(wall_ms)
keys = []
for _, f in measured:
    for k in f:
        if k not in keys:
            keys.append(k)

print(f"bench_glxgears: glxgears {size}, {len(measured)} frames measured after {warmup} warm-up")
print(f"  libGL: {libgl}")
print(f"  frame sizes seen: {sorted({f.get('size', '?') for _, f in measured})}")
for k in keys:
    if k.endswith("_ms"):
        m, n = median_of(k)
        print(f"  {k:<18} median {m:10.3f} ms  ({n} frames)")
print(f"  {'wall ms/frame':<18} median {wall:10.3f} ms  (real clock, between stats lines)")
rays, _ = median_of("rays")
shim_mrays, _ = median_of("mrays_per_s")
if shim_mrays is not None:
    print(f"  {'mrays_per_s':<18} median {shim_mrays:10.3f}     (as glpt reports it)")
if rays is not None and wall > 0:
    print(f"  {'Mrays/s (wall)':<18} median {rays / (wall * 1000.0):10.3f}     (median rays / wall ms per frame)")
for k in ("triangles", "rays", "spp", "blas_builds", "blas_reused"):
    m, n = median_of(k)
    if m is not None:
        print(f"  {k:<18} median {m:10.0f}")
# glpt's timers must read the real clock. detclock interposes clock_gettime for the whole
# process and advances 1 ms (DETCLOCK_STEP_US) per call, so virtual timings are whole
# milliseconds, far from the wall time per frame.
ms_values = [float(f[k]) for _, f in measured for k in f if k.endswith("_ms")
             and f[k].replace(".", "", 1).isdigit() and float(f[k]) > 0]
all_whole = len(ms_values) >= 10 and all(v == int(v) for v in ms_values)
total, _ = median_of("total_ms")
if all_whole or (total is not None and wall > 0 and not (0.5 <= total / wall <= 1.5)):
    print(f"  WARNING: glpt's total_ms ({total:.2f}) is far from the real time per frame ({wall:.2f}): "
          "its timers may read detclock's virtual clock (clock_gettime is interposed for the "
          "whole process). Time with the real clock, e.g. dlsym(RTLD_NEXT, \"clock_gettime\") "
          "from libGL, which comes after detclock.so in LD_PRELOAD.")
print("reproduce:")
print(f"  {bench_cmd}")
print(f"  # the run itself: {run_cmd}")
PY
