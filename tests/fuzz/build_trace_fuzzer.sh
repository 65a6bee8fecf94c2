#!/usr/bin/env bash
# Builds the trace reader's libFuzzer target with clang (the project itself builds with g++):
#   tests/fuzz/build_trace_fuzzer.sh OUTPUT
# then e.g. `OUTPUT -max_total_time=600 NEW_DIR tests/fuzz/trace_corpus` to fuzz for longer
# (libFuzzer adds the inputs it finds to the first directory; keep the committed corpus second).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:?usage: build_trace_fuzzer.sh OUTPUT}
clangxx=${CLANGXX:-clang++}
# shellcheck disable=SC2046
"$clangxx" -std=c++20 -g -O1 -Wall -Wextra -Werror \
  -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer \
  -I"$root" \
  "$root"/replay/trace/trace_container.cpp "$root"/replay/trace/trace_model.cpp \
  "$root"/replay/trace/trace_reader.cpp "$root"/tests/fuzz/trace_reader_fuzz.cpp \
  $(pkg-config --cflags --libs snappy libbrotlidec zlib) -o "$out"
