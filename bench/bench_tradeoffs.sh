#!/usr/bin/env bash
# bench_tradeoffs.sh [--work DIR] [--full] [--reference N] [--scenes "A B ..."]
#                    [--game TRACE --game-frames LIST] [--game-full] [--resume] [--report FILE]
#
# The speed/accuracy trade of every quality knob, measured (docs/BENCHMARKS.md): `glpt tune` on
# four recorded scenes, then bench/tradeoffs_report.py writes the tables, the Pareto fronts and
# the plots into docs/. Not part of CI (tens of minutes on two cores).
#
# Scenes (each recorded once with apitrace on real Mesa under a private Xvfb, into DIR/traces):
#   glxgears   /usr/bin/glxgears 300x300, its clock made deterministic (bench/detclock.c)
#   lit_scene  bench/lit_scene: 50,178 textured lit triangles, 320x240, the camera panning
#              0.5 degrees per frame over a still world
#   lights100  the same scene lit by 100 GL lights
#   game       a recorded real game (--game TRACE [--game-frames LIST]), e.g. bzflag recorded by
#              scripts/record_real_games.sh (its first frames: a menu over the 3-D world)
#
#   --work DIR       traces and tune outputs (default /tmp/glpt-tradeoffs)
#   --full           glpt tune's full grid (49 settings; default: the reduced one, 15)
#   --game-full      the full grid for the game too (at 640x480 its 8-sample settings take
#                    minutes each: by default the game gets the reduced grid)
#   --reference N    samples per pixel of the references (default 256)
#   --scenes LIST    which scenes (default "glxgears lit_scene lights100 game")
#   --resume         keep the results of scenes that have a tune.csv in DIR from an earlier run
#   --report FILE    the Markdown written (default docs/BENCHMARKS.md)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${GLPT_BUILD_DIR:-$repo/build}
work=/tmp/glpt-tradeoffs
full=""
reference=256
scenes="glxgears lit_scene lights100 game"
game=""
game_frames=""
game_full=""
resume=""
report=$repo/docs/BENCHMARKS.md
while [ $# -gt 0 ]; do
  case $1 in
    --work) work=$2; shift 2 ;;
    --full) full=--full; shift ;;
    --reference) reference=$2; shift 2 ;;
    --scenes) scenes=$2; shift 2 ;;
    --game) game=$2; shift 2 ;;
    --game-frames) game_frames=$2; shift 2 ;;
    --game-full) game_full=--full; shift ;;
    --resume) resume=1; shift ;;
    --report) report=$2; shift 2 ;;
    -h|--help) sed -n '2,24p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench_tradeoffs: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
glpt=$build/replay/glpt
lit_scene=$build/bench/lit_scene
[ -x "$glpt" ] && [ -x "$lit_scene" ] || { echo "bench_tradeoffs: build first (scripts/build.sh)" >&2; exit 2; }
command -v apitrace >/dev/null || { echo "bench_tradeoffs: needs apitrace (Debian package)" >&2; exit 2; }
mkdir -p "$work/traces"
command_line="$0 --work $work ${full:+--full }${game_full:+--game-full }--reference $reference --scenes \"$scenes\"${game:+ --game $game}${game_frames:+ --game-frames $game_frames}"

display=:$((200 + RANDOM % 100))
Xvfb "$display" -screen 0 1024x768x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
sleep 1
export DISPLAY=$display

# record NAME COMMAND...: DIR/traces/NAME.trace, recorded on real Mesa, once.
record() {
  local name=$1
  shift
  local trace=$work/traces/$name.trace
  [ -s "$trace" ] && return 0
  echo "recording $name: $*"
  apitrace trace --api gl -o "$trace" "$@" >"$work/traces/$name.log" 2>&1 || true
  [ -s "$trace" ] || { echo "bench_tradeoffs: recording $name failed (see $work/traces/$name.log)" >&2; exit 1; }
}

for scene in $scenes; do
  case $scene in
    glxgears)
      # glxgears runs until stopped: 2 s on llvmpipe are hundreds of frames (the tune uses 32).
      # Its clock is detclock's, preloaded with apitrace's GLX wrapper (apitrace's launcher
      # would replace LD_PRELOAD).
      trace=$work/traces/glxgears.trace
      if [ ! -s "$trace" ]; then
        gcc -shared -fPIC -O2 -o "$work/detclock.so" "$here/detclock.c"
        wrapper=$(ls /usr/lib/*/apitrace/wrappers/glxtrace.so 2>/dev/null | head -1)
        [ -n "$wrapper" ] || { echo "bench_tradeoffs: apitrace's glxtrace.so not found" >&2; exit 2; }
        echo "recording glxgears (detclock, $wrapper)"
        LD_PRELOAD="$work/detclock.so:$wrapper" TRACE_FILE="$trace" DETCLOCK_STEP_US=2000 \
          timeout -s INT 2 /usr/bin/glxgears -geometry 300x300 >"$work/traces/glxgears.log" 2>&1 || true
        [ -s "$trace" ] || { echo "bench_tradeoffs: recording glxgears failed" >&2; exit 1; }
      fi
      ;;
    lit_scene) record lit_scene "$lit_scene" --frames 40 --size 320x240 --pan 0.5 ;;
    lights100) record lights100 "$lit_scene" --frames 40 --size 320x240 --pan 0.5 --lights 100 ;;
    game)
      if [ -z "$game" ]; then
        for candidate in "$work/traces/game.trace" /tmp/games/bzflag.trace; do
          [ -s "$candidate" ] && { game=$candidate; break; }
        done
      fi
      [ -n "$game" ] || { echo "bench_tradeoffs: no game trace: give --game TRACE --game-frames LIST" >&2; exit 2; }
      ;;
    *) echo "bench_tradeoffs: unknown scene '$scene'" >&2; exit 2 ;;
  esac
done

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), Mesa $(dpkg-query -W -f '${Version}' mesa-vulkan-drivers 2>/dev/null)"
echo "command: $command_line"
csvs=()
for scene in $scenes; do
  trace=$work/traces/$scene.trace
  frames=()
  grid=$full
  if [ "$scene" = game ]; then
    trace=$game
    grid=$game_full
    [ -n "$game_frames" ] && frames=(--frames "$game_frames")
  fi
  if [ -n "$resume" ] && [ -s "$work/$scene/tune.csv" ]; then
    echo "== $scene: kept from an earlier run ($work/$scene/tune.csv)"
    csvs+=("$work/$scene/tune.csv")
    continue
  fi
  echo "== $scene ($trace)"
  status=0
  "$glpt" tune "$trace" $grid --reference "$reference" --scene "$scene" --out "$work/$scene" \
    "${frames[@]}" | tee "$work/$scene.txt" || status=$?
  [ "$status" -eq 0 ] || echo "bench_tradeoffs: glpt tune on $scene exited with $status" >&2
  [ -f "$work/$scene/tune.csv" ] && csvs+=("$work/$scene/tune.csv")
done

/usr/bin/python3 "$here/tradeoffs_report.py" --report "$report" --command "$command_line" \
  --images "$(dirname "$report")/benchmarks" "${csvs[@]}"
echo "report: $report"
