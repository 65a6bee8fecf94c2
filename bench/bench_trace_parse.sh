#!/usr/bin/env bash
# bench_trace_parse.sh [TRACE] [--seconds S] [--repeat N]
#
# How fast glpt's apitrace reader (replay/trace) parses a trace: calls/s and MB/s (of the file as
# stored), best of N runs of build/bench/glpt_trace_bench, and, as a rough reference, the
# time `apitrace dump` takes over the same file (apitrace parses and also formats every call as
# text, so it is an upper bound on apitrace's own parse time, not a like-for-like figure).
#
# Without TRACE, records one: xscreensaver's moebius hack (immediate mode, ~0.4 M calls/s of
# tracing) under `apitrace trace --api egl` for S seconds (default 4) in a private Xvfb.
#
#   --seconds S  recording length when no TRACE is given (default 4)
#   --repeat N   runs of each reader; the best is reported (default 3)
# Environment: GLPT_BUILD_DIR (default <repo>/build; the script builds glpt_trace_bench there),
# XSCREENSAVER_HACK (default /usr/libexec/xscreensaver/moebius).
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${GLPT_BUILD_DIR:-$repo/build}
hack=${XSCREENSAVER_HACK:-/usr/libexec/xscreensaver/moebius}
trace=""
given_trace=""
seconds=4
repeat=3
usage() { sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case $1 in
    --seconds) seconds=$2; shift 2 ;;
    --repeat) repeat=$2; shift 2 ;;
    -h|--help) usage; exit 0 ;;
    -*) echo "bench_trace_parse: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
    *) trace=$1; given_trace=$1; shift ;;
  esac
done

cmake --build "$build" --target glpt_trace_bench >/dev/null
bench=$build/bench/glpt_trace_bench

tmp=$(mktemp -d)
xvfb_pid=""
cleanup() {
  [ -n "$xvfb_pid" ] && kill "$xvfb_pid" 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT

if [ -z "$trace" ]; then
  display=""
  for n in $(seq 90 140); do
    if [ ! -e "/tmp/.X11-unix/X$n" ] && [ ! -e "/tmp/.X$n-lock" ]; then display=":$n"; break; fi
  done
  [ -n "$display" ] || { echo "bench_trace_parse: no free X display" >&2; exit 1; }
  Xvfb "$display" -screen 0 640x480x24 >/dev/null 2>&1 &
  xvfb_pid=$!
  sleep 1
  trace=$tmp/$(basename "$hack").trace
  echo "recording $(basename "$hack") for ${seconds} s into $trace"
  DISPLAY=$display timeout -s INT "$seconds" apitrace trace --api egl -o "$trace" "$hack" -delay 0 \
    >/dev/null 2>&1 || true
fi
[ -s "$trace" ] || { echo "bench_trace_parse: no trace at $trace" >&2; exit 1; }

echo "glpt reader:   $("$bench" "$trace" --repeat "$repeat")"
best=""
for _ in $(seq "$repeat"); do
  start=$(date +%s.%N)
  apitrace dump --color=never "$trace" >/dev/null 2>&1
  end=$(date +%s.%N)
  t=$(echo "$end - $start" | bc -l)
  if [ -z "$best" ] || [ "$(echo "$t < $best" | bc -l)" = 1 ]; then best=$t; fi
done
printf 'apitrace dump: best of %d: %.3f s (parse + text formatting, to /dev/null)\n' "$repeat" "$best"
if [ -n "$given_trace" ]; then
  echo "reproduce: bench/bench_trace_parse.sh $given_trace --repeat $repeat"
else
  echo "reproduce: bench/bench_trace_parse.sh --seconds $seconds --repeat $repeat"
fi
