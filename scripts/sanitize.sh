#!/usr/bin/env bash
# Builds glpt with AddressSanitizer and UndefinedBehaviorSanitizer into build-asan/ (or
# $GLPT_BUILD_DIR) and runs every test there. Any sanitizer report fails the test that caused it
# (-fno-sanitize-recover). Assumes scripts/setup.sh has run.
#
# The e2e tests LD_PRELOAD libGL.so.1 into unmodified programs, which are not built with ASan, so
# the runtime is preloaded into every test process too (it must come before libGL).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${GLPT_BUILD_DIR:-$root/build-asan}
# -O1 with line tables only: reports keep file and line, and the build takes less than half the
# time of -O2 -g (measured on rt_core/scene/classify.cpp: 8.7 s against 20.0 s).
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DGLPT_SANITIZE=address,undefined >/dev/null
cmake --build "$build" -j "$(nproc)"
runtime="$(gcc -print-file-name=libasan.so):$(gcc -print-file-name=libubsan.so)"
# Leaks: lavapipe and the Vulkan loader keep allocations for the life of the process, so leak
# checking reports theirs; glpt's own objects are RAII and checked by the unit tests' expectations.
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=0:verify_asan_link_order=0:abort_on_error=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
LD_PRELOAD="$runtime${LD_PRELOAD:+:$LD_PRELOAD}" \
  ctest --test-dir "$build" --output-on-failure -j 2 --timeout 1200 "$@"
