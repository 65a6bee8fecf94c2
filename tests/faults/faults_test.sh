#!/usr/bin/env bash
# faults_test.sh FAULT FAULT_CLIENT
#
# One fault of issue 7 item 6, run with tests/faults/fault_client (linked with glpt's
# libGL.so.1) under with_xvfb.sh; checks its output lines, exit status and stderr:
#   no-ray-query   GLPT_VK_NO_RAY_QUERY=1: one message, then frames drawn in raster mode
#   no-vulkan      no Vulkan driver: one message, GL state answers, frames show the clear colour
#                  (window, glReadPixels, PNG)
#   no-display     DISPLAY unset, then pointing at a dead server: GLX NULL, EGL's errors
#   window-closed  the window (GLX, then EGL) destroyed by another client mid-frame, then the
#                  program exits with its context current: a clean exit
#   window-killed  the program's X connection killed (XKillClient) mid-frame: Xlib's own exit,
#                  no crash, no hang
#   bad-output     GLPT_OUTPUT under a regular file, or a directory that takes no files: one
#                  message, frames still drawn
set -euo pipefail
fault=$1
client=$2
work=$(mktemp -d "${TMPDIR:-/tmp}/glpt-faults.XXXXXX")
trap 'rm -rf "$work"' EXIT
failures=0

