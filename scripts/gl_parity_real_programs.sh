#!/usr/bin/env bash
# gl_parity_real_programs.sh [--hacks "sproingies rubik menger"] [--seconds S] [--frame F]
#                             [--work DIR]
#
# GL parity of path-traced mode on real lit GL 1.x programs (docs/light-transport.md): records
# each xscreensaver hack (which draw through EGL) with apitrace on real Mesa in a private Xvfb (S seconds), then replays
# frame F of the trace through Mesa (OSMesa, the reference), through glpt's path tracer with
# --shadows 0 --bounces 0 --ao 0 (GL's lighting equation per pixel) and with the defaults, and
# prints FLIP and PSNR of each against Mesa (`glpt diff`). The traces and PNGs stay in DIR
# (default: a temporary directory, printed).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${GLPT_BUILD_DIR:-$root/build}
hacks="sproingies rubik menger"
seconds=4
frame=40
work=""
while [ $# -gt 0 ]; do
  case $1 in
    --hacks) hacks=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    --frame) frame=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    -h|--help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "gl_parity_real_programs: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ -n "$work" ] || work=$(mktemp -d /tmp/glpt-parity.XXXXXX)
mkdir -p "$work"
replay=$build/replay/glpt-replay
glpt=$build/replay/glpt
[ -x "$replay" ] || { echo "gl_parity_real_programs: build first (scripts/build.sh)" >&2; exit 2; }

display=:$((90 + RANDOM % 100))
Xvfb "$display" -screen 0 640x480x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
sleep 1
echo "command: $0 --hacks \"$hacks\" --seconds $seconds --frame $frame --work $work"
printf '%-12s %-9s %10s %9s\n' program settings flip_mean psnr_db
for hack in $hacks; do
  program=/usr/libexec/xscreensaver/$hack
  [ -x "$program" ] || { echo "$hack: not installed (xscreensaver-gl)"; continue; }
  trace=$work/$hack.trace
  if [ ! -f "$trace" ]; then
    DISPLAY=$display timeout -s INT "$seconds" apitrace trace --api egl -o "$trace" "$program" \
      >/dev/null 2>&1 || true
  fi
  "$replay" --quiet --backend mesa --frames "$frame" --out "$work/$hack.mesa" "$trace"
  "$replay" --quiet --mode path --shadows 0 --bounces 0 --ao 0 --frames "$frame" \
    --out "$work/$hack.parity" "$trace"
  "$replay" --quiet --mode path --spp 16 --frames "$frame" --out "$work/$hack.path" "$trace"
  for variant in parity path; do
    line=$("$glpt" diff --json --threshold 1 "$work/$hack.mesa" "$work/$hack.$variant" | head -n 1)
    flip=$(sed -n 's/.*"flip_mean": *\([0-9.e+-]*\).*/\1/p' <<<"$line")
    psnr=$(sed -n 's/.*"psnr": *\([0-9.e+-]*\|null\).*/\1/p' <<<"$line")
    settings=$([ "$variant" = parity ] && echo "parity" || echo "default")
    printf '%-12s %-9s %10s %9s\n' "$hack" "$settings" "$flip" "$psnr"
  done
done
echo "images: $work"
