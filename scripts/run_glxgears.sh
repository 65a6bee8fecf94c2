#!/usr/bin/env bash
# The main job: install, build, then run the unmodified /usr/bin/glxgears path-traced through
# glpt's libGL.so.1 in a private Xvfb, writing every frame as PNG.
#
#   scripts/run_glxgears.sh [FRAMES] [WxH]        (defaults: 30 frames, 300x300)
#   GLPT_OUTPUT=DIR to choose where the PNGs go (default: out/glxgears)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
frames=${1:-30}
size=${2:-300x300}
out=${GLPT_OUTPUT:-$root/out/glxgears}

bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh"
build=${GLPT_BUILD_DIR:-$root/build}

rm -rf "$out"
mkdir -p "$out"
echo "run: glxgears -geometry $size, $frames frames, path-traced by glpt (GLPT_STATS on)"
GLPT_OUTPUT="$out" GLPT_STATS=1 "$root/tests/e2e/with_xvfb.sh" \
  "$root/scripts/run_until_frames.sh" "$out" "$frames" "$build/tests/tools/x_send_key" \
  env LD_PRELOAD="$build/gl_shim/libGL.so.1" /usr/bin/glxgears -geometry "$size"
n=$(find "$out" -name 'frame_*.png' | wc -l)
echo "run: $n frames written to $out (last: $(ls "$out" | sort | tail -n 1))"
