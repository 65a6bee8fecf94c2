#!/usr/bin/env bash
# record_real_games.sh [--games "torcs bzflag trigger-rally pinball"] [--out DIR]
#
# Records apitrace traces of real GL 1.x games in gameplay, on real Mesa (llvmpipe; nothing of
# glpt involved), headless in a private Xvfb, playing them with xdotool: a torcs Quick Race on
# $TORCS_TRACK (default e-track-4) against one robot, driving (HUD: laps, times, gauges, map); a
# bzflag game on a local bzfs with one robot, at noon (sky, radar, messages, scores); a
# trigger-rally single race, driving (timer, map, gauge); the Emilia pinball Tux table, a ball
# launched and the flippers in use (score). Each game runs in a fresh temporary HOME, ends on
# SIGINT (apitrace flushes the trace then; pinball quits from its menu) and leaves DIR/GAME.trace
# and DIR/GAME.log (default DIR: a temporary directory, printed); a trace over 60 MiB is repacked
# with Brotli. Prints per game the trace size, frame count and the seconds spent recording and
# repacking. Skips games that are not installed; exits non-zero when a game leaves no trace or one
# of under 60 frames. Needs the Debian packages apitrace, xvfb, xdotool and the games': torcs,
# bzflag-client and bzflag-server, trigger-rally, pinball. One to three minutes a game (2 cores).
set -euo pipefail
games="torcs bzflag trigger-rally pinball"
out=""
while [ $# -gt 0 ]; do
  case $1 in
    --games) games=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    -h|--help) sed -n '2,15p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "record_real_games: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
say() { echo "record_real_games: $*" >&2; }
for game in $games; do
  case $game in
    torcs|bzflag|trigger-rally|pinball) ;;
    *) say "unknown game '$game' (torcs, bzflag, trigger-rally, pinball)"; exit 2 ;;
  esac
done
for tool in apitrace Xvfb xdotool timeout; do
  command -v $tool >/dev/null || { say "needs $tool"; exit 2; }
done
[ -n "$out" ] || out=$(mktemp -d /tmp/glpt-games.XXXXXX)
mkdir -p "$out"
out=$(cd "$out" && pwd)
tmp=$(mktemp -d /tmp/glpt-record.XXXXXX)
max_bytes=$((60 << 20))
torcs_track=${TORCS_TRACK:-e-track-4}

# Real Mesa, software: nothing of glpt (or anything else) preloaded.
unset LD_PRELOAD LD_LIBRARY_PATH
export LIBGL_ALWAYS_SOFTWARE=1
# No sound card: OpenAL (torcs, trigger-rally) and SDL (bzflag, pinball) write to nothing.
export ALSOFT_DRIVERS=null SDL_AUDIODRIVER=dummy
export XDG_RUNTIME_DIR=$tmp/run
mkdir -m 700 "$XDG_RUNTIME_DIR"

