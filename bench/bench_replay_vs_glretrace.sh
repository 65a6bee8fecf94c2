#!/usr/bin/env bash
# bench_replay_vs_glretrace.sh [--frames N] [--rounds R] [--trace FILE]
#
# Replay speed: the same apitrace trace replayed into glpt's raster mode by glpt-replay
# (in-process, headless) and by apitrace's glretrace with glpt's libGL.so.1 preloaded (in a
# private Xvfb, --benchmark so glretrace skips its own error checks), alternating R times. Both
# drive the same front end and renderer; the difference is parsing and dispatch. Without
# --trace it records bench/gl_throughput in immediate mode with apitrace: N frames (default 10)
# of 20000 triangles, 180000 glColor/glNormal/glVertex calls each: call-heavy, as parsing is.
# Prints each run's wall time, the medians and their ratio, and the command to reproduce.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${GLPT_BUILD_DIR:-$repo/build}
frames=10
rounds=3
trace=""
while [ $# -gt 0 ]; do
  case $1 in
    --frames) frames=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --trace) trace=$(realpath "$2"); shift 2 ;;
    -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench_replay_vs_glretrace: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
if [ -z "${GLPT_BENCH_UNDER_XVFB:-}" ]; then
  GLPT_BENCH_UNDER_XVFB=1 exec "$repo/tests/e2e/with_xvfb.sh" "$0" --frames "$frames" \
    --rounds "$rounds" ${trace:+--trace "$trace"}
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if [ -z "$trace" ]; then
  trace=$tmp/immediate.trace
  apitrace trace --api gl -o "$trace" "$build/bench/gl_throughput" --mode immediate \
    --triangles 20000 --frames "$frames" >/dev/null 2>&1
fi
echo "trace: $trace ($(stat -c %s "$trace") bytes)"
now() { date +%s.%N; }
times_replay=() times_glretrace=()
for ((r = 1; r <= rounds; ++r)); do
  t0=$(now)
  GLPT_QUIET=1 "$build/replay/glpt-replay" --quiet --mode raster "$trace" >/dev/null 2>&1
  t1=$(now)
  LD_PRELOAD=$build/gl_shim/libGL.so.1 GLPT_MODE=raster GLPT_QUIET=1 glretrace --benchmark \
    "$trace" >/dev/null 2>&1
  t2=$(now)
  a=$(echo "$t1 - $t0" | bc) b=$(echo "$t2 - $t1" | bc)
  times_replay+=("$a") times_glretrace+=("$b")
  echo "round $r: glpt-replay ${a} s, glretrace+glpt ${b} s"
done
median() { printf '%s\n' "$@" | sort -g | awk '{v[NR]=$1} END {print v[int((NR+1)/2)]}'; }
mr=$(median "${times_replay[@]}") mg=$(median "${times_glretrace[@]}")
echo "median: glpt-replay $mr s, glretrace through glpt $mg s, ratio glretrace/glpt-replay $(echo "scale=2; $mg / $mr" | bc)"
echo "reproduce: bench/bench_replay_vs_glretrace.sh --frames $frames --rounds $rounds"
