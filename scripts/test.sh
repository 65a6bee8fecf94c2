#!/usr/bin/env bash
# Installs what is needed, builds, and runs every test (ctest). This is what CI runs.
#
#   scripts/test.sh              the normal build (build/)
#   scripts/test.sh --sanitize   every test built with AddressSanitizer and
#                                UndefinedBehaviorSanitizer instead (build-asan/, scripts/sanitize.sh)
#   scripts/test.sh --validation every test with GLPT_VALIDATION=1: the Khronos validation layer
#                                with synchronization validation in every process; any message
#                                fails the run (all are collected in build/validation.log)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
sanitize=0
validation=0
for arg in "$@"; do
  case $arg in
    --sanitize) sanitize=1 ;;
    --validation) validation=1 ;;
    -h|--help) sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "test.sh: unknown argument '$arg' (see --help)" >&2; exit 2 ;;
  esac
done
bash "$root/scripts/setup.sh"
if [ "$sanitize" = 1 ]; then
  exec bash "$root/scripts/sanitize.sh"
fi
bash "$root/scripts/build.sh"
build=${GLPT_BUILD_DIR:-$root/build}
if [ "$validation" = 1 ]; then
  # Every Vulkan device any test process creates (the test binaries, glpt-replay, programs with
  # libGL.so.1 preloaded) reads these; tests that set GLPT_VALIDATION themselves keep theirs. The
  # layer makes lavapipe several times slower, hence the longer default timeout.
  log="$build/validation.log"
  : >"$log"
  status=0
  GLPT_VALIDATION=1 GLPT_VALIDATION_LOG="$log" \
    ctest --test-dir "$build" --output-on-failure -j 2 --timeout 1800 || status=$?
  if [ -s "$log" ]; then
    echo "test.sh --validation: $(wc -l <"$log") validation messages; by program and message id:"
    cut -d' ' -f2- "$log" | sed 's/\] \([^:]*\):.*/] \1/' | sort | uniq -c | sort -rn | head -40
    echo "(all of them: $log)"
    exit 1
  fi
  echo "test.sh --validation: no validation message"
  exit "$status"
fi
ctest --test-dir "$build" --output-on-failure -j 2 --timeout 600
