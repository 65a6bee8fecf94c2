#!/usr/bin/env bash
# Runs the whole conformance suite (tests/conformance) in one process per backend and prints a
# table: scene, fraction of pixels within the scene's tolerance, largest channel difference,
# PSNR, state mismatches, pass/fail. Faster than ctest for a whole run; the images, state dumps
# and difference images stay in OUT (default $BUILD/conformance).
#
#   scripts/conformance.sh [-b BUILD_DIR] [-o OUT] [-f REGEX] [-s]
#     -b  build directory (default: $GLPT_BUILD_DIR or build/)
#     -o  output directory (default: BUILD/conformance)
#     -f  only scenes whose name matches REGEX (grep -E)
#     -s  also compare the GL state dumps (a column of mismatching queries per scene)
# Exit status: 0 when every scene passes, 1 otherwise.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${GLPT_BUILD_DIR:-$root/build}
out=""
filter=""
with_state=0
while getopts "b:o:f:s" opt; do
  case $opt in
    b) build=$OPTARG ;;
    o) out=$OPTARG ;;
    f) filter=$OPTARG ;;
    s) with_state=1 ;;
    *) sed -n '2,12p' "$0"; exit 2 ;;
  esac
done
out=${out:-$build/conformance}
mesa=$build/tests/conformance/glpt_conformance_mesa
glpt=$build/tests/conformance/glpt_conformance_glpt
imgcompare=$build/tests/tools/glpt_imgcompare
for tool in "$mesa" "$glpt" "$imgcompare"; do
  [ -x "$tool" ] || { echo "conformance.sh: $tool is missing: build first" >&2; exit 2; }
done

# name, max diff, min fraction (tab-separated, from the scene table)
mapfile -t table < <("$mesa" --list | cut -f1,4,5 | { [ -n "$filter" ] && grep -E "^[^	]*($filter)" || cat; })
[ ${#table[@]} -gt 0 ] || { echo "conformance.sh: no scene matches '$filter'" >&2; exit 2; }
args=()
for row in "${table[@]}"; do args+=(--scene "${row%%	*}"); done

rm -rf "$out/mesa" "$out/glpt"
"$mesa" "${args[@]}" --out "$out/mesa" > "$out.mesa.log" 2>&1 || true
GLPT_QUIET=${GLPT_QUIET:-1} "$glpt" "${args[@]}" --out "$out/glpt" > "$out.glpt.log" 2>&1 || true

printf '%-48s %10s %8s %8s %10s  %s\n' scene within max_diff psnr tolerance result
passed=0
failed=0
for row in "${table[@]}"; do
  IFS=$'\t' read -r scene max_diff min_fraction <<< "$row"
  reference=$out/mesa/$scene.png test=$out/glpt/$scene.png
  if [ ! -s "$reference" ] || [ ! -s "$test" ]; then
    printf '%-48s %10s %8s %8s %10s  %s\n' "$scene" - - - "$max_diff@$min_fraction" "FAIL (no image)"
    failed=$((failed + 1))
    continue
  fi
  line=$("$imgcompare" within "$reference" "$test" --max-diff "$max_diff" \
           --min-fraction "$min_fraction" 2>&1 | head -1) || true
  fraction=$(sed -n 's/.*fraction=\([0-9.]*\).*/\1/p' <<< "$line")
  largest=$(sed -n 's/.*max_diff=\([0-9]*\).*/\1/p' <<< "$line")
  psnr=$(sed -n 's/.*psnr=\([0-9.inf]*\).*/\1/p' <<< "$line")
  result=FAIL
  [[ $line == *"-> PASS"* ]] && result=PASS
  if [ "$with_state" = 1 ]; then
    summary=$("$imgcompare" state "$out/mesa/$scene.state.json" "$out/glpt/$scene.state.json" \
                --known "$root/tests/conformance/state_known.txt" 2>&1 | tail -n 1) || true
    mismatches=$(sed -n 's/.* \([0-9]*\) mismatches (\([0-9]*\) known).*/\1 (\2 known)/p' <<< "$summary")
    result="$result, state mismatches: ${mismatches:-?}"
    if [[ $summary == *"-> FAIL"* && $result == PASS* ]]; then result="FAIL${result#PASS}"; fi
  fi
  [[ $result == PASS* ]] && passed=$((passed + 1)) || failed=$((failed + 1))
  printf '%-48s %10s %8s %8s %10s  %s\n' "$scene" "${fraction:--}" "${largest:--}" "${psnr:--}" \
    "$max_diff@$min_fraction" "$result"
done
echo "passed $passed, failed $failed of ${#table[@]} (images in $out; difference images: $out/glpt/*.diff.png)"
[ "$failed" -eq 0 ]
