#!/usr/bin/env bash
# bench_denoiser.sh [--frames F] [--rounds N] [--default-only]
#
# What the SVGF denoiser costs (docs/denoiser.md, "Cost"): for glxgears (gears over a cleared
# background: few shaded pixels) and bench/lit_scene (lit geometry over the whole window), at
# 320x240 and 640x480, the median device time per frame of the trace pass, the denoiser (its
# temporal pass and a-trous iterations), the composite pass and the temporal anti-aliasing pass
# (Vulkan timestamps, GLPT_STATS), and the denoiser's cost (with its anti-aliasing) as a fraction
# of the trace's. Runs in a private Xvfb; accumulation off
# (every frame traces and denoises); the two sizes alternate round by round.
#
#   --frames F    frames per lit_scene run (default 12; the first three are not counted)
#   --rounds N    runs per measurement (default 2)
#   --default-only  the default settings only (not also the 3x3 and 5x5 a-trous kernels)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${GLPT_BUILD_DIR:-$repo/build}
frames=12
rounds=2
variants=("" "GLPT_DENOISE_KERNEL=1" "GLPT_DENOISE_KERNEL=2")
while [ $# -gt 0 ]; do
  case $1 in
    --frames) frames=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --default-only) variants=(""); shift ;;
    -h|--help) sed -n '2,14p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench_denoiser: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
libgl=$build/gl_shim/libGL.so.1
lit_scene=$build/bench/lit_scene
[ -f "$libgl" ] && [ -x "$lit_scene" ] ||
  { echo "bench_denoiser: build first (scripts/build.sh)" >&2; exit 2; }

display=:$((200 + RANDOM % 100))
Xvfb "$display" -screen 0 1280x1024x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
sleep 1

# run SETTINGS PROGRAM ARGS...: prints "trace_ms denoise_ms composite_ms taa_ms" (medians).
run() {
  local settings=$1
  shift
  local log
  log=$(mktemp)
  env DISPLAY="$display" LD_PRELOAD="$libgl" GLPT_STATS=1 GLPT_ACCUMULATE=0 GLPT_QUIET=1 \
    $settings "$@" 2>"$log" >/dev/null || true
  awk -v skip=3 '
    /^glpt: frame=/ {
      for (i = 1; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
      if (v["trace_ms"] + 0 == 0) next
      if (seen++ < skip) next
      trace[n] = v["trace_ms"]; denoise[n] = v["denoise_ms"]; composite[n] = v["composite_ms"]
      taa[n] = v["taa_ms"] + 0; ++n
    }
    function median(a, n,   i, j, t) {
      for (i = 0; i < n; ++i) for (j = i + 1; j < n; ++j) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
      return n ? (n % 2 ? a[int(n / 2)] : (a[n / 2 - 1] + a[n / 2]) / 2) : 0
    }
    END {
      printf "%.2f %.2f %.2f %.2f\n", median(trace, n), median(denoise, n), median(composite, n),
        median(taa, n)
    }' "$log"
  rm -f "$log"
}

median_of() { tr ' ' '\n' | sort -g | awk '{a[NR]=$1} END {print NR % 2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "command: $0 --frames $frames --rounds $rounds$([ ${#variants[@]} -eq 1 ] && echo ' --default-only')"
printf '%-10s %-8s %-12s %10s %11s %13s %8s %14s\n' scene size settings trace_ms denoise_ms \
  composite_ms taa_ms \(den+taa\)/trace
for scene in glxgears lit_scene; do
  for settings in "${variants[@]}"; do
    declare -A traces=() denoises=() composites=() taas=()
    for ((round = 0; round < rounds; ++round)); do
      for size in 320x240 640x480; do
        if [ "$scene" = glxgears ]; then
          result=$(run "$settings" timeout -s INT 25 /usr/bin/glxgears -geometry "$size")
        else
          result=$(run "$settings" "$lit_scene" --frames "$frames" --size "$size")
        fi
        read -r tr dn co ta <<<"$result"
        traces[$size]+="$tr "
        denoises[$size]+="$dn "
        composites[$size]+="$co "
        taas[$size]+="$ta "
      done
    done
    for size in 320x240 640x480; do
      tr=$(median_of <<<"${traces[$size]% }")
      dn=$(median_of <<<"${denoises[$size]% }")
      co=$(median_of <<<"${composites[$size]% }")
      ta=$(median_of <<<"${taas[$size]% }")
      printf '%-10s %-8s %-12s %10s %11s %13s %8s %14s\n' "$scene" "$size" \
        "${settings:-default}" "$tr" "$dn" "$co" "$ta" \
        "$(awk -v a="$dn" -v t="$ta" -v b="$tr" 'BEGIN { printf "%.2f", (b > 0 ? (a + t) / b : 0) }')"
    done
  done
done
