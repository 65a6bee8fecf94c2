#!/usr/bin/env bash
# bench_ray_ceiling.sh [--frames F] [--size WxH] [--rounds N] [--reps R] [--scenes "LIST"]
#
# Distance to the limit (docs/ray-ceiling.md): the rays per second glpt's trace pass achieves
# inside a path-traced frame (GLPT_STATS: rays / trace_ms, median over the frames after the
# second, GLPT_ACCUMULATE=0, default settings) against the same scene's rays traced by a bare
# ray-query compute shader on the same Vulkan device (lavapipe) and by Embree 3 with 2 threads
# (bench/ray_ceiling, on the frame GLPT_DUMP_SCENE wrote in the same run). Each round runs every
# scene once, glpt then the microbenchmark, so both sides of a ratio see the same machine load;
# the table gives medians over the rounds. Runs in a private Xvfb. Prints the machine, the
# command, one line per run and the table.
#
#   --frames F    frames per glpt run (default 12; the first two are not counted)
#   --size WxH    lit_scene's window (default 320x240; glxgears uses its own 300x300)
#   --rounds N    rounds (default 3)
#   --reps R      timed repetitions per tracer in the microbenchmark (default 5)
#   --scenes L    from: lit1 (lit_scene, 1 light), lit100 (lit_scene, 100 lights), gears
#                 (glxgears) (default "lit1 lit100")
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${GLPT_BUILD_DIR:-$repo/build}
frames=12
size=320x240
rounds=3
reps=5
scenes="lit1 lit100"
while [ $# -gt 0 ]; do
  case $1 in
    --frames) frames=$2; shift 2 ;;
    --size) size=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    --scenes) scenes=$2; shift 2 ;;
    -h|--help) sed -n '2,19p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "bench_ray_ceiling: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
libgl=$build/gl_shim/libGL.so.1
lit_scene=$build/bench/lit_scene
ceiling=$build/bench/ray_ceiling/ray_ceiling
[ -f "$libgl" ] && [ -x "$lit_scene" ] && [ -x "$ceiling" ] ||
  { echo "bench_ray_ceiling: build first (scripts/build.sh; ray_ceiling needs libembree-dev)" >&2; exit 2; }

work=$(mktemp -d)
display=:$((200 + RANDOM % 100))
Xvfb "$display" -screen 0 1024x768x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true; rm -rf "$work"' EXIT
sleep 1

# glpt SCENE DUMP: runs SCENE under glpt, writes its 3rd traced frame to DUMP; prints the median
# Mrays/s inside the frame (rays / trace_ms) over the frames after the second.
glpt() {
  local scene=$1 dump=$2 log=$work/glpt.log
  local -a cmd
  case $scene in
    lit1) cmd=("$lit_scene" --frames "$frames" --size "$size" --lights 1) ;;
    lit100) cmd=("$lit_scene" --frames "$frames" --size "$size" --lights 100) ;;
    gears) cmd=(timeout -s INT 25 /usr/bin/glxgears) ;;
    *) echo "bench_ray_ceiling: unknown scene '$scene'" >&2; exit 2 ;;
  esac
  env DISPLAY="$display" LD_PRELOAD="$libgl" GLPT_STATS=1 GLPT_ACCUMULATE=0 GLPT_QUIET=1 \
    GLPT_DUMP_SCENE="$dump" "${cmd[@]}" 2>"$log" >/dev/null || true
  awk -v skip=2 '
    /^glpt: frame=/ {
      for (i = 1; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
      if (v["trace_ms"] + 0 == 0 || v["rays"] + 0 == 0) next
      if (seen++ < skip) next
      rate[n++] = v["rays"] / v["trace_ms"] / 1000
    }
    function median(a, n,   i, j, t) {
      for (i = 0; i < n; ++i) for (j = i + 1; j < n; ++j) if (a[j] < a[i]) { t = a[i]; a[i] = a[j]; a[j] = t }
      return n ? (n % 2 ? a[int(n / 2)] : (a[n / 2 - 1] + a[n / 2]) / 2) : 0
    }
    END { printf "%.4f %d\n", median(rate, n), n }' "$log"
}

median_of() { tr ' ' '\n' | sed '/^$/d' | sort -g | awk '{a[NR]=$1} END {print NR % 2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }
field() { tr ' ' '\n' | sed -n "s/^$1=//p"; }

mesa=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers 2>/dev/null || echo unknown)
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), mesa-vulkan-drivers $mesa"
echo "command: $0 --frames $frames --size $size --rounds $rounds --reps $reps --scenes \"$scenes\""
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.4f", (b > 0 ? a / b : 0) }'; }
declare -A g=() rq=() flat=() em=() g_rq=() g_em=() rq_em=() info=()
for ((round = 0; round < rounds; ++round)); do
  for scene in $scenes; do
    dump=$work/$scene.dump
    rm -f "$dump"
    read -r glpt_rate frames_counted <<<"$(glpt "$scene" "$dump")"
    [ -f "$dump" ] || { echo "bench_ray_ceiling: $scene wrote no dump" >&2; exit 1; }
    result=$("$ceiling" "$dump" --reps "$reps" | tee "$work/$scene.$round.txt" | grep '^RESULT')
    r=$(field rq_mrays <<<"$result") f=$(field rq_flat_mrays <<<"$result")
    e=$(field embree_mrays <<<"$result")
    echo "round $round $scene: glpt $glpt_rate Mrays/s (median of $frames_counted frames) | ray query $r | flat $f | Embree $e"
    g[$scene]+="$glpt_rate " rq[$scene]+="$r " flat[$scene]+="$f " em[$scene]+="$e "
    # Ratios within a round: both sides saw the same machine load.
    g_rq[$scene]+="$(ratio "$glpt_rate" "$r") " g_em[$scene]+="$(ratio "$glpt_rate" "$e") "
    rq_em[$scene]+="$(ratio "$r" "$e") "
    info[$scene]="$(field triangles <<<"$result") tris, $(field instances <<<"$result") inst, rays $(field glpt_rays <<<"$result")/$(field secondary_rays <<<"$result")"
  done
done
echo
echo "Mrays/s and ratios: medians over $rounds rounds (ratios taken within each round)."
echo "glpt: inside the frame (rays / trace_ms); rq: bare ray query over glpt's TLAS; rq flat: one"
echo "BLAS per mask; rays: glpt's frame / the microbenchmark's secondary rays"
printf '| %-7s | %-38s | %7s | %7s | %7s | %7s | %7s | %11s | %9s |\n' scene "scene" glpt rq \
  glpt/rq "rq flat" Embree glpt/Embree rq/Embree
echo "|---------|----------------------------------------|---------|---------|---------|---------|---------|-------------|-----------|"
for scene in $scenes; do
  printf '| %-7s | %-38s | %7.3f | %7.3f | %7.2f | %7.3f | %7.2f | %11.3f | %9.3f |\n' "$scene" \
    "${info[$scene]}" "$(median_of <<<"${g[$scene]}")" "$(median_of <<<"${rq[$scene]}")" \
    "$(median_of <<<"${g_rq[$scene]}")" "$(median_of <<<"${flat[$scene]}")" \
    "$(median_of <<<"${em[$scene]}")" "$(median_of <<<"${g_em[$scene]}")" \
    "$(median_of <<<"${rq_em[$scene]}")"
done
echo
for scene in $scenes; do
  echo "--- $scene, last round's microbenchmark:"
  grep -v '^RESULT' "$work/$scene.$((rounds - 1)).txt"
done
