#!/usr/bin/env bash
# The commands behind the conformance ctest tests (see CMakeLists.txt and discover_scenes.cmake).
#   run_scene.sh harness SCENE OUT MESA IMGCOMPARE
#       Mesa renders SCENE twice (two processes): the images and state dumps must be identical
#       and the image non-trivial (>= 1% of the pixels differ from the top-left one).
#   run_scene.sh image SCENE OUT MESA GLPT IMGCOMPARE MAX_DIFF MIN_FRACTION
#       Mesa and glpt render SCENE; glpt's image must be within the scene's tolerance of Mesa's.
#       On failure OUT/glpt/SCENE.diff.png shows where (see README.md).
#   run_scene.sh image-path SCENE OUT MESA GLPT IMGCOMPARE MAX_DIFF MIN_FRACTION
#       The same with glpt in path-traced mode (GLPT_CONFORMANCE_MODE=path): for the scenes
#       path_mode.txt lists, whose draws path-traced mode rasterizes as raster mode does.
#   run_scene.sh state SCENE OUT MESA GLPT IMGCOMPARE
#       Mesa and glpt render SCENE; their GL state dumps must agree (but for the deliberate
#       differences state_known.txt lists with their reasons).
#   run_scene.sh table MESA MIN_SCENES
#       The scene table is valid (the runner checks it) and has at least MIN_SCENES scenes.
#   run_scene.sh compare-fails OUT MESA IMGCOMPARE
#       The comparison rejects a deliberately different image and writes its difference image.
#   run_scene.sh order OUT MESA IMGCOMPARE
#       `--all` (one process, a fresh context per scene) gives the same images and states as
#       the reverse order: no state leaks between scenes.
set -euo pipefail

mode=$1
shift

# Runs RUNNER for SCENE into DIR, failing the test (with the runner's output) if it fails.
render() {
  local runner=$1 scene=$2 dir=$3
  rm -rf "$dir"
  mkdir -p "$dir"
  "$runner" --scene "$scene" --out "$dir"
}

case "$mode" in
  harness)
    scene=$1 out=$2 mesa=$3 imgcompare=$4
    render "$mesa" "$scene" "$out/first"
    render "$mesa" "$scene" "$out/second"
    "$imgcompare" within "$out/first/$scene.png" "$out/second/$scene.png" \
      --max-diff 0 --min-fraction 1
    "$imgcompare" state "$out/first/$scene.state.json" "$out/second/$scene.state.json" \
      --float-tolerance 0
    "$imgcompare" nonblank "$out/first/$scene.png" --min-fraction 0.01
    ;;
  image)
    scene=$1 out=$2 mesa=$3 glpt=$4 imgcompare=$5 max_diff=$6 min_fraction=$7
    render "$mesa" "$scene" "$out/mesa"
    render "$glpt" "$scene" "$out/glpt"
    "$imgcompare" within "$out/mesa/$scene.png" "$out/glpt/$scene.png" \
      --max-diff "$max_diff" --min-fraction "$min_fraction"
    ;;
  image-path)
    scene=$1 out=$2 mesa=$3 glpt=$4 imgcompare=$5 max_diff=$6 min_fraction=$7
    render "$mesa" "$scene" "$out/mesa"
    GLPT_CONFORMANCE_MODE=path GLPT_STATS=1 render "$glpt" "$scene" "$out/glpt"
    "$imgcompare" within "$out/mesa/$scene.png" "$out/glpt/$scene.png" \
      --max-diff "$max_diff" --min-fraction "$min_fraction"
    ;;
  state)
    scene=$1 out=$2 mesa=$3 glpt=$4 imgcompare=$5
    render "$mesa" "$scene" "$out/mesa"
    render "$glpt" "$scene" "$out/glpt"
    "$imgcompare" state "$out/mesa/$scene.state.json" "$out/glpt/$scene.state.json" \
      --known "$(dirname "$0")/state_known.txt"
    ;;
  table)
    mesa=$1 min_scenes=$2
    count=$("$mesa" --list | wc -l)
    echo "scenes: $count (at least $min_scenes required)"
    [ "$count" -ge "$min_scenes" ]
    ;;
  compare-fails)
    out=$1 mesa=$2 imgcompare=$3
    rm -rf "$out"
    mkdir -p "$out"
    # Two scenes of the same size that differ in one light: a comparison must reject one as the
    # other, and write the difference image next to the test image.
    "$mesa" --scene lighting_light0_alone --scene lighting_light1_alone --out "$out"
    cp "$out/lighting_light1_alone.png" "$out/different.png"
    status=0
    "$imgcompare" within "$out/lighting_light0_alone.png" "$out/different.png" || status=$?
    if [ "$status" -ne 1 ]; then
      echo "FAIL: comparing different images exited $status, want 1" >&2
      exit 1
    fi
    [ -s "$out/different.diff.png" ] || { echo "FAIL: no $out/different.diff.png" >&2; exit 1; }
    # The same comparison of an image with itself passes and writes no difference image.
    "$imgcompare" within "$out/lighting_light0_alone.png" "$out/lighting_light0_alone.png"
    [ ! -e "$out/lighting_light0_alone.diff.png" ] || { echo "FAIL: diff on a pass" >&2; exit 1; }
    # A state dump compared with another scene's must report mismatches.
    status=0
    "$imgcompare" state "$out/lighting_light0_alone.state.json" \
      "$out/lighting_light1_alone.state.json" > "$out/state.txt" || status=$?
    if [ "$status" -ne 1 ] || ! grep -q 'GL_LIGHT1' "$out/state.txt"; then
      echo "FAIL: state comparison exited $status or did not name GL_LIGHT1" >&2
      cat "$out/state.txt" >&2
      exit 1
    fi
    echo "compare-fails: PASS"
    ;;
  order)
    out=$1 mesa=$2 imgcompare=$3
    rm -rf "$out"
    mkdir -p "$out/all" "$out/single"
    "$mesa" --all --out "$out/all"
    failed=0
    # The same scenes in reverse order: every scene starts from a fresh context, so the order
    # must not matter.
    mapfile -t scenes < <("$mesa" --list | cut -f1)
    args=()
    for ((i = ${#scenes[@]} - 1; i >= 0; i--)); do args+=(--scene "${scenes[i]}"); done
    "$mesa" "${args[@]}" --out "$out/single"
    for scene in "${scenes[@]}"; do
      if ! cmp -s "$out/all/$scene.png" "$out/single/$scene.png" ||
         ! cmp -s "$out/all/$scene.state.json" "$out/single/$scene.state.json"; then
        echo "FAIL: $scene differs between --all and a reversed run" >&2
        failed=1
      fi
    done
    echo "order: ${#scenes[@]} scenes compared"
    exit $failed
    ;;
  *)
    echo "run_scene.sh: unknown mode '$mode'" >&2
    exit 2
    ;;
esac
