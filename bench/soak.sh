#!/usr/bin/env bash
# soak.sh [--frames N] [--modes "raster path"] [--programs "glxgears gears pipes"]
#         [--trace FILE] [--trace-repeat K] [--path-settings "GLPT_*=..."] [--out DIR]
#         [--geometry WxH]
#
# The soak of issue 22 (not a test, not in CI; docs/soak.md): each program runs N frames
# (default 10,000) in each mode under glpt, headless, and what every frame cost is read from
# GLPT_STATS_FILE: resident memory (rss_kb), Vulkan objects alive (vk_objects) and the frame's
# own work (total_ms: recording to presented). bench/soak_report.py then says, per run, how much
# memory grew after the warm-up, whether the Vulkan object count grew, and which frames took more
# than 3x the median after the warm-up.
#
# Programs: glxgears and xscreensaver hacks (/usr/libexec/xscreensaver/NAME -window) run with
# libGL.so.1 preloaded in a private Xvfb (tests/e2e/with_xvfb.sh) until their stats file holds N
# frames; the recorded game (--trace, an apitrace trace) is replayed by glpt-replay in one process,
# --repeat K times (K defaults to enough passes for N frames). Path-traced runs use
# --path-settings (default: 1 sample, trace scale 0.5: 10,000 path-traced frames of a 640x480
# game otherwise take hours on 2 cores). --geometry gives glxgears and the hacks that window size
# (default: theirs; the hacks open 1280x720 in the private Xvfb, and the trace and the denoiser
# cost grows with the window).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${GLPT_BUILD_DIR:-$repo/build}
libgl=$build/gl_shim/libGL.so.1
replay=$build/replay/glpt-replay
frames=10000
modes="raster path"
programs="glxgears gears pipes"
trace=""
trace_repeat=0
path_settings="GLPT_SPP=1 GLPT_SCALE=0.5"
out=/tmp/glpt-soak
geometry=""
while [ $# -gt 0 ]; do
  case $1 in
    --frames) frames=$2; shift 2 ;;
    --modes) modes=$2; shift 2 ;;
    --programs) programs=$2; shift 2 ;;
    --trace) trace=$2; shift 2 ;;
    --trace-repeat) trace_repeat=$2; shift 2 ;;
    --path-settings) path_settings=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --geometry) geometry=$2; shift 2 ;;
    -h|--help) sed -n '2,21p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "soak: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ -f "$libgl" ] && [ -x "$replay" ] || { echo "soak: build first ($libgl, $replay)" >&2; exit 2; }
mkdir -p "$out"
echo "command: $0 --frames $frames --modes \"$modes\" --programs \"$programs\"" \
  "${trace:+--trace $trace} --path-settings \"$path_settings\" --out $out" \
  "${geometry:+--geometry $geometry}"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "commit: $(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)"

settings_for() {  # the GLPT_* settings of a mode, as env arguments
  if [ "$1" = path ]; then echo "GLPT_MODE=path $path_settings"; else echo "GLPT_MODE=raster"; fi
}

frames_in() { [ -f "$1" ] && grep -c ' frame=' "$1" || echo 0; }

runs=()
for mode in $modes; do
  for program in $programs; do
    if [ "$program" = glxgears ]; then
      command=(glxgears)
    else
      command=("/usr/libexec/xscreensaver/$program" -window)
    fi
    [ -n "$geometry" ] && command+=(-geometry "$geometry")
    command -v "${command[0]}" >/dev/null || { echo "soak: no ${command[0]}, skipped" >&2; continue; }
    stats=$out/$program.$mode.stats
    rm -f "$stats"
    echo "soak: $program ($mode), $frames frames ..."
    start=$(date +%s)
    # shellcheck disable=SC2046  # the settings are words on purpose
    "$repo/tests/e2e/with_xvfb.sh" env $(settings_for "$mode") GLPT_STATS_FILE="$stats" \
      LD_PRELOAD="$libgl" "${command[@]}" >"$out/$program.$mode.log" 2>&1 &
    pid=$!
    while kill -0 "$pid" 2>/dev/null && [ "$(frames_in "$stats")" -lt "$frames" ]; do sleep 2; done
    # The program (and the Xvfb) are with_xvfb.sh's children: stopping them ends it (it waits for
    # its command before it handles a signal of its own).
    pkill -TERM -P "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    echo "soak: $program ($mode): $(frames_in "$stats") frames in $(($(date +%s) - start)) s"
    runs+=("$program.$mode=$stats")
  done
  if [ -n "$trace" ]; then
    name=$(basename "$trace" .trace)
    stats=$out/$name.$mode.stats
    rm -f "$stats"
    repeat=$trace_repeat
    if [ "$repeat" = 0 ]; then
      # Frames per pass from a raster replay's summary line ("... N frames ...").
      per_pass=$(GLPT_MODE=raster "$replay" --quiet --mode raster "$trace" 2>&1 |
        sed -n 's/.* \([0-9][0-9]*\) frames.*/\1/p' | tail -1)
      [ -n "$per_pass" ] && [ "$per_pass" -gt 0 ] ||
        { echo "soak: cannot count the frames of $trace" >&2; exit 1; }
      repeat=$(((frames + per_pass - 1) / per_pass))
    fi
    echo "soak: $name ($mode), glpt-replay --repeat $repeat ..."
    start=$(date +%s)
    # shellcheck disable=SC2046
    env $(settings_for "$mode") GLPT_STATS_FILE="$stats" \
      "$replay" --quiet --mode "$mode" --repeat "$repeat" "$trace" >"$out/$name.$mode.log" 2>&1 ||
      echo "soak: glpt-replay exited $? (see $out/$name.$mode.log)"
    echo "soak: $name ($mode): $(frames_in "$stats") frames in $(($(date +%s) - start)) s"
    runs+=("$name.$mode=$stats")
  fi
done
/usr/bin/python3 "$here/soak_report.py" --frames "$frames" "${runs[@]}" | tee "$out/report.md"
