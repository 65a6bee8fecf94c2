#!/usr/bin/env bash
# bench_refit.sh [--grid G] [--frames F] [--amplitudes "A ..."] [--reps R] [LIBGL]
#
# What refitting a deforming object's BLAS saves and what it costs the rays (docs/classification.md,
# "Deforming geometry"): bench/deforming_mesh (a G x G grid, default 96: 18,432 triangles, waving
# with height A relative to its size) path-traced under glpt (LIBGL, default
# <build>/gl_shim/libGL.so.1) in a private Xvfb, with GLPT_BLAS_REFIT=1 (refit or built anew by
# cost, BlasCache::refit_source) and =0 (built anew every frame), alternating, R repetitions (default 3)
# of F frames (default 30), accumulation off. Prints per setting the medians over the frames
# after the second of: host upload ms (BLAS inputs and shading data), device BLAS ms, device
# trace ms, wall ms per frame, and builds and refits per frame. Not a test.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$here/.." && pwd)
build=${GLPT_BUILD_DIR:-$repo/build}
program=$build/bench/deforming_mesh
grid=96
frames=30
amplitudes="0.15 0.5"
reps=3
while [ $# -gt 0 ]; do
  case $1 in
    --grid) grid=$2; shift 2 ;;
    --frames) frames=$2; shift 2 ;;
    --amplitudes) amplitudes=$2; shift 2 ;;
    --reps) reps=$2; shift 2 ;;
    -h|--help) sed -n '2,12p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) break ;;
  esac
done
libgl=${1:-$build/gl_shim/libGL.so.1}
[ -x "$program" ] || { echo "bench_refit: $program not built" >&2; exit 2; }
[ -f "$libgl" ] || { echo "bench_refit: no $libgl" >&2; exit 2; }
if [ -z "${GLPT_BENCH_UNDER_XVFB:-}" ]; then
  GLPT_BENCH_UNDER_XVFB=1 exec "$repo/tests/e2e/with_xvfb.sh" "$0" --grid "$grid" \
    --frames "$frames" --amplitudes "$amplitudes" --reps "$reps" "$libgl"
fi
echo "command: bench/bench_refit.sh --grid $grid --frames $frames --amplitudes \"$amplitudes\" --reps $reps $libgl"
exec python3 - "$program" "$libgl" "$grid" "$frames" "$amplitudes" "$reps" <<'PY'
import os, re, statistics, subprocess, sys, tempfile
program, libgl, grid, frames, amplitudes, reps = sys.argv[1:7]
reps = int(reps)
fields = ["upload_ms", "blas_ms", "trace_ms", "wall_ms", "blas_builds", "blas_refits"]

def run(refit, amplitude):
    with tempfile.NamedTemporaryFile(suffix=".stats") as stats:
        env = dict(os.environ, LD_PRELOAD=libgl, GLPT_QUIET="1", GLPT_ACCUMULATE="0",
                   GLPT_BLAS_REFIT=refit, GLPT_STATS_FILE=stats.name)
        subprocess.run([program, "--grid", grid, "--frames", frames, "--amplitude", amplitude],
                       env=env, check=True, stderr=subprocess.DEVNULL)
        lines = [l for l in open(stats.name).read().splitlines() if " frame=" in " " + l]
    rows = []
    for line in lines[2:]:
        rows.append({f: float(re.search(r"\b%s=([0-9.]+)" % f, line).group(1)) for f in fields})
    return rows

print("%-9s %-6s %9s %8s %9s %8s %7s %7s" % ("amplitude", "refit", "upload_ms", "blas_ms",
                                             "trace_ms", "wall_ms", "builds", "refits"))
for amplitude in amplitudes.split():
    results = {"1": [], "0": []}
    for rep in range(reps):
        for refit in ("1", "0"):
            results[refit] += run(refit, amplitude)
            print("  round %d/%d amplitude %s refit %s done" % (rep + 1, reps, amplitude, refit),
                  file=sys.stderr, flush=True)
    for refit in ("1", "0"):
        rows = results[refit]
        med = {f: statistics.median(r[f] for r in rows) for f in fields[:4]}
        mean = {f: statistics.mean(r[f] for r in rows) for f in fields[4:]}
        print("%-9s %-6s %9.2f %8.2f %9.2f %8.2f %7.2f %7.2f" % (
            amplitude, refit, med["upload_ms"], med["blas_ms"], med["trace_ms"], med["wall_ms"],
            mean["blas_builds"], mean["blas_refits"]))
PY
