#!/usr/bin/env bash
# glpt tune on a real trace (tests/replay/data/gearsdet.trace, three frames): a few settings
# measured against a small reference, the CSV and the table; a budget and an error bound no
# setting meets (exit 1, the closest settings printed); traces without frames (exit 3, a
# message, never a crash). No X server is used.
#   tune_test.sh GLPT TRACE OUT
set -euo pipefail
unset DISPLAY WAYLAND_DISPLAY
export GLPT_QUIET=1
glpt=$1 trace=$2 out=$3
rm -rf "$out"
mkdir -p "$out"
fail() { echo "FAIL: $*"; exit 1; }

# Three settings, a 4-sample reference.
"$glpt" tune "$trace" --only raster,gl-parity,scale0.5 --reference 4 --out "$out/ok" --no-plot \
  >"$out/ok.txt" 2>&1 || { cat "$out/ok.txt"; fail "tune exited with $?"; }
cat "$out/ok.txt"
grep -q '^\[3/3\] scale0.5' "$out/ok.txt" || fail "no progress line for the third setting"
csv=$out/ok/tune.csv
[[ $(head -1 "$csv") == scene,setting,flags,* ]] || fail "CSV header: $(head -1 "$csv")"
[[ $(tail -n +2 "$csv" | wc -l) -eq 3 ]] || fail "CSV rows: $(tail -n +2 "$csv" | wc -l), want 3"
# Every setting measured (timed frames, a compared frame, a finite FLIP in [0, 1], no failure),
# and at least one on the Pareto front.
awk -F, 'NR > 1 {
  if ($4 < 1 || $15 < 1 || $16 < 0 || $16 > 1 || $NF != "\"\"") { print "bad row: " $0; bad = 1 }
  front += $19
} END { if (!front) { print "no setting on the front"; bad = 1 } exit bad }' "$csv" ||
  fail "CSV content"
# The reference is not the setting: a 1-sample setting differs from it somewhere.
awk -F, '$2 == "scale0.5" && $16 == 0 { exit 1 }' "$csv" || fail "scale0.5 equals the reference"

# A budget nothing meets: exit 1, the closest settings named.
status=0
"$glpt" tune "$trace" --only raster --reference 4 --out "$out/budget" --no-plot \
  --budget-ms 0.000001 >"$out/budget.txt" 2>&1 || status=$?
cat "$out/budget.txt"
[[ $status -eq 1 ]] || fail "unmet budget: exit $status, want 1"
grep -q 'no setting meets the budget' "$out/budget.txt" || fail "no message for the budget"
grep -q '^  raster ' "$out/budget.txt" || fail "the closest setting is not named"

# An error bound nothing reaches, and one that is met: the setting and its flags printed.
status=0
"$glpt" tune "$trace" --only raster --reference 4 --out "$out/budget" --no-plot \
  --max-flip 0.0000001 >"$out/bound.txt" 2>&1 || status=$?
[[ $status -eq 1 ]] || fail "unmet error bound: exit $status, want 1"
grep -q 'no setting meets the FLIP bound' "$out/bound.txt" || fail "no message for the bound"
"$glpt" tune "$trace" --only raster --reference 4 --out "$out/budget" --no-plot --max-flip 1 \
  >"$out/met.txt" 2>&1 || fail "a met bound exited with $?"
grep -q 'glpt run --mode raster --no-accumulate -- PROGRAM' "$out/met.txt" ||
  fail "no glpt run line: $(cat "$out/met.txt")"

# Traces without frames: an empty file and the first 100 bytes of a real one.
: >"$out/empty.trace"
head -c 100 "$trace" >"$out/cut.trace"
for bad in "$out/empty.trace" "$out/cut.trace"; do
  status=0
  "$glpt" tune "$bad" --out "$out/bad" --no-plot >"$out/bad.txt" 2>&1 || status=$?
  cat "$out/bad.txt"
  [[ $status -eq 3 ]] || fail "$bad: exit $status, want 3"
  grep -q 'has no frames to measure' "$out/bad.txt" || fail "$bad: no message"
done
# Bad usage.
status=0
"$glpt" tune "$trace" --budget-ms -3 >/dev/null 2>&1 || status=$?
[[ $status -eq 2 ]] || fail "--budget-ms -3: exit $status, want 2"
for bad_arguments in "--shard 3/2" "--frames 5-x"; do
  status=0
  "$glpt" tune "$trace" $bad_arguments >/dev/null 2>&1 || status=$?
  [[ $status -eq 2 ]] || fail "$bad_arguments: exit $status, want 2"
done
echo "tune: ok"
