#!/usr/bin/env bash
# ctest's trace.fuzz: runs the fuzzer for a few seconds from the committed seed corpus, writing
# what it finds to a scratch directory (the committed corpus is never modified).
#   run_trace_fuzzer.sh FUZZER CORPUS SECONDS
set -euo pipefail
fuzzer=$1 corpus=$2 seconds=$3
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# The reader holds at most 512 MiB of strings and blobs per call (kMaxBytesPerCall), which a
# string may grow to twice that in capacity: the limits leave room for it and ASan.
# The fuzzer carries clang's sanitizer runtimes; scripts/sanitize.sh preloads GCC's for the other
# tests, which clang's ASan refuses to run beside ("incompatible ASan runtimes").
env -u LD_PRELOAD "$fuzzer" -max_total_time="$seconds" -rss_limit_mb=3072 -malloc_limit_mb=1200 -max_len=16384 -timeout=10 \
  -print_final_stats=1 -artifact_prefix="${TRACE_FUZZ_ARTIFACTS:-$PWD}/trace-fuzz-" "$scratch" "$corpus"
