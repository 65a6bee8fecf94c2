#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test (ctest). This is what CI runs.
#
#   scripts/test.sh              the normal build (build/)
#   scripts/test.sh --sanitize   every test built with AddressSanitizer and
#                                UndefinedBehaviorSanitizer instead (build-asan/, scripts/sanitize.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
sanitize=0
for arg in "$@"; do
  case $arg in
    --sanitize) sanitize=1 ;;
    -h|--help) sed -n '2,6p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "test.sh: unknown argument '$arg' (see --help)" >&2; exit 2 ;;
  esac
done
bash "$root/scripts/setup.sh"
if [ "$sanitize" = 1 ]; then
  exec bash "$root/scripts/sanitize.sh"
fi
bash "$root/scripts/build.sh"
build=${GLPT_BUILD_DIR:-$root/build}
ctest --test-dir "$build" --output-on-failure -j 2 --timeout 600
