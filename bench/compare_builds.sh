#!/usr/bin/env bash
# compare_builds.sh BUILD_A BUILD_B [--rounds N] [--frames F] [--settings "VAR=V ..."]
#                   [--settings-b "VAR=V ..."] [--metric total_ms|wall_ms]
#
# Whether a change made path-traced frames slower: runs glxgears and bench/lit_scene through the
# libGL.so.1 of two build directories (say, one of the commit before a change and one after),
# alternating A and B round by round so both see the same machine load, and prints the median
# ms per frame (GLPT_STATS' total_ms, frames after the second) of each and the ratio B / A. Two
# settings of one build compare the same way: the same build twice and --settings-b.
# Accumulation is off (every frame pays for its samples). lit_scene comes from BUILD_B.
#
#   --rounds N      alternations (default 3)
#   --frames F      lit_scene's frames per run (default 8; glxgears runs 25 s)
#   --settings S    GLPT_* settings of every run (default: none, glpt's defaults)
#   --settings-b S  settings added to B's runs only (say GLPT_VK_SYNC=1)
#   --metric M      total_ms (the stages' sum, default) or wall_ms (the wall clock of the
#                   frame's end, render and present: what overlapping host and device work
#                   saves shows here only)
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,19p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
build_a=$1
build_b=$2
shift 2
rounds=3
frames=8
settings=""
settings_b=""
metric=total_ms
while [ $# -gt 0 ]; do
  case $1 in
    --rounds) rounds=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --settings) settings=$2; shift 2 ;;
    --settings-b) settings_b=$2; shift 2 ;;
    --metric) metric=$2; shift 2 ;;
    *) echo "compare_builds: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
for b in "$build_a" "$build_b"; do
  [ -f "$b/gl_shim/libGL.so.1" ] || { echo "compare_builds: no $b/gl_shim/libGL.so.1" >&2; exit 2; }
done
lit_scene=$build_b/bench/lit_scene
[ -x "$lit_scene" ] || { echo "compare_builds: no $lit_scene" >&2; exit 2; }

display=:$((300 + RANDOM % 100))
Xvfb "$display" -screen 0 1024x768x24 -nolisten tcp >/dev/null 2>&1 &
xvfb=$!
trap 'kill $xvfb 2>/dev/null || true' EXIT
sleep 1

# run BUILD EXTRA_SETTINGS PROGRAM ARGS...: the median $metric of the frames after the second.
run() {
  local build=$1 extra=$2 log
  shift 2
  log=$(mktemp)
  env DISPLAY="$display" LD_PRELOAD="$build/gl_shim/libGL.so.1" GLPT_STATS=1 GLPT_ACCUMULATE=0 \
    GLPT_QUIET=1 $settings $extra "$@" 2>"$log" >/dev/null || true
  awk -v metric="$metric" '/^glpt: frame=/ {
         for (i = 1; i <= NF; ++i) { split($i, kv, "="); v[kv[1]] = kv[2] }
         if (v["trace_ms"] + 0 == 0 || seen++ < 2) next
         t[n++] = v[metric] }
       END { for (i = 0; i < n; ++i) for (j = i + 1; j < n; ++j) if (t[j] < t[i]) { x = t[i]; t[i] = t[j]; t[j] = x }
             printf "%.1f\n", n ? (n % 2 ? t[int(n / 2)] : (t[n / 2 - 1] + t[n / 2]) / 2) : 0 }' "$log"
  rm -f "$log"
}
median() { tr ' ' '\n' | grep . | sort -g | awk '{a[NR]=$1} END {print NR % 2 ? a[(NR+1)/2] : (a[NR/2]+a[NR/2+1])/2}'; }

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "command: $0 $build_a $build_b --rounds $rounds --frames $frames --settings \"$settings\" --settings-b \"$settings_b\" --metric $metric"
printf '%-10s %12s %12s %8s\n' scene a_ms b_ms b/a
for scene in glxgears lit_scene; do
  a="" b=""
  for ((round = 0; round < rounds; ++round)); do
    for side in a b; do
      build=$([ $side = a ] && echo "$build_a" || echo "$build_b")
      extra=$([ $side = a ] && echo "" || echo "$settings_b")
      if [ $scene = glxgears ]; then
        ms=$(run "$build" "$extra" timeout -s INT 25 /usr/bin/glxgears)
      else
        ms=$(run "$build" "$extra" "$lit_scene" --frames "$frames")
      fi
      if [ $side = a ]; then a+="$ms "; else b+="$ms "; fi
    done
  done
  ma=$(median <<<"$a")
  mb=$(median <<<"$b")
  printf '%-10s %12s %12s %8s\n' $scene "$ma" "$mb" "$(awk -v a="$ma" -v b="$mb" 'BEGIN { printf "%.3f", (a > 0 ? b / a : 0) }')"
done
