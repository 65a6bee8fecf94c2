#!/usr/bin/env bash
# Runs a GL program (under $DISPLAY) until DIR holds FRAMES PNG frames, then asks it to quit
# the way a user would: the Escape key in its window. Exits with the program's status.
#
#   run_until_frames.sh DIR FRAMES X_SEND_KEY COMMAND...
set -euo pipefail
dir=$1 frames=$2 send_key=$3
shift 3
timeout_s=${GLPT_RUN_TIMEOUT:-300}
"$@" &
pid=$!
start=$(date +%s)
while kill -0 "$pid" 2>/dev/null; do
  n=$(find "$dir" -maxdepth 1 -name 'frame_*.png' | wc -l)
  [ "$n" -ge "$frames" ] && break
  if [ $(( $(date +%s) - start )) -gt "$timeout_s" ]; then
    echo "run_until_frames: only $n of $frames frames after ${timeout_s}s" >&2
    kill "$pid" 2>/dev/null || true
    wait "$pid" || true
    exit 1
  fi
  sleep 0.2
done
if kill -0 "$pid" 2>/dev/null; then
  "$send_key" >/dev/null || true
  for _ in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$pid" 2>/dev/null; then
    echo "run_until_frames: program did not exit after Escape" >&2
    kill "$pid" 2>/dev/null || true
  fi
fi
wait "$pid"
