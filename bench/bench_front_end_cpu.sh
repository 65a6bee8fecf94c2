#!/usr/bin/env bash
# bench_front_end_cpu.sh [--reps R] [--modes "immediate arrays elements vbo"] [--heap] [LIBGL...]
#
# CPU time per frame of bench/gl_throughput (100 000 lit triangles per frame) on Mesa llvmpipe and
# on each given glpt libGL.so.1 (default: <build>/gl_shim/libGL.so.1) in raster mode, in one
# private Xvfb: `perf stat -e task-clock` of a 13-frame run minus a 3-frame run, divided by 10
# (start-up cancels out). Mesa and the glpt builds alternate, R times (default 5); prints each
# value and the median per mode. CPU time is steadier than wall time on a shared machine; compare
# ratios measured in the same run. --heap adds Mesa run with the heap thresholds glpt sets
# (gl_shim/frame/heap_tuning.hpp, as GLIBC_TUNABLES) and each libGL with GLPT_HEAP_TUNING=0, so
# the tuning's share is seen. Not a test.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${GLPT_BUILD_DIR:-$repo/build}
program=$build/bench/gl_throughput
reps=5
modes="immediate arrays elements vbo"
heap=""
while [ $# -gt 0 ]; do
  case $1 in
    --reps) reps=$2; shift 2 ;;
    --modes) modes=$2; shift 2 ;;
    --heap) heap=--heap; shift ;;
    -h|--help) sed -n '2,13p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) break ;;
  esac
done
libs=("$@")
[ ${#libs[@]} -gt 0 ] || libs=("$build/gl_shim/libGL.so.1")
[ -x "$program" ] || { echo "bench_front_end_cpu: $program not built" >&2; exit 2; }
command -v perf >/dev/null || { echo "bench_front_end_cpu: perf not found" >&2; exit 2; }
if [ -z "${GLPT_BENCH_UNDER_XVFB:-}" ]; then
  GLPT_BENCH_UNDER_XVFB=1 exec "$repo/tests/e2e/with_xvfb.sh" "$0" --reps "$reps" \
    --modes "$modes" $heap "${libs[@]}"
fi

heap_tunables=glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=67108864
task_clock() {  # mesa|mesa+heap|LIBGL|LIBGL+noheap mode frames: milliseconds of CPU
  local lib=$1 mode=$2 frames=$3
  case $lib in
    mesa) perf stat -x, -e task-clock "$program" --mode "$mode" --frames "$frames" 2>&1 >/dev/null ;;
    mesa+heap)
      GLIBC_TUNABLES=$heap_tunables perf stat -x, -e task-clock "$program" --mode "$mode" \
        --frames "$frames" 2>&1 >/dev/null ;;
    *)
      local tuning=1
      [ "${lib%+noheap}" != "$lib" ] && tuning=0
      LD_PRELOAD=${lib%+noheap} GLPT_MODE=raster GLPT_QUIET=1 GLPT_HEAP_TUNING=$tuning \
        perf stat -x, -e task-clock "$program" --mode "$mode" --frames "$frames" 2>&1 >/dev/null ;;
  esac | awk -F, '/task-clock/ {print $1}'
}
per_frame() { awk -v a="$(task_clock "$1" "$2" 13)" -v b="$(task_clock "$1" "$2" 3)" \
  'BEGIN {printf "%.1f", (a - b) / 10}'; }
median() { tr ' ' '\n' | grep . | sort -n | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'; }

if [ -n "$heap" ]; then
  with_variants=()
  for lib in "${libs[@]}"; do with_variants+=("$lib" "$lib+noheap"); done
  libs=("${with_variants[@]}")
fi
others=(mesa)
[ -n "$heap" ] && others+=(mesa+heap)
for mode in $modes; do
  declare -A values=()
  for ((r = 0; r < reps; ++r)); do
    for lib in "${others[@]}" "${libs[@]}"; do
      values[$lib]="${values[$lib]:-} $(per_frame "$lib" "$mode")"
    done
  done
  mesa=$(echo "${values[mesa]}" | median)
  line="$mode: mesa $mesa ms [${values[mesa]# }]"
  [ -n "$heap" ] && line="$line | mesa+heap $(echo "${values[mesa+heap]}" | median) ms [${values[mesa+heap]# }]"
  for lib in "${libs[@]}"; do
    m=$(echo "${values[$lib]}" | median)
    line="$line | $lib $m ms [${values[$lib]# }] Mesa/glpt $(awk -v a="$mesa" -v b="$m" 'BEGIN {printf "%.2f", a / b}')"
  done
  echo "$line"
  unset values
done
