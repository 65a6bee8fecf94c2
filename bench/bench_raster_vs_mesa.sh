#!/usr/bin/env bash
# bench_raster_vs_mesa.sh [--libgl PATH] [--size WxH] [--seconds S] [--rounds N] [--also-sync]
#
# Frame rate of the unmodified /usr/bin/glxgears drawn by real Mesa (llvmpipe, the system
# libGL) and by glpt's raster mode (GLPT_MODE=raster, LD_PRELOAD), in the same private Xvfb,
# alternating A, B, A, B... for N rounds of S seconds each, so both see the same machine load.
# glxgears reports its own frame rate every 5 seconds ("N frames in 5.0 seconds = F FPS"); the
# first report of each run is skipped (start-up, pipeline compilation) and the rest are averaged.
# Prints one line per run, the medians, the ratio glpt/Mesa, and the command to reproduce.
#
#   --libgl PATH  glpt's libGL.so.1 (default: $GLPT_LIBGL, else <repo>/build/gl_shim/libGL.so.1)
#   --size WxH    window size (default 300x300)
#   --seconds S   length of each run (default 16: three reports, two of them measured)
#   --rounds N    A/B pairs (default 3)
#   --also-sync   a third run per round: glpt with GLPT_PRESENT=sync (each swap waits for its
#                 frame to be on screen, as Mesa's does: the frames do not overlap)
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
libgl=${GLPT_LIBGL:-$repo/build/gl_shim/libGL.so.1}
size=300x300
seconds=16
rounds=3
also_sync=0
usage() { sed -n '2,17p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; }
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
[[ $seconds =~ ^[1-9][0-9]*$ && $seconds -ge 11 ]] ||
  { echo "bench_raster_vs_mesa: --seconds must be >= 11 (two glxgears reports)" >&2; exit 2; }
[[ $rounds =~ ^[1-9][0-9]*$ ]] || { echo "bench_raster_vs_mesa: bad --rounds '$rounds'" >&2; exit 2; }
libgl=$(realpath "$libgl" 2>/dev/null || echo "$libgl")
[ -f "$libgl" ] || { echo "bench_raster_vs_mesa: libGL not found: $libgl" >&2; exit 2; }
glxgears=${GLXGEARS:-/usr/bin/glxgears}

if [ -z "${GLPT_BENCH_UNDER_XVFB:-}" ]; then
  GLPT_BENCH_UNDER_XVFB=1 exec "$repo/tests/e2e/with_xvfb.sh" "$0" --libgl "$libgl" \
    --size "$size" --seconds "$seconds" --rounds "$rounds" $([ "$also_sync" = 1 ] && echo --also-sync)
fi

# run NAME ENV...: glxgears for $seconds s; prints the mean of its FPS reports after the first.
run() {
  local name=$1
  shift
  local log
  log=$(mktemp)
  timeout -s INT "$seconds" env "$@" "$glxgears" -geometry "$size" >"$log" 2>&1 || true
  local fps
  fps=$(awk '/frames in .* seconds =/ { n++; if (n > 1) { sum += $(NF-1); m++ } }
             END { if (m > 0) printf "%.1f", sum / m; else print "nan" }' "$log")
  echo "$name fps=$fps" >&2
  rm -f "$log"
  echo "$fps"
}

mesa=()
glpt=()
sync=()
for _ in $(seq 1 "$rounds"); do
  mesa+=("$(run mesa)")
  glpt+=("$(run glpt LD_PRELOAD="$libgl" GLPT_MODE=raster GLPT_QUIET=1)")
  if [ "$also_sync" = 1 ]; then
    sync+=("$(run glpt_sync LD_PRELOAD="$libgl" GLPT_MODE=raster GLPT_QUIET=1 GLPT_PRESENT=sync)")
  fi
done
median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
m=$(median "${mesa[@]}")
g=$(median "${glpt[@]}")
ratio=$(awk -v g="$g" -v m="$m" 'BEGIN { if (m > 0) printf "%.2f", g / m; else print "nan" }')
echo "glxgears ${size}: Mesa llvmpipe median ${m} FPS (${mesa[*]}), glpt raster median ${g} FPS (${glpt[*]}), glpt/Mesa = ${ratio}"
if [ "$also_sync" = 1 ]; then
  s=$(median "${sync[@]}")
  echo "glpt with GLPT_PRESENT=sync: median ${s} FPS (${sync[*]}), glpt/Mesa = $(awk -v g="$s" -v m="$m" 'BEGIN { if (m > 0) printf "%.2f", g / m; else print "nan" }')"
fi
echo "reproduce: bench/bench_raster_vs_mesa.sh --size $size --seconds $seconds --rounds $rounds$([ "$also_sync" = 1 ] && echo ' --also-sync')"