fail() {
  echo "FAIL ($fault): $*" >&2
  failures=$((failures + 1))
}
# run ENV... -- ARGS...: runs the client with extra environment, 60 s at most.
run() {
  local envs=()
  while [ "$1" != "--" ]; do envs+=("$1"); shift; done
  shift
  set +e
  env "${envs[@]}" timeout 60 "$client" "$@" >"$work/out" 2>"$work/err"
  rc=$?
  set -e
  echo "--- $fault: fault_client $* (rc $rc)"
  cat "$work/out"
  sed 's/^/stderr: /' "$work/err"
}
expect_line() {  # the client printed exactly this line
  grep -qxF -- "$1" "$work/out" || fail "no line '$1'"
}
expect_stderr_count() {  # N lines of stderr match the pattern
  local n
  n=$(grep -c -- "$2" "$work/err" || true)
  [ "$n" -eq "$1" ] || fail "$n stderr lines match '$2', expected $1"
}
expect_rc() {
  [ "$rc" -eq "$1" ] || fail "exit status $rc, expected $1"
}
# The RGB of pixel (x, y) (top-down) of an 8-bit RGB or RGBA PNG, as rrggbb.
png_pixel() {
  python3 - "$1" "$2" "$3" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
x, y = int(sys.argv[2]), int(sys.argv[3])
pos, idat = 8, b""
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b"IHDR":
        w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
    elif kind == b"IDAT":
        idat += body
    pos += 12 + n
assert depth == 8 and ctype in (2, 6), (depth, ctype)
bpp = 3 if ctype == 2 else 4
raw, stride, rows, prev = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp)
for r in range(h):
    f, line = raw[r * (stride + 1)], bytearray(raw[r * (stride + 1) + 1:(r + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - bpp] if i >= bpp else 0
        b, c = prev[i], prev[i - bpp] if i >= bpp else 0
        p = a + b - c
        pred = [0, a, b, (a + b) // 2,
                a if abs(p - a) <= abs(p - b) and abs(p - a) <= abs(p - c)
                else (b if abs(p - b) <= abs(p - c) else c)][f]
        line[i] = (line[i] + pred) & 0xFF
    rows.append(line)
    prev = line
px = rows[y][x * bpp:x * bpp + 3]
print("%02x%02x%02x" % tuple(px))
PY
}

case "$fault" in
  no-ray-query)
    run GLPT_MODE=path GLPT_VK_NO_RAY_QUERY=1 -- draw 5
    expect_rc 0
    expect_line "frames 5"
    expect_line "second_context drew"  # ... and said nothing more (once per process)
    expect_stderr_count 1 "has no ray queries (lacks .*hidden by GLPT_VK_NO_RAY_QUERY.*): drawing in raster mode"
    # Raster mode drew the quad: red left, the clear colour right.
    expect_line "read_left 255 0 0 255"
    expect_line "read_right 0 0 255 255"
    expect_line "window_right 0x0000ff"
    ;;
  no-vulkan)
    none="$work/no_such_icd.json"
    run VK_ICD_FILENAMES="$none" VK_DRIVER_FILES="$none" GLPT_OUTPUT="$work/png" -- draw 5
    expect_rc 0
    expect_line "frames 5"
    expect_line "second_context drew"  # ... and said nothing more (once per process)
    expect_stderr_count 1 "frames show only the clear colour"
    # GL's state machine answers.
    expect_line "clear_value 0 0 1 1"
    expect_line "viewport 0 0 32 32"
    expect_line "lighting 1"
    expect_line "error 0x500"
    expect_line "error_after 0x0"
    # Every buffer shows the last clear colour (the quad is not drawn).
    expect_line "read_left 0 0 255 255"
    expect_line "read_depth_right 1"
    expect_line "read_right 0 0 255 255"
    expect_line "window_right 0x0000ff"
    [ "$(find "$work/png" -name 'frame_*.png' | wc -l)" -eq 5 ] || fail "not 5 PNGs"
    if [ -f "$work/png/frame_000004.png" ]; then
      [ "$(png_pixel "$work/png/frame_000004.png" 8 16)" = 0000ff ] || fail "PNG not the clear colour"
    fi
    ;;
  no-display)
    for display in unset ":4242"; do  # no X server listens on :4242 (with_xvfb.sh's is elsewhere)
      if [ "$display" = unset ]; then
        run -u DISPLAY -- no-display
      else
        run DISPLAY="$display" -- no-display
      fi
      expect_rc 0
      expect_line "XOpenDisplay NULL"
      expect_line "glXChooseVisual NULL"
      expect_line "glXChooseFBConfig NULL 0"
      expect_line "glXCreateContext NULL"
      expect_line "glXGetCurrentContext NULL"
      # As Mesa's libEGL answers (Mesa 25.0.7, checked by hand): a handle, then
      # EGL_NOT_INITIALIZED.
      expect_line "eglGetDisplay display 0x3000"  # EGL_SUCCESS
      expect_line "eglInitialize 0 0x3001"         # EGL_NOT_INITIALIZED
      expect_line "eglGetConfigs 0 0x3001"
      expect_line "surfaceless 1"
      expect_line "glGetError 0x0"
    done
    ;;
  window-closed)
    for mode in destroy destroy-egl; do
      run -- window-closed "$mode"
      expect_rc 0
      expect_line "closed 3"
      expect_line "frame 7"
      expect_line "exit"
    done
    ;;
  window-killed)
    run -- window-closed kill
    # Xlib's default I/O error handler ends the program with status 1: not a crash (no signal,
    # 128+N) and no hang (timeout: 124).
    expect_rc 1
    expect_line "closed 3"
    grep -q "X connection to .* broken\|XIO" "$work/err" || fail "no message from Xlib"
    ;;
  bad-output)
    touch "$work/file"
    run GLPT_OUTPUT="$work/file/frames" -- draw 5
    expect_rc 0
    expect_line "frames 5"
    expect_stderr_count 1 "GLPT_OUTPUT"
    expect_line "read_right 0 0 255 255"
    # A directory that exists but takes no files (not even root's): each frame's PNG fails,
    # reported once.
    run GLPT_OUTPUT=/proc/self -- draw 5
    expect_rc 0
    expect_line "frames 5"
    expect_stderr_count 1 "GLPT_OUTPUT"
    expect_line "read_right 0 0 255 255"
    ;;
  *)
    echo "unknown fault $fault" >&2
    exit 2
    ;;
esac
if [ "$failures" -ne 0 ]; then
  echo "$failures check(s) failed" >&2
  exit 1
fi
echo "ok ($fault)"
