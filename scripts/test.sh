#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test (ctest). This is what CI runs.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
bash "$root/scripts/build.sh"
build=${GLPT_BUILD_DIR:-$root/build}
ctest --test-dir "$build" --output-on-failure -j 2 --timeout 600
