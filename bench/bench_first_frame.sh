#!/usr/bin/env bash
# bench_first_frame.sh [--programs "glxgears gears pipes atlantis"] [--mode raster|path]
#                      [--seconds S]
#
# What the first frame costs on a cold and on a warm pipeline cache (docs/performance.md, "The
# first frame"): runs each program under glpt (LD_PRELOAD, GLPT_STATS_FILE) in a private Xvfb
# for S seconds (default 6), twice: first with an empty glpt pipeline cache (GLPT_CACHE_DIR) and
# an empty Mesa shader cache (MESA_SHADER_CACHE_DIR: lavapipe compiles fragment-shader variants
# into it at draw time), then again with both caches as the first run left them. Prints frame 0's
# total_ms (recording to presented), raster_ms, wall_ms (how long the frame's end, the swap, held
# the program) and the pipelines it created, per program and cache state. Programs: glxgears or the name of an
# xscreensaver hack in /usr/libexec/xscreensaver. Not a test.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
libgl=${GLPT_BUILD_DIR:-$repo/build}/gl_shim/libGL.so.1
programs="glxgears gears pipes atlantis"
mode=raster
seconds=6
while [ $# -gt 0 ]; do
  case $1 in
    --programs) programs=$2; shift 2 ;;
    --mode) mode=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    -h|--help) sed -n '2,12p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench_first_frame: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ -f "$libgl" ] || { echo "bench_first_frame: build first ($libgl)" >&2; exit 2; }
work=$(mktemp -d /tmp/glpt-first-frame.XXXXXX)
trap 'rm -rf "$work"' EXIT
echo "command: $0 --programs \"$programs\" --mode $mode --seconds $seconds"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
printf '%-12s %-5s %9s %10s %9s %10s\n' program cache total_ms raster_ms wall_ms pipelines
for program in $programs; do
  if [ "$program" = glxgears ]; then
    command=(glxgears)
  else
    command=("/usr/libexec/xscreensaver/$program" -window)
  fi
  command -v "${command[0]}" >/dev/null ||
    { echo "bench_first_frame: no ${command[0]}, skipped" >&2; continue; }
  rm -rf "$work/glpt-cache" "$work/mesa-cache"
  mkdir -p "$work/glpt-cache" "$work/mesa-cache"
  for cache in cold warm; do
    stats=$work/$program.$cache.stats
    rm -f "$stats"
    # The variables reach the program only (env inside with_xvfb.sh), not Xvfb.
    timeout -s INT "$seconds" "$repo/tests/e2e/with_xvfb.sh" env GLPT_MODE="$mode" \
      GLPT_STATS_FILE="$stats" GLPT_CACHE_DIR="$work/glpt-cache" \
      MESA_SHADER_CACHE_DIR="$work/mesa-cache" LD_PRELOAD="$libgl" "${command[@]}" \
      >/dev/null 2>&1 || true
    line=$(grep -m1 ' frame=0 ' "$stats" 2>/dev/null || true)
    if [ -z "$line" ]; then
      printf '%-12s %-5s %9s\n' "$program" "$cache" "no frame"
      continue
    fi
    field() { sed -n "s/.* $1=\([^ ]*\).*/\1/p" <<<"$line"; }
    printf '%-12s %-5s %9s %10s %9s %10s\n' "$program" "$cache" "$(field total_ms)" \
      "$(field raster_ms)" "$(field wall_ms)" "$(field pipelines_created)"
  done
done
