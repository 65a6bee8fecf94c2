#!/usr/bin/env bash
# apitrace_state_test.sh LIBGL STATETOUR IMGCOMPARE
#
# apitrace as the oracle for GL state (issue: every query). In a private Xvfb:
#   1. records statetour (tests/programs; it moves nearly every GL 1.x state from its default)
#      with `apitrace trace`;
#   2. replays the trace with glretrace on real Mesa and with glpt preloaded (raster mode),
#      dumping the whole GL state at the last frame's glFlush (`glretrace -D CALL
#      --dump-format=json`), and compares the dumps with apitrace_state_compare.py: every
#      GL 1.x parameter, the texel images of every bound texture, depth and stencil; the
#      deliberate differences are listed with reasons in apitrace_state_known.txt;
#   3. compares the colour buffers of the two dumps and the two snapshots glretrace takes at that
#      call (`glretrace -S CALL -s PREFIX`) with the conformance tolerance (2/255 on 99.5 % of
#      the pixels), and checks that glretrace's default per-frame snapshots work through glpt.
# Exits 77 (skipped) when apitrace is not installed. On failure the files stay in the temporary
# directory it prints.
set -euo pipefail

if [ $# -ne 3 ]; then
  echo "usage: apitrace_state_test.sh LIBGL STATETOUR IMGCOMPARE" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
for tool in apitrace glretrace; do
  command -v "$tool" >/dev/null 2>&1 || { echo "apitrace_state_test: $tool not installed: skipped"; exit 77; }
done
if [ -z "${GLPT_E2E_UNDER_XVFB:-}" ]; then
  GLPT_E2E_UNDER_XVFB=1 exec "$here/with_xvfb.sh" "$0" "$@"
fi
libgl=$1
statetour=$2
imgcompare=$3
frames=2
run_timeout_s=120

tmp=$(mktemp -d "${TMPDIR:-/tmp}/glpt-apitrace-state.XXXXXX")
keep_tmp=1
trap '[ "$keep_tmp" = 0 ] && rm -rf "$tmp"' EXIT
failures=()
fail() { failures+=("$1"); echo "apitrace_state_test: FAIL: $1" >&2; }
echo "apitrace_state_test: DISPLAY=$DISPLAY dir=$tmp"

timeout "$run_timeout_s" apitrace trace --api gl -o "$tmp/tour.trace" "$statetour" --frames "$frames" \
  >"$tmp/trace.log" 2>&1 || { cat "$tmp/trace.log" >&2; echo "apitrace_state_test: tracing failed" >&2; exit 1; }
# The call to look at: the last frame's glFlush, where the attribute and matrix stacks are pushed.
call=$(apitrace dump "$tmp/tour.trace" | awk '$2 == "glFlush()" { n = $1 } END { print n }')
[ -n "$call" ] || { echo "apitrace_state_test: no glFlush in the trace" >&2; exit 1; }
echo "apitrace_state_test: state at call $call"

# replay NAME PRELOAD GLRETRACE-ARGS...: glretrace on the trace; stdout to $tmp/NAME.out.
replay() {
  local name=$1 preload=$2
  shift 2
  local rc=0
  timeout "$run_timeout_s" env ${preload:+LD_PRELOAD="$preload"} GLPT_MODE=raster GLPT_QUIET=1 \
    glretrace "$@" "$tmp/tour.trace" >"$tmp/$name.out" 2>"$tmp/$name.err" || rc=$?
  if [ "$rc" != 0 ]; then
    fail "$name: glretrace $* exited with status $rc"
    tail -n 20 "$tmp/$name.err" >&2 || true
    return 1
  fi
}

replay mesa_dump "" -D "$call" --dump-format=json || true
replay glpt_dump "$libgl" -D "$call" --dump-format=json || true
if [ -s "$tmp/mesa_dump.out" ] && [ -s "$tmp/glpt_dump.out" ]; then
  python3 "$here/apitrace_state_compare.py" "$tmp/mesa_dump.out" "$tmp/glpt_dump.out" \
    --known "$here/apitrace_state_known.txt" --images "$tmp" || fail "state dumps differ"
  "$imgcompare" within "$tmp/mesa_GL_BACK.png" "$tmp/glpt_GL_BACK.png" --diff "$tmp/dump_back.diff.png" ||
    fail "the dumps' back buffers differ"
fi

mkdir -p "$tmp/snap_mesa" "$tmp/snap_glpt" "$tmp/frames_glpt"
replay mesa_snapshot "" -S "$call" -s "$tmp/snap_mesa/" || true
replay glpt_snapshot "$libgl" -S "$call" -s "$tmp/snap_glpt/" || true
name=$(printf '%010d.png' "$call")
if [ -s "$tmp/snap_mesa/$name" ] && [ -s "$tmp/snap_glpt/$name" ]; then
  "$imgcompare" within "$tmp/snap_mesa/$name" "$tmp/snap_glpt/$name" --diff "$tmp/snapshot.diff.png" ||
    fail "the snapshots at call $call differ"
else
  fail "glretrace -S $call -s wrote no snapshot $name"
fi
# Default snapshots: one per frame, at each swap.
replay glpt_frames "$libgl" -s "$tmp/frames_glpt/" || true
snapshots=$(find "$tmp/frames_glpt" -name '*.png' | wc -l)
[ "$snapshots" = "$frames" ] || fail "glretrace -s through glpt wrote $snapshots snapshots, expected $frames"

if [ ${#failures[@]} -ne 0 ]; then
  echo "apitrace_state_test: ${#failures[@]} failure(s); files in $tmp" >&2
  exit 1
fi
keep_tmp=0
echo "apitrace_state_test: PASS"
