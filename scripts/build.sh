#!/usr/bin/env bash
# Configures and builds glpt into build/ (or $GLPT_BUILD_DIR), Release unless $GLPT_BUILD_TYPE says
# otherwise (Debug, RelWithDebInfo, MinSizeRel: all build warning-free with GCC 12 and Clang 14).
# Assumes scripts/setup.sh has run.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${GLPT_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=${GLPT_BUILD_TYPE:-Release} >/dev/null
cmake --build "$build" -j "$(nproc)"
echo "build: libGL.so.1 at $build/gl_shim/libGL.so.1"
