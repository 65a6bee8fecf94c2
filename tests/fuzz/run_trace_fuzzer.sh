#!/usr/bin/env bash
# ctest's trace.fuzz: runs the fuzzer for a few seconds from the committed seed corpus, writing
# what it finds to a scratch directory (the committed corpus is never modified).
#   run_trace_fuzzer.sh FUZZER CORPUS SECONDS
set -euo pipefail
fuzzer=$1 corpus=$2 seconds=$3
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# -rss_limit_mb: the reader's own limits keep any input far below it.
"$fuzzer" -max_total_time="$seconds" -rss_limit_mb=1024 -max_len=16384 -timeout=10 \
  -print_final_stats=1 -artifact_prefix="${TRACE_FUZZ_ARTIFACTS:-$PWD}/trace-fuzz-" "$scratch" "$corpus"
