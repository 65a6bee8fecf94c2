#!/usr/bin/env bash
# bench_light_transport.sh [--frames F] [--size WxH] [--rounds N]
#
# What path-traced mode's light transport costs (docs/light-transport.md, "Cost"): for glxgears
# and bench/lit_scene (a textured, lit scene of ~50k triangles), at each quality preset, the
# median ms per frame (GLPT_STATS' total_ms, frames after the second), the trace pass's ms and
# the rays per pixel per frame; then lit_scene with 100 GL lights against the same scene with
# one light at equal samples. Runs in a private Xvfb; settings alternate round by round so both
# sides of a ratio see the same machine load. Prints one line per measurement, the ratios and
# the command. Accumulation is off (GLPT_ACCUMULATE=0): every frame pays for its samples.
#
#   --frames F    frames per run (default 12; the first two are not counted)
#   --size WxH    lit_scene's window (default 320x240; glxgears uses its own 300x300)
#   --rounds N    runs per measurement, alternating (default 2)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${GLPT_BUILD_DIR:-$repo/build}
frames=12
size=320x240
rounds=2
while [ $# -gt 0 ]; do
  case $1 in
    --frames) frames=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    -h|--help) sed -n '2,15p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench_light_transport: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
libgl=$build/gl_shim/libGL.so.1
lit_scene=$build/bench/lit_scene
[ -f "$libgl" ] && [ -x "$lit_scene" ] ||
  { echo "bench_light_transport: build first (scripts/build.sh)" >&2; exit 2; }

display=:$((200 + RANDOM % 100))
Xvfb "$display" -screen 0 1024x768x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
sleep 1

# Presets: what a user picks between, cheapest first.
declare -A preset=(
  [gl-parity]="GLPT_SHADOWS=0 GLPT_BOUNCES=0 GLPT_AO=0"
  [direct]="GLPT_BOUNCES=0"
  [default]=""
  [bounces4]="GLPT_BOUNCES=4"
  [spp4]="GLPT_SPP=4"
)
order="gl-parity direct default bounces4 spp4"

# run NAME SETTINGS PROGRAM ARGS...: prints "median_total_ms median_trace_ms rays_per_pixel".
run() {
  local settings=$1
  shift
  local log
  log=$(mktemp)
  env DISPLAY="$display" LD_PRELOAD="$libgl" GLPT_STATS=1 GLPT_ACCUMULATE=0 GLPT_QUIET=1 \
    $settings "$@" 2>"$log" >/dev/null || true
  awk -v skip=2 '
    /^glpt: frame=/ {
      for (i = 1; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
      if (v["trace_ms"] + 0 == 0) next
      if (seen++ < skip) next
      split(v["size"], wh, "x")
      total[n] = v["total_ms"]; trace[n] = v["trace_ms"]; rays += v["rays"] / (wh[1] * wh[2]); ++n
    }
    function median(a, n,   i, j, t) {
      for (i = 0; i < n; ++i) for (j = i + 1; j < n; ++j) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
      return n ? (n % 2 ? a[int(n / 2)] : (a[n / 2 - 1] + a[n / 2]) / 2) : 0
    }
    END { printf "%.1f %.1f %.2f\n", median(total, n), median(trace, n), n ? rays / n : 0 }' "$log"
  rm -f "$log"
}

median_of() { tr ' ' '\n' | sort -g | awk '{a[NR]=$1} END {print NR % 2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "command: $0 --frames $frames --size $size --rounds $rounds"
printf '%-10s %-10s %12s %12s %10s\n' scene preset frame_ms trace_ms rays/px
for scene in glxgears lit_scene; do
  declare -A totals=() traces=() rays=()
  for ((round = 0; round < rounds; ++round)); do
    for name in $order; do
      if [ "$scene" = glxgears ]; then
        # glxgears runs until stopped: give it time for about `frames` path-traced frames.
        result=$(run "${preset[$name]}" timeout -s INT 25 /usr/bin/glxgears)
      else
        result=$(run "${preset[$name]}" "$lit_scene" --frames "$frames" --size "$size")
      fi
      read -r t tr r <<<"$result"
      totals[$name]+="$t "
      traces[$name]+="$tr "
      rays[$name]=$r
    done
  done
  for name in $order; do
    printf '%-10s %-10s %12s %12s %10s\n' "$scene" "$name" \
      "$(median_of <<<"${totals[$name]% }")" "$(median_of <<<"${traces[$name]% }")" "${rays[$name]}"
  done
done

# Many lights: 100 against 1, the same scene and samples, alternating.
one="" hundred=""
for ((round = 0; round < rounds; ++round)); do
  read -r t _ _ <<<"$(run "" "$lit_scene" --frames "$frames" --size "$size" --lights 1)"
  one+="$t "
  read -r t _ _ <<<"$(run "" "$lit_scene" --frames "$frames" --size "$size" --lights 100)"
  hundred+="$t "
done
m1=$(median_of <<<"${one% }")
m100=$(median_of <<<"${hundred% }")
echo "lit_scene 1 light: $m1 ms/frame; 100 lights: $m100 ms/frame; ratio $(awk -v a="$m100" -v b="$m1" 'BEGIN { printf "%.2f", a / b }')"
