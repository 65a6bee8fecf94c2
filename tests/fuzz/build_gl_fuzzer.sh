#!/usr/bin/env bash
# Builds the GL call fuzzer (gl_call_fuzz.cpp) with clang (the project itself builds with g++):
#   tests/fuzz/build_gl_fuzzer.sh OUTPUT GENERATED_DIR CALLS_INC SOURCE...
# GENERATED_DIR: the build's generated/ (gl_enums.h, gl_shim/gl_entry_*); CALLS_INC: the command
# table gen_gl_fuzz_calls.py wrote; SOURCE...: the front-end sources (tests/fuzz/CMakeLists.txt
# passes glpt_gl_front's, less GLX and EGL). Objects go to OUTPUT.objects/, built by a ninja file
# written there: parallel, and incremental (a rebuild compiles only what changed).
# Then e.g. `OUTPUT -max_total_time=600 NEW_DIR tests/fuzz/gl_corpus` fuzzes for longer.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:?usage: build_gl_fuzzer.sh OUTPUT GENERATED_DIR CALLS_INC SOURCE...}
generated=$(realpath "${2:?}") calls_inc=${3:?}
shift 3
objdir=$out.objects
mkdir -p "$objdir/include"
cp -p "$calls_inc" "$objdir/include/gl_fuzz_calls.inc.new"
# Replaced only when it changed, so that ninja recompiles the harness only then.
if cmp -s "$objdir/include/gl_fuzz_calls.inc.new" "$objdir/include/gl_fuzz_calls.inc"; then
  rm "$objdir/include/gl_fuzz_calls.inc.new"
else
  mv "$objdir/include/gl_fuzz_calls.inc.new" "$objdir/include/gl_fuzz_calls.inc"
fi
clangxx=${CLANGXX:-clang++}
# -Iinclude: relative to the object directory (ninja runs there), so the flags do not depend on
# where it is. -O1 -g1 as scripts/sanitize.sh's build: line numbers in reports at half the
# compile time of -O2 -g. The front end's own options (gl_shim/CMakeLists.txt): no FMA contraction.
flags="-std=c++20 -g1 -Wall -Wextra -Werror -Wno-unused-command-line-argument \
-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer \
-ffp-contract=off -I$root -I$generated -Iinclude -DGLPT_VERSION_STRING=\\\"fuzz\\\""
{
  # The generated entry points (thin wrappers, one per GL command) at -O0: at -O1 that one file
  # takes 160 s of CPU, a third of the whole build; at -O0 14 s.
  for opt in O1 O0; do
    echo "rule cxx_$opt"
    echo "  command = $clangxx $flags -$opt -MMD -MF \$out.d -c \$in -o \$out"
    echo "  depfile = \$out.d"
    echo "  deps = gcc"
    echo "  description = fuzzer: \$in"
  done
  echo "rule link"
  echo "  command = $clangxx -fsanitize=fuzzer,address,undefined \$in -lpthread -o \$out"
  echo "  description = fuzzer: linking \$out"
  objects=()
  for src in "$@" "$root/tests/fuzz/gl_call_fuzz.cpp" "$root/tests/fuzz/gl_fuzz_no_renderer.cpp"; do
    src=$(realpath "$src")
    obj=$(echo "${src#/}" | tr / _).o
    objects+=("$obj")
    opt=O1
    [[ $src == */gl_shim/gl_entry_points.cpp ]] && opt=O0
    echo "build $obj: cxx_$opt $src"
  done
  echo "build $(realpath -m "$out"): link ${objects[*]}"
} >"$objdir/build.ninja.new"
if ! cmp -s "$objdir/build.ninja.new" "$objdir/build.ninja"; then
  mv "$objdir/build.ninja.new" "$objdir/build.ninja"
else
  rm "$objdir/build.ninja.new"
fi
ninja -C "$objdir" -j "${GLPT_FUZZ_JOBS:-$(nproc)}"
