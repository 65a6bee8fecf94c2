#!/usr/bin/env bash
# ab_denoiser_builds.sh BASE_BUILD_DIR NEW_BUILD_DIR [ROUNDS] [glxgears|lit_scene]
#
# The denoiser's device time on glxgears (320x240 and 640x480, 25 s each, accumulation off) or
# on bench/lit_scene (lit geometry over the whole window, 12 frames; the new build's program) for
# two builds of glpt, alternating run by run so both see the same machine: per run the median
# trace_ms, denoise_ms, composite_ms and taa_ms (GLPT_STATS, Vulkan timestamps; taa_ms 0 for
# builds without the anti-aliasing pass) and the frames counted. For changes to
# the denoiser (docs/denoiser.md, "Cost"); bench_denoiser.sh measures one build in full.
set -u
base=${1:?base build dir}
new=${2:?new build dir}
rounds=${3:-3}
scene=${4:-glxgears}
echo "command: $0 $base $new $rounds $scene"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
display=:$((200 + RANDOM % 100))
Xvfb $display -screen 0 1280x1024x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb' EXIT
sleep 1
# A pipeline cache per build: builds with different shaders alternating in one cache would
# rewrite it every run, and each run would compile the trace pass anew (20 s on a 2-core machine).
caches=$(mktemp -d)
trap 'kill $xvfb; rm -rf "$caches"' EXIT
run() {
  local libgl=$1 size=$2 log
  log=$(mktemp)
  env DISPLAY=$display LD_PRELOAD=$libgl GLPT_STATS=1 GLPT_ACCUMULATE=0 GLPT_QUIET=1 \
    GLPT_CACHE_DIR="$caches/$(echo "$libgl" | md5sum | cut -c1-8)" \
    $(if [ "$scene" = lit_scene ]; then echo "$new/bench/lit_scene --frames 12 --size $size"
      else echo "timeout -s INT 25 /usr/bin/glxgears -geometry $size"; fi) 2>"$log" >/dev/null
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
      printf "%.2f %.2f %.2f %.2f %d\n", median(trace, n), median(denoise, n), median(composite, n),
        median(taa, n), n
    }' "$log"
  rm -f "$log"
}
echo "round size build trace_ms denoise_ms composite_ms taa_ms frames"
# One run of each build first, not reported: it fills the build's pipeline cache.
for build in "$base" "$new"; do run "$build/gl_shim/libGL.so.1" 320x240 >/dev/null; done
for ((round = 1; round <= rounds; ++round)); do
  for size in 320x240 640x480; do
    echo "$round $size base $(run "$base/gl_shim/libGL.so.1" $size)"
    echo "$round $size new  $(run "$new/gl_shim/libGL.so.1" $size)"
  done
done
