#!/usr/bin/env bash
# glx_oracle_test.sh LIBGL ORACLE: runs glx_oracle (linked with the system libGL, i.e. Mesa) on one
# X server twice, plain and with glpt's LIBGL preloaded, and requires identical output: the same
# visuals and FBConfigs with the same attributes, the same glXChooseVisual/glXChooseFBConfig
# results, the same pixels of a glXUseXFont string in a single-buffered window, and the same X
# errors and return values for bad GLX calls, and the same drawable/context queries and GL
# buffer state for GLX windows, pbuffers and pixmaps of several configs.
# Run under tests/e2e/with_xvfb.sh.
set -euo pipefail
libgl=$1
oracle=$2
out=$(mktemp -d "${TMPDIR:-/tmp}/glx-oracle.XXXXXX")
trap 'rm -rf "$out"' EXIT
status=0
for mode in configs xfont errors queries; do
  "$oracle" "$mode" >"$out/mesa_$mode.txt"
  LD_PRELOAD=$libgl GLPT_MODE=raster "$oracle" "$mode" >"$out/glpt_$mode.txt"
  if ! diff -u "$out/mesa_$mode.txt" "$out/glpt_$mode.txt"; then
    echo "glx_oracle $mode: glpt differs from Mesa (above)" >&2
    status=1
  fi
done
# The comparison must not be vacuous.
grep -q '^fbconfig:' "$out/mesa_configs.txt" || { echo "Mesa listed no FBConfigs" >&2; status=1; }
grep -q '#' "$out/mesa_xfont.txt" || { echo "Mesa drew no text" >&2; status=1; }
grep -q 'error GLX+' "$out/mesa_errors.txt" || { echo "Mesa reported no GLX error" >&2; status=1; }
exit $status