xvfb="" bzfs="" game_pid="" win=""
cleanup() {
  [ -z "$game_pid" ] || kill -KILL -- "-$game_pid" 2>/dev/null || true
  [ -z "$bzfs" ] || kill "$bzfs" 2>/dev/null || true
  [ -z "$xvfb" ] || kill "$xvfb" 2>/dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT
n=$((90 + RANDOM % 100))
while [ -e /tmp/.X$n-lock ] || [ -e /tmp/.X11-unix/X$n ]; do n=$((n + 1)); done
export DISPLAY=:$n
Xvfb "$DISPLAY" -screen 0 800x600x24 -nolisten tcp >"$tmp/xvfb.log" 2>&1 &
xvfb=$!
for _ in $(seq 1 50); do xdotool getmouselocation >/dev/null 2>&1 && break; sleep 0.2; done
xdotool getmouselocation >/dev/null 2>&1 || { say "Xvfb did not start"; cat "$tmp/xvfb.log" >&2; exit 1; }

# start TRACE SECONDS COMMAND...: runs COMMAND under apitrace, in a process group of its own
# (timeout's), for at most SECONDS. SIGINT is reset to its default: a non-interactive shell starts
# background jobs with it ignored, and the game would then not end on it. The sh in between turns
# a game's crash on SIGINT (torcs) into an exit status instead of a job report from bash.
start() {
  local trace=$1 limit=$2
  shift 2
  rm -f "$trace"
  # shellcheck disable=SC2016  # $0 and $@ are sh's
  timeout -s INT -k 30 "$limit" env --default-signal=INT \
    sh -c 'apitrace trace --api gl -o "$0" "$@"; exit $?' "$trace" "$@" </dev/null >>"$log" 2>&1 &
  game_pid=$!
  sleep 1
}
# stop: SIGINT to the game (timeout passes it on to its group) and waits until all of it is gone.
stop() {
  kill -INT "$game_pid" 2>/dev/null || true
  for _ in $(seq 1 300); do kill -0 -- "-$game_pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 -- "-$game_pid" 2>/dev/null; then
    say "$game did not end on SIGINT; killing it"
    kill -TERM -- "-$game_pid" 2>/dev/null || true; sleep 3
    kill -KILL -- "-$game_pid" 2>/dev/null || true
  fi
  wait "$game_pid" 2>/dev/null || true
  game_pid=""
}
alive() { kill -0 "$game_pid" 2>/dev/null; }
# launch NAME TRACE SECONDS COMMAND...: start, then wait for the game's window NAME (its id in
# $win). Three tries: SDL 1.2 (pinball) now and then fails with "Couldn't open X11 display".
launch() {
  local name=$1 try
  shift
  for try in 1 2 3; do
    start "$@"
    win=$(window "$name" 60) && return 0
    stop
    [ "$try" = 3 ] || say "$game: trying again"
  done
  return 1
}
# window NAME SECONDS: the id of the first visible window whose name matches NAME.
window() {
  local w
  for _ in $(seq 1 $(($2 * 2))); do
    w=$(xdotool search --onlyvisible --name "$1" 2>/dev/null | head -n 1) || true
    [ -n "$w" ] && { echo "$w"; return 0; }
    alive || break
    sleep 0.5
  done
  say "$game: no window named '$1' (log: $log)"
  return 1
}
# Without a window manager keys go to the window under the pointer: keep it in the game's window.
move() { xdotool mousemove --window "$1" "$2" "$3"; sleep "${4:-0.7}"; }
click() { xdotool mousemove --window "$1" "$2" "$3"; sleep 0.3; xdotool click 1; sleep "${4:-1.5}"; }
# A key held down for a moment: games that poll key state (pinball) miss instant taps.
key() { xdotool keydown "$1"; sleep 0.15; xdotool keyup "$1"; sleep "${2:-1}"; }
hold() {  # hold KEY... SECONDS
  local keys=("${@:1:$#-1}") s=${!#} k
  for k in "${keys[@]}"; do xdotool keydown "$k"; done
  sleep "$s"
  for k in "${keys[@]}"; do xdotool keyup "$k"; done
}

record_torcs() {  # Race -> Quick Race -> New Race (the player's car, keyboard), then drive
  # The launcher's first step (copying the default config), then a Quick Race on TORCS_TRACK
  # against one robot: every frame of a race holds thousands of small glDrawElements on client
  # arrays, which apitrace copies; forza (the default track) and five cars make ~4 MB a frame.
  local conf=$HOME/.torcs lib=/usr/lib/x86_64-linux-gnu/torcs
  mkdir -p "$conf"
  (cd /usr/share/games/torcs && bash "$lib/setup_linux.sh" "$conf") >>"$log" 2>&1
  sed -i -e '/<section name="Drivers">/,/^    <\/section>/{/<section name="[235]">/,/<\/section>/d}' \
    -e '/<section name="Drivers">/,/^    <\/section>/s/<section name="4">/<section name="2">/' \
    -e "s|<attstr name=\"name\" val=\"forza\"/>|<attstr name=\"name\" val=\"$torcs_track\"/>|" \
    "$conf/config/raceman/quickrace.xml"
  launch TORCS "$1" 240 /usr/games/torcs || return 1
  local w=$win
  sleep 10                                      # clicks before the menu is up are lost
  move "$w" 320 120; click "$w" 320 88          # Race (menus redraw on input only)
  move "$w" 300 200; click "$w" 320 88          # Quick Race
  move "$w" 300 300; click "$w" 320 88 8        # New Race; loading, the race starts
  move "$w" 320 300 0.2
  hold Up 5; hold Up Left 0.3; hold Up 3; hold Up Right 0.3; hold Up 2; hold Down 1
  stop
}

record_bzflag() {  # a local bzfs, one robot; spawn and drive (the robot shoots)
  local port=$((5200 + RANDOM % 700))
  HOME=$tmp/home-bzfs timeout 600 /usr/games/bzfs -p "$port" -i 127.0.0.1 -a 50 38 \
    </dev/null >"$tmp/bzfs.log" 2>&1 &
  bzfs=$!
  sleep 2
  kill -0 "$bzfs" 2>/dev/null || { say "bzfs did not start: $(cat "$tmp/bzfs.log")"; return 1; }
  # -time: noon at bzflag's default longitude (sky and sun rather than night). -configdir: bzflag
  # keeps its config in the passwd entry's home, not $HOME.
  launch bzflag "$1" 240 /usr/games/bzflag -configdir "$HOME/bzf" -window 640x480 -nolist \
    -nomotd -time 20:00:00 -solo 1 "recorder@127.0.0.1:$port" || return 1
  local w=$win
  sleep 8
  move "$w" 320 240 0.2
  key i 3                                       # "Press Right Mouse or i to start"
  # No shots of our own: bzfs drops a player whose first shot comes before its UDP link is up.
  for _ in 1 2 3 4; do
    key i 0.5                                   # respawn if the robot got us
    hold Up 3; hold Left 0.6; key i 0.3; hold Up 2; hold Down 1; hold Right 0.5
  done
  stop
  kill "$bzfs" 2>/dev/null || true
  wait "$bzfs" 2>/dev/null || true
  bzfs=""
}

record_trigger_rally() {  # single race "Blue Noon", the default car; drive
  # A first run without a display only writes the default config; then: a 640x480 window.
  env -u DISPLAY timeout 30 /usr/games/trigger-rally </dev/null >>"$log" 2>&1 || true
  local config
  config=$(find "$HOME/.local/share/trigger-rally" -name "trigger-rally-*.config" 2>/dev/null | head -n 1)
  [ -n "$config" ] || { say "trigger-rally wrote no config (log: $log)"; return 1; }
  sed -i -e 's/automatic="yes"/automatic="no"/' -e 's/width="800"/width="640"/' \
    -e 's/height="600"/height="480"/' -e 's/enablesound="yes"/enablesound="no"/' "$config"
  launch 'Trigger Rally' "$1" 240 /usr/games/trigger-rally || return 1
  local w=$win
  sleep 6
  click "$w" 320 278 2                          # single race
  click "$w" 150 376 2                          # Blue Noon (11th in the list)
  click "$w" 590 454 4                          # race
  move "$w" 320 300 0.2
  key Return 12                                 # car selection: the first car; loading
  hold Up 8; hold Up Left 0.5; hold Up 5; hold Up Right 0.5; hold Up 5
  stop
}

record_pinball() {  # Load Table -> Tux, Play; launch balls, flip
  # /usr/games/pinball is setgid games: the loader ignores LD_PRELOAD for it; a copy is plain.
  mkdir -p "$tmp/pinball-bin"
  cp /usr/games/pinball "$tmp/pinball-bin/pinball"
  launch Pinball "$1" 240 "$tmp/pinball-bin/pinball" || return 1
  local w=$win
  sleep 4
  move "$w" 320 240 0.2
  key Down; key Return 1.5; key Return 8        # Load Table, Tux; loading it
  key Up; key Return 0.5                        # Play (Enter also brings the first ball)
  # ~18 frames a second of ~20000 immediate-mode vertices each (~1.8 MB): about 12 seconds of
  # play. The second round launches a second ball only if the first has drained by then.
  for _ in 1 2; do
    hold Return 1.5; sleep 1                    # pull the plunger back and let go
    for _ in 1 2; do hold Shift_L 0.3; sleep 0.4; hold Shift_R 0.3; sleep 0.6; done
    key Return 0.5                              # the next ball, if this one drained
  done
  # Quit from the menu: pinball ignores SIGINT in some states and has crashed in its handler.
  key Escape 1.5; key Down 0.5; key Down 0.5; key Down 0.5; key Down 0.5; key Return 3
  stop
}

echo "command: $0 --games \"$games\" --out $out"
printf '%-14s %8s %7s %9s %7s  %s\n' game MiB frames record_s pack_s trace
failed=""
for game in $games; do
  if [ ! -x "/usr/games/$game" ]; then
    say "$game: not installed (/usr/games/$game), skipped"
    continue
  fi
  if [ "$game" = bzflag ] && [ ! -x /usr/games/bzfs ]; then
    say "bzflag: needs bzfs (package bzflag-server), skipped"
    continue
  fi
  trace=$out/$game.trace
  log=$out/$game.log
  : >"$log"
  export HOME=$tmp/home-$game
  mkdir -p "$HOME"
  t0=$(date +%s)
  ok=yes
  "record_${game//-/_}" "$trace" || ok=""
  [ -z "$game_pid" ] || stop
  t1=$(date +%s)
  if [ -z "$ok" ] || [ ! -s "$trace" ]; then
    say "$game: recording failed, no trace (log: $log)"
    failed="$failed $game"
    continue
  fi
  if [ "$(stat -c %s "$trace")" -gt "$max_bytes" ]; then
    # Quality 7: torcs' frames repeat the same client arrays, which quality 6 and less do not
    # find (100 MB against 27); 8 and more take minutes longer for a few percent.
    apitrace repack --brotli=7 "$trace" "$trace.brotli" && mv "$trace.brotli" "$trace"
  fi
  t2=$(date +%s)
  frames=$(apitrace info "$trace" 2>/dev/null | sed -n 's/.*"FramesCount": *\([0-9]*\).*/\1/p')
  printf '%-14s %8.1f %7s %9d %7d  %s\n' "$game" \
    "$(stat -c %s "$trace" | awk '{print $1 / 1048576}')" "${frames:-?}" $((t1 - t0)) $((t2 - t1)) \
    "$trace"
  if [ "${frames:-0}" -lt 60 ]; then
    say "$game: only ${frames:-0} frames recorded (log: $log)"
    failed="$failed $game"
  fi
done
if [ -n "$failed" ]; then
  say "failed:$failed"
  exit 1
fi
