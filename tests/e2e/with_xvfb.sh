#!/usr/bin/env bash
# with_xvfb.sh CMD [ARGS...]
#
# Runs CMD under a private Xvfb (screen 1280x1024x24) on a display number that Xvfb picks itself
# (-displayfd), with DISPLAY exported. Xvfb is always stopped afterwards, also when CMD fails or
# this script is interrupted. Exits with CMD's exit status (or 125 if Xvfb does not start).
set -euo pipefail

if [ $# -eq 0 ]; then
  echo "usage: with_xvfb.sh CMD [ARGS...]" >&2
  exit 125
fi
if ! command -v Xvfb >/dev/null 2>&1; then
  echo "with_xvfb.sh: Xvfb not found (Debian package xvfb)" >&2
  exit 125
fi

state=$(mktemp -d "${TMPDIR:-/tmp}/glpt-xvfb.XXXXXX")
xvfb_pid=""
# shellcheck disable=SC2317  # called from the EXIT trap
cleanup() {
  if [ -n "$xvfb_pid" ]; then
    kill "$xvfb_pid" 2>/dev/null || true
    wait "$xvfb_pid" 2>/dev/null || true
  fi
  rm -rf "$state"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM

# -displayfd: Xvfb chooses a free display and writes its number to the fd once it accepts
# connections. -noreset: stay up when the last client disconnects.
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset \
  3>"$state/display" >"$state/xvfb.log" 2>&1 &
xvfb_pid=$!

display=""
for _ in $(seq 1 200); do  # up to 20 s
  if grep -q '^[0-9][0-9]*$' "$state/display" 2>/dev/null; then
    display=$(head -n 1 "$state/display")
    break
  fi
  if ! kill -0 "$xvfb_pid" 2>/dev/null; then
    break
  fi
  sleep 0.1
done
if [ -z "$display" ]; then
  echo "with_xvfb.sh: Xvfb did not start; its log:" >&2
  cat "$state/xvfb.log" >&2 || true
  exit 125
fi

export DISPLAY=":$display"
set +e
"$@"
rc=$?
set -e
exit "$rc"
