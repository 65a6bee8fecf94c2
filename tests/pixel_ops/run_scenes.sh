#!/usr/bin/env bash
# run_scenes.sh MESA_RUNNER GLPT_RUNNER OUT: renders every pixel scene with real Mesa into
# OUT/mesa and with glpt into OUT/glpt, then compares them (see scene_runner.hpp). On failure
# OUT/glpt/SCENE.diff.png marks the pixels that are off.
set -euo pipefail
mesa=$1 glpt=$2 out=$3
rm -rf "$out"
mkdir -p "$out/mesa" "$out/glpt"
"$mesa" --out "$out/mesa"
"$glpt" --out "$out/glpt"
"$glpt" --compare "$out/mesa" "$out/glpt"
