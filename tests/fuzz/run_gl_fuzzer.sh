#!/usr/bin/env bash
# ctest's gl.fuzz: runs the GL call fuzzer for a few seconds from the committed seed corpus,
# writing what it finds to a scratch directory (the committed corpus is never modified).
#   run_gl_fuzzer.sh FUZZER CORPUS SECONDS
set -euo pipefail
fuzzer=$1 corpus=$2 seconds=$3
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# -max_len: a few hundred calls an input. -timeout: one input's calls take milliseconds; seconds
# mean a hang. The fuzzer carries clang's sanitizer runtimes, which GCC's (preloaded by
# scripts/sanitize.sh for the other tests) refuse to run beside. GLPT_QUIET: one line per
# unimplemented command and input would bury the fuzzer's own output.
env -u LD_PRELOAD GLPT_QUIET=1 "$fuzzer" -max_total_time="$seconds" -rss_limit_mb=3072 -malloc_limit_mb=1024 \
  -max_len=4096 -timeout=10 -print_final_stats=1 \
  -artifact_prefix="${GL_FUZZ_ARTIFACTS:-$PWD}/gl-fuzz-" "$scratch" "$corpus"
