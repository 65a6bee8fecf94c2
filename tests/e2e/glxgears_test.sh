#!/usr/bin/env bash
# glxgears_test.sh LIBGL X_SEND_KEY IMGCOMPARE
#
# Runs the unmodified /usr/bin/glxgears under glpt (LD_PRELOAD=LIBGL) in a private Xvfb, with
# GLPT_OUTPUT=<tmpdir> (glpt writes frame_NNNNNN.png there) and GLPT_STATS=1 (one "glpt: ..."
# stats line per frame on stderr). Waits until at least 30 frames exist, sends Escape to the
# glxgears window with X_SEND_KEY and waits for glxgears to exit. Passes iff
#   - glxgears exits with status 0 after Escape,
#   - >= 30 frame PNGs were written, each readable and 300x300 (glxgears' default window),
#   - sampled frames are not blank (>= 1% of pixels differ from the top-left pixel),
#   - stderr has >= 30 stats lines carrying every documented key.
# On failure it prints the reasons and the tail of glxgears' stderr and keeps the temporary
# directory. An empty LIBGL runs glxgears on real Mesa without any preload (then no frames are
# written, so the test fails: use it only to watch the flow). IMGCOMPARE is glpt_imgcompare.
#
# Environment: GLXGEARS (default /usr/bin/glxgears), GLPT_E2E_WAIT_S (default 120, time allowed
# for the 30 frames).
set -euo pipefail

if [ $# -ne 3 ]; then
  echo "usage: glxgears_test.sh LIBGL X_SEND_KEY IMGCOMPARE" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
if [ -z "${GLPT_E2E_UNDER_XVFB:-}" ]; then
  GLPT_E2E_UNDER_XVFB=1 exec "$here/with_xvfb.sh" "$0" "$@"
fi

libgl=$1
x_send_key=$2
imgcompare=$3
glxgears=${GLXGEARS:-/usr/bin/glxgears}
wait_s=${GLPT_E2E_WAIT_S:-120}
want_frames=30
want_size=300x300
stats_keys=(frame size capture_ms blas_ms tlas_ms trace_ms present_ms total_ms triangles rays
            mrays_per_s)

for f in "$x_send_key" "$imgcompare" "$glxgears"; do
  [ -x "$f" ] || { echo "glxgears_test: not executable: $f" >&2; exit 2; }
done
if [ -n "$libgl" ] && [ ! -f "$libgl" ]; then
  echo "glxgears_test: LIBGL not found: $libgl" >&2
  exit 2
fi

# shellcheck source-path=SCRIPTDIR source=frames_lib.sh
source "$here/frames_lib.sh"
e2e_frames_setup glpt-glxgears

preload=()
if [ -n "$libgl" ]; then preload=(LD_PRELOAD="$libgl${LD_PRELOAD:+:$LD_PRELOAD}"); fi
echo "glxgears_test: DISPLAY=$DISPLAY LIBGL=${libgl:-<none, real Mesa>} output=$out"
start=$(date +%s)
env "${preload[@]}" GLPT_OUTPUT="$out" GLPT_STATS=1 "$glxgears" \
  >"$tmp/glxgears.stdout" 2>"$tmp/glxgears.stderr" &
pid=$!

failures=()
fail() { failures+=("$1"); echo "glxgears_test: FAIL: $1" >&2; }
report_and_exit() {
  local rc=0
  if [ ${#failures[@]} -gt 0 ]; then
    echo "---- glxgears stderr (last 40 lines) ----" >&2
    tail -n 40 "$tmp/glxgears.stderr" >&2 || true
    echo "----" >&2
    echo "glxgears_test: ${#failures[@]} check(s) failed; kept $tmp" >&2
    rc=1
  else
    echo "glxgears_test: PASS"
    keep_tmp=0
  fi
  exit "$rc"
}

# 1. Wait for the frames.
if ! wait_for_frames "$want_frames" "$wait_s" glxgears; then
  fail "$wait_error"
  report_and_exit
fi
echo "glxgears_test: $(count_frames) frames after $(($(date +%s) - start))s; sending Escape"

# 2. Escape, then glxgears must exit by itself with status 0.
sent=0
for _ in 1 2 3 4 5; do
  if "$x_send_key" glxgears Escape; then sent=1; break; fi
  sleep 1
done
[ "$sent" = 1 ] || fail "x_send_key found no window named glxgears"
exit_rc=""
for _ in $(seq 1 300); do  # up to 30 s for the frame in flight and the shutdown
  if ! kill -0 "$pid" 2>/dev/null; then
    wait "$pid" && exit_rc=0 || exit_rc=$?
    pid=""
    break
  fi
  sleep 0.1
done
if [ -z "$exit_rc" ]; then
  fail "glxgears did not exit within 30 s of Escape (killed)"
elif [ "$exit_rc" != 0 ]; then
  fail "glxgears exited with status $exit_rc after Escape (want 0)"
fi

# 3. The frames: enough, readable, the window's size, not blank. Up to 10 evenly spaced samples
# including the first and the last.
mapfile -t frames < <(find "$out" -maxdepth 1 -name 'frame_*.png' | sort)
n=${#frames[@]}
[ "$n" -ge "$want_frames" ] || fail "only $n frame PNGs in $out (want >= $want_frames)"
if [ "$n" -gt 0 ]; then
  samples=()
  k=$((n < 10 ? n : 10))
  for i in $(seq 0 $((k - 1))); do
    samples+=("${frames[$(( k == 1 ? 0 : i * (n - 1) / (k - 1) ))]}")
  done
  if ! "$imgcompare" nonblank "${samples[@]}" --min-fraction 0.01 >"$tmp/nonblank.txt" 2>&1; then
    fail "blank or unreadable frames: $(grep -v PASS "$tmp/nonblank.txt" | head -n 3 | tr '\n' ' ')"
  fi
  cat "$tmp/nonblank.txt"
  wrong_size=$(grep -v " $want_size " "$tmp/nonblank.txt" | grep -c '^nonblank:' || true)
  [ "$wrong_size" = 0 ] || fail "$wrong_size sampled frame(s) are not $want_size (glxgears' window)"
fi

# 4. Stats lines: one per frame, with every key.
grep '^glpt: ' "$tmp/glxgears.stderr" | grep ' frame=[0-9]' >"$tmp/stats.txt" || true
nstats=$(wc -l <"$tmp/stats.txt")
[ "$nstats" -ge "$want_frames" ] ||
  fail "$nstats 'glpt: frame=...' stats lines on stderr (want >= $want_frames with GLPT_STATS=1)"
if [ "$nstats" -gt 0 ]; then
  missing=()
  for key in "${stats_keys[@]}"; do
    bad=$(grep -vc " $key=[0-9]" "$tmp/stats.txt" || true)
    [ "$bad" = 0 ] || missing+=("$key (absent in $bad of $nstats lines)")
  done
  [ ${#missing[@]} -eq 0 ] || fail "stats lines lack keys: ${missing[*]}"
  echo "glxgears_test: $nstats stats lines, e.g.: $(tail -n 1 "$tmp/stats.txt")"
fi

report_and_exit
