# shellcheck shell=bash
# Sourced by the e2e scripts that run an unmodified program under glpt and watch the frame PNGs
# glpt writes into GLPT_OUTPUT. e2e_frames_setup PREFIX makes $tmp and $out ($tmp/frames), clears
# $pid (the caller starts the program and sets it) and installs an EXIT trap that stops the
# program and removes $tmp unless $keep_tmp is 1 (it starts at 1: a failing run keeps its files).

e2e_frames_setup() {
  tmp=$(mktemp -d "${TMPDIR:-/tmp}/$1.XXXXXX")
  out=$tmp/frames
  mkdir "$out"
  pid=""
  keep_tmp=1
  trap e2e_frames_cleanup EXIT
}

# shellcheck disable=SC2317  # called from the EXIT trap
e2e_frames_cleanup() {
  if [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null; then
    kill "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  fi
  if [ "$keep_tmp" = 0 ]; then rm -rf "$tmp"; fi
}

count_frames() { find "$out" -maxdepth 1 -name 'frame_*.png' | wc -l; }

# shellcheck disable=SC2034  # wait_error is read by the sourcing script
# wait_for_frames WANT WAIT_S NAME: returns 0 once WANT frames exist; otherwise 1, with the
# reason in $wait_error (NAME exited, clearing $pid, or WAIT_S seconds passed).
wait_for_frames() {
  local want=$1 wait_s=$2 name=$3 started n rc
  started=$(date +%s)
  while :; do
    n=$(count_frames)
    [ "$n" -ge "$want" ] && return 0
    if ! kill -0 "$pid" 2>/dev/null; then
      wait "$pid" && rc=0 || rc=$?
      pid=""
      wait_error="$name exited (status $rc) after writing only $n of $want frames"
      return 1
    fi
    if [ $(($(date +%s) - started)) -ge "$wait_s" ]; then
      wait_error="only $n of $want frames after ${wait_s}s"
      return 1
    fi
    sleep 0.2
  done
}
