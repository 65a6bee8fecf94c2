#!/usr/bin/env bash
# bench_shards.sh --trace FILE [--shards N] [--modes "raster path"] [--frames LIST]
#
# What sharding saves (docs/replay.md, "Sharding"): for each mode, the wall time of one whole
# replay of the trace's frames (glpt-replay --frames LIST, default all), of each of N shards
# (--shard i/N, default N 3) and of a replay that renders no frame at all (the state replay every
# shard pays), run one after the other on this machine; then the largest shard's time against
# whole / N + state replay, and whether the N shards' frames equal the whole replay's byte for
# byte. Without --trace, records the xscreensaver hack `gears` (EGL, 320 frames) with apitrace
# in a private Xvfb. Not a test.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${GLPT_BUILD_DIR:-$repo/build}
replay=$build/replay/glpt-replay
trace=""
shards=3
modes="raster path"
frames=""
while [ $# -gt 0 ]; do
  case $1 in
    --trace) trace=$(realpath "$2"); shift 2 ;;
    --shards) shards=$2; shift 2 ;;
    --modes) modes=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    -h|--help) sed -n '2,10p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench_shards: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
[ -x "$replay" ] || { echo "bench_shards: build first ($replay)" >&2; exit 2; }
work=$(mktemp -d /tmp/glpt-shards.XXXXXX)
trap 'rm -rf "$work"' EXIT
if [ -z "$trace" ]; then
  trace=$work/gears.trace
  hack=/usr/libexec/xscreensaver/gears
  [ -x "$hack" ] || { echo "bench_shards: needs xscreensaver-gl (or --trace)" >&2; exit 2; }
  echo "recording $hack (apitrace, EGL) ..." >&2
  # Recorded until the trace holds 320 frames (the hack runs at about 20 frames a second here).
  timeout -s INT 25 "$repo/tests/e2e/with_xvfb.sh" apitrace trace --api egl -o "$trace" \
    "$hack" -window >/dev/null 2>&1 || true
  frames=${frames:-0-319}
fi
echo "command: bench/bench_shards.sh --trace $trace --shards $shards --modes \"$modes\"${frames:+ --frames $frames}"
seconds() {  # seconds of one glpt-replay run
  local start end
  start=$(date +%s.%N)
  "$replay" "$trace" --quiet "$@" >/dev/null 2>"$work/err" || { cat "$work/err" >&2; exit 1; }
  end=$(date +%s.%N)
  python3 -c "print(round($end - $start, 2))"
}
select=()
[ -n "$frames" ] && select=(--frames "$frames")
printf '%-7s %9s %9s %s %12s %9s\n' mode whole_s state_s "shards_s" "bound_s" identical
for mode in $modes; do
  rm -rf "$work/whole" "$work/shards"
  whole=$(seconds --mode "$mode" "${select[@]}" --out "$work/whole")
  state=$(seconds --mode "$mode" --frames 1000000000)
  times=()
  for ((i = 0; i < shards; ++i)); do
    times+=("$(seconds --mode "$mode" "${select[@]}" --shard "$i/$shards" --out "$work/shards")")
  done
  same=yes
  for f in "$work"/whole/*.png; do
    cmp -s "$f" "$work/shards/$(basename "$f")" || { same=no; break; }
  done
  [ "$(ls "$work/whole" | wc -l)" = "$(ls "$work/shards" | wc -l)" ] || same=no
  bound=$(python3 -c "print(round($whole / $shards + $state, 2))")
  printf '%-7s %9.2f %9.2f %s %12.2f %9s\n' "$mode" "$whole" "$state" "${times[*]}" "$bound" "$same"
  echo "  frames: $(ls "$work/whole" | wc -l)" >&2
done
