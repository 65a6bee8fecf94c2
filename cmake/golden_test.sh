#!/usr/bin/env bash
# golden_test.sh GLPT_REPLAY GLPT TRACE FRAMES THRESHOLD GOLDEN_DIR WORK_DIR MODE [REPLAY ARGS...]
#
# The command behind glpt_add_golden_test (GlptGolden.cmake, installed beside it): replays TRACE's frames FRAMES
# in MODE into WORK_DIR/frames and compares them with GOLDEN_DIR by `glpt diff --threshold`.
# With GLPT_UPDATE_GOLDENS=1 the replayed frames replace GOLDEN_DIR's instead.
set -euo pipefail
if [ $# -lt 8 ]; then
  echo "usage: golden_test.sh GLPT_REPLAY GLPT TRACE FRAMES THRESHOLD GOLDEN_DIR WORK_DIR MODE [ARGS...]" >&2
  exit 2
fi
replay=$1 glpt=$2 trace=$3 frames=$4 threshold=$5 golden=$6 work=$7 mode=$8
shift 8
rm -rf "$work"
mkdir -p "$work/frames"
"$replay" --quiet --mode "$mode" --frames "$frames" --out "$work/frames" "$@" "$trace" >"$work/replay.log" 2>&1 || {
  echo "golden_test: glpt-replay failed; its output:" >&2
  tail -n 20 "$work/replay.log" >&2
  exit 1
}
if [ "${GLPT_UPDATE_GOLDENS:-0}" = 1 ]; then
  rm -rf "$golden"
  mkdir -p "$golden"
  cp "$work"/frames/*.png "$golden"/
  echo "golden_test: updated $golden ($(ls "$golden" | wc -l) images)"
  exit 0
fi
if [ ! -d "$golden" ]; then
  echo "golden_test: no goldens in $golden (create them with GLPT_UPDATE_GOLDENS=1 ctest -L golden)" >&2
  exit 1
fi
# Every golden must be replayed and every replayed frame must have a golden (unmatched names fail).
"$glpt" diff "$golden" "$work/frames" --threshold "$threshold" --heatmap "$work/heatmaps"
