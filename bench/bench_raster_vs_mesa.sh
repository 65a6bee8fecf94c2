#!/usr/bin/env bash
# bench_raster_vs_mesa.sh [--libgl PATH] [--size WxH] [--seconds S] [--rounds N] [--also-sync]
#
# Frame rate of the unmodified /usr/bin/glxgears drawn by real Mesa (llvmpipe, the system
# libGL) and by glpt's raster mode (GLPT_MODE=raster, LD_PRELOAD), in the same private Xvfb,
# alternating Mesa, glpt, Mesa, glpt... for N rounds. Each run counts glxgears' swaps over a
# window of S seconds after one second of warm-up (build/bench/swap_rate.so, preloaded ahead of
# the libGL, then ends the program): on a shared machine whose CPU speed drifts by tens of per
# cent within seconds, many short windows side by side compare the two libraries under the same
# conditions, where a few long runs compared different machines. Prints one line per run, the
# medians, the median of the per-round ratios glpt/Mesa with its quartiles (the spread to read
# the median against), and the command to reproduce.
#
#   --libgl PATH  glpt's libGL.so.1 (default: $GLPT_LIBGL, else <repo>/build/gl_shim/libGL.so.1)
#   --size WxH    window size (default 300x300)
#   --seconds S   counted window of each run (default 1.5)
#   --rounds N    Mesa/glpt pairs (default 12)
#   --also-sync   a third run per round: glpt with GLPT_PRESENT=sync (each swap waits for its
#                 frame to be on screen, as Mesa's does: the frames do not overlap)
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
libgl=${GLPT_LIBGL:-$repo/build/gl_shim/libGL.so.1}
swap_rate=${GLPT_SWAP_RATE:-$repo/build/bench/swap_rate.so}
size=300x300
seconds=1.5
rounds=12
also_sync=0
usage() { sed -n '2,19p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
while [ $# -gt 0 ]; do
  case $1 in
    --libgl) libgl=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --also-sync) also_sync=1; shift ;;
    -h|--help) usage; exit 0 ;;
    *) echo "bench_raster_vs_mesa: unknown argument '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
[[ $size =~ ^[1-9][0-9]*x[1-9][0-9]*$ ]] || { echo "bench_raster_vs_mesa: bad --size '$size'" >&2; exit 2; }
[[ $seconds =~ ^[0-9]*\.?[0-9]+$ ]] && awk -v s="$seconds" 'BEGIN { exit !(s > 0 && s <= 600) }' ||
  { echo "bench_raster_vs_mesa: --seconds must be a number of seconds in (0, 600]" >&2; exit 2; }
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "bench_raster_vs_mesa: bad --rounds '$rounds'" >&2; exit 2; }
libgl=$(realpath "$libgl" 2>/dev/null || echo "$libgl")
[ -f "$libgl" ] || { echo "bench_raster_vs_mesa: libGL not found: $libgl" >&2; exit 2; }
[ -f "$swap_rate" ] || { echo "bench_raster_vs_mesa: $swap_rate not built (scripts/build.sh)" >&2; exit 2; }
swap_rate=$(realpath "$swap_rate")
glxgears=${GLXGEARS:-/usr/bin/glxgears}

if [ -z "${GLPT_BENCH_UNDER_XVFB:-}" ]; then
  GLPT_BENCH_UNDER_XVFB=1 exec "$repo/tests/e2e/with_xvfb.sh" "$0" --libgl "$libgl" \
    --size "$size" --seconds "$seconds" --rounds "$rounds" $([ "$also_sync" = 1 ] && echo --also-sync)
fi

# run NAME PRELOAD ENV...: glxgears until swap_rate has counted its window; prints the rate.
run() {
  local name=$1 preload=$2
  shift 2
  local limit fps
  limit=$(awk -v s="$seconds" 'BEGIN { printf "%d", s + 60 }')
  fps=$(env GLPT_SWAP_RATE_SECONDS="$seconds" LD_PRELOAD="$preload" "$@" \
          timeout -s INT "$limit" "$glxgears" -geometry "$size" 2>&1 |
        awk -F'fps=' '/^swap_rate: / { v = $2 } END { if (v != "") print v; else print "nan" }')
  echo "$name fps=$fps" >&2
  echo "$fps"
}

mesa=()
glpt=()
sync=()
for _ in $(seq 1 "$rounds"); do
  mesa+=("$(run mesa "$swap_rate")")
  glpt+=("$(run glpt "$swap_rate $libgl" GLPT_MODE=raster GLPT_QUIET=1)")
  if [ "$also_sync" = 1 ]; then
    sync+=("$(run glpt_sync "$swap_rate $libgl" GLPT_MODE=raster GLPT_QUIET=1 GLPT_PRESENT=sync)")
  fi
done
# quantiles Q... of the numbers on stdin (nan dropped): nearest-rank, so no interpolation
quantiles() {
  grep -v nan | sort -g | awk -v qs="$*" '{ v[NR] = $1 } END {
    n = split(qs, q, " ");
    for (i = 1; i <= n; ++i) { r = int(q[i] * (NR - 1) + 0.5) + 1; printf "%s%s", (i > 1 ? " " : ""), (NR ? v[r] : "nan") }
    print "" }'
}
ratios() {  # per-round ratios of two lists given as "a1 a2 ..." "b1 b2 ..."
  awk -v a="$1" -v b="$2" 'BEGIN { n = split(a, x, " "); split(b, y, " ");
    for (i = 1; i <= n; ++i) if (x[i] != "nan" && y[i] != "nan" && y[i] > 0) printf "%.4f\n", x[i] / y[i] }'
}
m=$(printf '%s\n' "${mesa[@]}" | quantiles 0.5)
g=$(printf '%s\n' "${glpt[@]}" | quantiles 0.5)
read -r q1 q2 q3 < <(ratios "${glpt[*]}" "${mesa[*]}" | quantiles 0.25 0.5 0.75)
echo "glxgears ${size}: Mesa llvmpipe median ${m} FPS, glpt raster median ${g} FPS;" \
  "per-round glpt/Mesa median ${q2} (quartiles ${q1} .. ${q3}, ${rounds} rounds of ${seconds} s)"
if [ "$also_sync" = 1 ]; then
  s=$(printf '%s\n' "${sync[@]}" | quantiles 0.5)
  read -r r1 r2 r3 < <(ratios "${sync[*]}" "${mesa[*]}" | quantiles 0.25 0.5 0.75)
  echo "glpt with GLPT_PRESENT=sync: median ${s} FPS, per-round glpt/Mesa median ${r2} (quartiles ${r1} .. ${r3})"
fi
echo "reproduce: bench/bench_raster_vs_mesa.sh --size $size --seconds $seconds --rounds $rounds$([ "$also_sync" = 1 ] && echo ' --also-sync')"
