#!/usr/bin/env bash
# menu_parity_real_games.sh [--games "torcs bzflag"] [--every N] [--work DIR]
#
# What path tracing adds to the menu screens of real GL 1.x games (docs/light-transport.md,
# "Unlit draws"): records each game's menus with apitrace on real Mesa in a private Xvfb,
# walking through them with xdotool (torcs redraws on input), replays every Nth frame through
# glpt's raster mode (= Mesa, checked by the conformance suite) and path-traced mode with the
# defaults, and prints per game how many frames are identical and the lowest PSNR
# (`glpt diff`). Needs torcs / bzflag-client, apitrace, Xvfb and xdotool (Debian packages).
# Traces and PNGs stay in DIR (default: a temporary directory, printed).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${GLPT_BUILD_DIR:-$root/build}
games="torcs bzflag"
every=1
work=""
while [ $# -gt 0 ]; do
  case $1 in
    --games) games=$2; shift 2 ;;
    --every) every=$2; shift 2 ;;
    --work) work=$2; shift 2 ;;
    -h|--help) sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "menu_parity_real_games: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ -n "$work" ] || work=$(mktemp -d /tmp/glpt-menus.XXXXXX)
mkdir -p "$work"
replay=$build/replay/glpt-replay
glpt=$build/replay/glpt
[ -x "$replay" ] || { echo "menu_parity_real_games: build first (scripts/build.sh)" >&2; exit 2; }
for tool in apitrace Xvfb xdotool; do
  command -v $tool >/dev/null || { echo "menu_parity_real_games: needs $tool" >&2; exit 2; }
done

display=:$((90 + RANDOM % 100))
Xvfb "$display" -screen 0 800x600x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
sleep 1
export DISPLAY=$display

key() { xdotool key "$1"; sleep 1.2; }
click() { xdotool mousemove --window "$1" "$2" "$3" click 1; sleep 1.5; }
move() { xdotool mousemove --window "$1" "$2" "$3"; sleep 0.7; }

record_torcs() {  # main menu, race types, players, options
  # torcs runs from its data directory and writes the trace there unless given a full path.
  timeout -s INT 40 apitrace trace --api gl -o "$1" /usr/games/torcs >/dev/null 2>&1 &
  local program=$!
  sleep 10
  local w
  w=$(xdotool search --name TORCS | head -n 1)
  move "$w" 320 100; move "$w" 320 120
  click "$w" 320 88; move "$w" 320 150; move "$w" 320 200
  click "$w" 320 150; move "$w" 300 300
  click "$w" 320 200; move "$w" 200 200
  key Escape; key Escape
  click "$w" 320 118; move "$w" 100 100
  key Escape
  click "$w" 320 134; move "$w" 200 250
  wait "$program" || true
}

record_bzflag() {  # the main menu and its submenus, drawn over the game's 3-D world
  SDL_AUDIODRIVER=dummy timeout -s INT 30 apitrace trace --api gl -o "$1" /usr/games/bzflag \
    -window 640x480+0+0 -nolist -nomotd >/dev/null 2>&1 &
  local program=$!
  sleep 12
  for k in Down Down Return Escape Down Return Escape Up Up Return Escape; do key $k; done
  wait "$program" || true
}

echo "command: $0 --games \"$games\" --every $every --work $work"
printf '%-8s %7s %10s %12s %12s\n' game frames identical min_psnr_db max_flip
for game in $games; do
  trace=$work/$game.trace
  if [ ! -f "$trace" ]; then
    command -v "/usr/games/$game" >/dev/null || { echo "$game: not installed"; continue; }
    "record_$game" "$trace"
  fi
  [ -f "$trace" ] || { echo "$game: recording failed"; continue; }
  rm -rf "$work/$game.raster" "$work/$game.path"
  "$replay" --quiet --every "$every" --mode raster --out "$work/$game.raster" "$trace" 2>/dev/null
  "$replay" --quiet --every "$every" --mode path --out "$work/$game.path" "$trace" 2>/dev/null
  "$glpt" diff --json --threshold 1 "$work/$game.raster" "$work/$game.path" |
    awk -v game="$game" '
      { frames++
        if ($0 ~ /"psnr":null/) identical++
        else { match($0, /"psnr":[0-9.e+-]+/); p = substr($0, RSTART + 7, RLENGTH - 7) + 0
               if (min == "" || p < min) min = p }
        match($0, /"flip_mean":[0-9.e+-]+/); f = substr($0, RSTART + 12, RLENGTH - 12) + 0
        if (f > maxflip) maxflip = f }
      END { printf "%-8s %7d %10d %12s %12.4g\n", game, frames, identical,
                   (min == "" ? "inf" : sprintf("%.1f", min)), maxflip }'
done
