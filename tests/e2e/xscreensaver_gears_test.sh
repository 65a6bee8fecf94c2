#!/usr/bin/env bash
# xscreensaver_gears_test.sh LIBGL IMGCOMPARE
#
# Runs the unmodified xscreensaver GL hack gears (/usr/libexec/xscreensaver/gears, Debian package
# xscreensaver-gl) in a window under glpt (LD_PRELOAD=LIBGL, GLPT_MODE=raster) in a private Xvfb.
# The hacks create their context through EGL (eglGetPlatformDisplay, eglChooseConfig,
# eglCreatePlatformWindowSurface, eglCreateContext for OpenGL 1.3, eglSwapBuffers), linking the
# system libEGL.so.1: the preloaded libGL.so.1 must answer those calls. With GLPT_OUTPUT=<tmpdir>
# glpt writes each swapped frame as frame_NNNNNN.png, which only happens when the frames went
# through glpt's EGL. Passes iff
#   - >= 10 frame PNGs appear within GLPT_E2E_WAIT_S (default 60) seconds,
#   - sampled frames are the window's size (300x200) and not blank (>= 1% of pixels differ from
#     the top-left pixel),
#   - gears printed no EGL failure (it aborts or exits on those).
# gears runs until it is killed. Exits 77 (skipped) when gears is not installed.
set -euo pipefail

if [ $# -ne 2 ]; then
  echo "usage: xscreensaver_gears_test.sh LIBGL IMGCOMPARE" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
gears=${XSCREENSAVER_GEARS:-/usr/libexec/xscreensaver/gears}
if [ ! -x "$gears" ]; then
  echo "xscreensaver_gears_test: $gears not installed (package xscreensaver-gl); skipped"
  exit 77
fi
if [ -z "${GLPT_E2E_UNDER_XVFB:-}" ]; then
  GLPT_E2E_UNDER_XVFB=1 exec "$here/with_xvfb.sh" "$0" "$@"
fi

libgl=$1
imgcompare=$2
wait_s=${GLPT_E2E_WAIT_S:-60}
want_frames=10
want_size=300x200
[ -f "$libgl" ] || { echo "xscreensaver_gears_test: LIBGL not found: $libgl" >&2; exit 2; }

# shellcheck source-path=SCRIPTDIR source=frames_lib.sh
source "$here/frames_lib.sh"
e2e_frames_setup glpt-xss-gears
failures=()
fail() { failures+=("$1"); echo "xscreensaver_gears_test: FAIL: $1" >&2; }

echo "xscreensaver_gears_test: DISPLAY=$DISPLAY LIBGL=$libgl output=$out"
env LD_PRELOAD="$libgl${LD_PRELOAD:+:$LD_PRELOAD}" GLPT_MODE=raster GLPT_OUTPUT="$out" \
  "$gears" -geometry "$want_size" >"$tmp/gears.stdout" 2>"$tmp/gears.stderr" &
pid=$!

wait_for_frames "$want_frames" "$wait_s" gears || fail "$wait_error"
if [ -n "$pid" ]; then
  kill "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  pid=""
fi

if grep -Eq "EGL|egl" "$tmp/gears.stderr"; then
  fail "gears reported EGL errors: $(grep -E 'EGL|egl' "$tmp/gears.stderr" | head -n 3 | tr '\n' ' ')"
fi
mapfile -t frames < <(find "$out" -maxdepth 1 -name 'frame_*.png' | sort)
n=${#frames[@]}
if [ "$n" -gt 0 ]; then
  samples=("${frames[0]}" "${frames[$((n / 2))]}" "${frames[$((n - 1))]}")
  if ! "$imgcompare" nonblank "${samples[@]}" --min-fraction 0.01 >"$tmp/nonblank.txt" 2>&1; then
    fail "blank or unreadable frames: $(grep -v PASS "$tmp/nonblank.txt" | head -n 3 | tr '\n' ' ')"
  fi
  cat "$tmp/nonblank.txt"
  wrong_size=$(grep -v " $want_size " "$tmp/nonblank.txt" | grep -c '^nonblank:' || true)
  [ "$wrong_size" = 0 ] || fail "$wrong_size sampled frame(s) are not $want_size (the window)"
fi

if [ ${#failures[@]} -gt 0 ]; then
  echo "---- gears stderr (last 40 lines) ----" >&2
  tail -n 40 "$tmp/gears.stderr" >&2 || true
  echo "xscreensaver_gears_test: ${#failures[@]} check(s) failed; kept $tmp" >&2
  exit 1
fi
echo "xscreensaver_gears_test: PASS ($n frames)"
keep_tmp=0
