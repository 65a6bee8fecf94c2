#!/usr/bin/env bash
# bench_classify.sh [--draws N] [--reps R] [LIBGL]
#
# What classification and identity matching cost (rt_core/scene/classify.hpp): bench/many_draws
# (N separate lit draws per frame, default 5000, under a camera that turns every frame) under
# glpt (LIBGL, default <build>/gl_shim/libGL.so.1) in a private Xvfb, in path-traced mode and in
# raster mode with GLPT_CLASSIFY_LOG=/dev/null (raster mode classifies only when asked; its
# frames cost the CPU least, so the share is largest there). Per mode: the CPU time of a frame
# (process CPU time of a 12-frame run minus a 4-frame run, divided by 8: start-up cancels out),
# the mean classify_ms of GLPT_STATS over the last 8 frames, their ratio, and the BLAS builds and
# TLAS instances per frame after the first. R repetitions (default 3), alternating modes; medians
# printed. Not a test.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${GLPT_BUILD_DIR:-$repo/build}
program=$build/bench/many_draws
draws=5000
reps=3
while [ $# -gt 0 ]; do
  case $1 in
    --draws) draws=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    -h|--help) sed -n '2,12p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) break ;;
  esac
done
libgl=${1:-$build/gl_shim/libGL.so.1}
[ -x "$program" ] || { echo "bench_classify: $program not built" >&2; exit 2; }
[ -f "$libgl" ] || { echo "bench_classify: no $libgl" >&2; exit 2; }
if [ -z "${GLPT_BENCH_UNDER_XVFB:-}" ]; then
  GLPT_BENCH_UNDER_XVFB=1 exec "$repo/tests/e2e/with_xvfb.sh" "$0" --draws "$draws" \
    --reps "$reps" "$libgl"
fi
echo "command: bench/bench_classify.sh --draws $draws --reps $reps $libgl"
exec python3 - "$program" "$libgl" "$draws" "$reps" <<'PY'
import os, re, resource, statistics, subprocess, sys, tempfile
program, libgl, draws, reps = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])

def run(mode, frames):
    """CPU seconds of one run and its stats lines."""
    with tempfile.NamedTemporaryFile(suffix=".stats") as stats:
        env = dict(os.environ, LD_PRELOAD=libgl, GLPT_MODE=mode, GLPT_QUIET="1",
                   GLPT_STATS_FILE=stats.name)
        if mode == "raster":
            env["GLPT_CLASSIFY_LOG"] = "/dev/null"
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run([program, "--draws", draws, "--frames", str(frames)], env=env, check=True)
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
        lines = open(stats.name).read().splitlines()
    return cpu, lines

def field(line, name):
    m = re.search(r"\b%s=([0-9.]+)" % name, line)
    return float(m.group(1)) if m else 0.0

results = {"path": [], "raster": []}
for rep in range(reps):
    for mode in ("path", "raster"):
        long_cpu, lines = run(mode, 12)
        short_cpu, _ = run(mode, 4)
        frame_cpu_ms = (long_cpu - short_cpu) / 8 * 1000
        last = lines[-8:]
        classify = statistics.mean(field(l, "classify_ms") for l in last)
        builds = statistics.mean(field(l, "blas_builds") for l in last)
        instances = statistics.mean(field(l, "instances") for l in last)
        results[mode].append((frame_cpu_ms, classify, builds, instances))
        print(f"rep {rep} {mode}: frame_cpu_ms={frame_cpu_ms:.1f} classify_ms={classify:.2f} "
              f"share={classify / frame_cpu_ms * 100:.2f}% blas_builds={builds:.1f} "
              f"instances={instances:.0f}", flush=True)
for mode, rows in results.items():
    cpu = statistics.median(r[0] for r in rows)
    classify = statistics.median(r[1] for r in rows)
    print(f"median {mode}: draws={draws} frame_cpu_ms={cpu:.1f} classify_ms={classify:.2f} "
          f"share={classify / cpu * 100:.2f}% blas_builds={rows[-1][2]:.1f} "
          f"instances={rows[-1][3]:.0f}")
PY
