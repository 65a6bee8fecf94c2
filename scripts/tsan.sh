#!/usr/bin/env bash
# Builds the tests labelled `threading` (contexts on several threads, GLX and EGL from several
# threads, contexts destroyed while current elsewhere) with ThreadSanitizer into build-tsan/ (or
# $GLPT_BUILD_DIR) and runs them; any report fails its test. Only those tests and the libraries
# they link are built. Assumes scripts/setup.sh has run.
#
# lavapipe, libX11 and the Vulkan loader are not instrumented: their own accesses are invisible
# to ThreadSanitizer, but the locks and threads they take are intercepted, so glpt's accesses on
# either side of them are still ordered correctly. Races inside lavapipe itself (no glpt frame in
# either stack) are suppressed: tests/tsan.supp says which and why.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${GLPT_BUILD_DIR:-$root/build-tsan}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG" \
  -DGLPT_SANITIZE=thread >/dev/null
cmake --build "$build" -j "$(nproc)" --target glpt_threading_tests glpt_egl_tests glpt_glx_tests \
  glpt_c_abi_tests
# A forked child that exits runs lavapipe's exit handler, which joins driver threads that only
# the parent has: under ThreadSanitizer that join waits forever (without it, it returns). The
# test exists for the parent's sake (ASan and the normal build run it).
export GTEST_FILTER=${GTEST_FILTER:--Egl.ForkedChildExitingLeavesTheParentPresenting}
export TSAN_OPTIONS=${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1:suppressions=$root/tests/tsan.supp}
ctest --test-dir "$build" --output-on-failure -j 2 --timeout 600 -L threading "$@"
