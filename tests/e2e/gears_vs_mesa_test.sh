#!/usr/bin/env bash
# gears_vs_mesa_test.sh LIBGL GEARSDET IMGCOMPARE
#
# Renders gearsdet (tests/programs) at 400x400 in a private Xvfb three times:
#   mesa_shaded.png  real Mesa, --mode shaded  (glxgears' lighting)
#   mesa_facing.png  real Mesa, --mode facing  (N.L oracle: bright iff the face turns to the light)
#   glpt_shaded.png  LD_PRELOAD=LIBGL, --mode shaded --frames 16 (16 identical frames, so a
#                    path tracer that accumulates while the scene is static converges a little;
#                    gearsdet reads the last one back with glReadPixels before its swap)
# and asserts
#   1. coverage IoU(glpt_shaded, mesa_shaded) >= 0.98: glpt draws the same geometry in the same
#      place (camera, projection, modelview, display lists, culling, depth);
#   2. lit-vs-away holds for mesa_shaded (checks gearsdet's oracle itself) and for glpt_shaded:
#      where Mesa's facing oracle says a face turns toward the light, glpt's image is brighter
#      (by >= 0.05 in Rec. 709 luma and by a factor >= 1.5) than where it turns away: normals,
#      light direction and materials reach the tracer correctly.
#
# Coverage tolerance 24: the clear colour is (64,0,64) and every gear colour in Mesa's rendering
# differs from it by >= 43 in some channel (measured; typical >= 54), so 24 is about half of the
# smallest geometry/background difference: noise or a darker tracer does not drop geometry, and
# an anti-aliased edge pixel counts as covered once roughly half of it is geometry, as Mesa's
# centre sampling does. Measured: Mesa 16x supersampled (box filter) vs Mesa 1x gives IoU 0.9906
# at tolerance 24, while rotating the gears by 2 degrees gives 0.931.
#
# An empty LIBGL runs the "glpt" render on real Mesa too: a self-check of this harness and of
# gearsdet. On failure the images (and a coverage diff) are kept in the temporary directory.
set -euo pipefail

if [ $# -ne 3 ]; then
  echo "usage: gears_vs_mesa_test.sh LIBGL GEARSDET IMGCOMPARE" >&2
  exit 2
fi
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
if [ -z "${GLPT_E2E_UNDER_XVFB:-}" ]; then
  GLPT_E2E_UNDER_XVFB=1 exec "$here/with_xvfb.sh" "$0" "$@"
fi

libgl=$1
gearsdet=$2
imgcompare=$3
size=400x400
background=64,0,64  # gearsdet's clear colour (0.25, 0, 0.25) in 8 bits
tolerance=24
min_iou=0.98
glpt_frames=16
run_timeout_s=60

for f in "$gearsdet" "$imgcompare"; do
  [ -x "$f" ] || { echo "gears_vs_mesa_test: not executable: $f" >&2; exit 2; }
done
if [ -n "$libgl" ] && [ ! -f "$libgl" ]; then
  echo "gears_vs_mesa_test: LIBGL not found: $libgl" >&2
  exit 2
fi

tmp=$(mktemp -d "${TMPDIR:-/tmp}/glpt-gears-vs-mesa.XXXXXX")
failures=()
fail() { failures+=("$1"); echo "gears_vs_mesa_test: FAIL: $1" >&2; }

# render NAME [ENV...] -- GEARSDET-ARGS...: runs gearsdet, output $tmp/NAME.png, log $tmp/NAME.log
render() {
  local name=$1
  shift
  local envs=()
  while [ "$1" != "--" ]; do envs+=("$1"); shift; done
  shift
  local rc=0
  timeout "$run_timeout_s" env "${envs[@]}" "$gearsdet" --size "$size" --out "$tmp/$name.png" \
    "$@" >"$tmp/$name.log" 2>&1 || rc=$?
  if [ "$rc" != 0 ] || [ ! -s "$tmp/$name.png" ]; then
    fail "$name: gearsdet $* exited with status $rc$([ "$rc" = 124 ] && echo " (timeout ${run_timeout_s}s)"); log tail:"
    tail -n 20 "$tmp/$name.log" >&2 || true
    return 1
  fi
}

echo "gears_vs_mesa_test: DISPLAY=$DISPLAY LIBGL=${libgl:-<none: self-check on real Mesa>} dir=$tmp"
render mesa_shaded -- --mode shaded || true
render mesa_facing -- --mode facing || true
glpt_env=()
if [ -n "$libgl" ]; then glpt_env=(LD_PRELOAD="$libgl${LD_PRELOAD:+:$LD_PRELOAD}"); fi
render glpt_shaded "${glpt_env[@]}" -- --mode shaded --frames "$glpt_frames" || true

check() {  # check DESCRIPTION IMGCOMPARE-ARGS...
  local what=$1
  shift
  if [ ! -s "$tmp/mesa_shaded.png" ] || [ ! -s "$tmp/mesa_facing.png" ] ||
     [ ! -s "$tmp/glpt_shaded.png" ]; then
    return 0  # a render already failed
  fi
  local rc=0
  "$imgcompare" "$@" || rc=$?
  [ "$rc" = 0 ] || fail "$what (glpt_imgcompare exit $rc)"
}

check "coverage of glpt vs Mesa (IoU < $min_iou)" \
  coverage "$tmp/glpt_shaded.png" "$tmp/mesa_shaded.png" --background "$background" \
  --tolerance "$tolerance" --min-iou "$min_iou" --diff "$tmp/coverage_diff.png"
check "lit-vs-away on Mesa's shaded image (gearsdet's oracle is broken)" \
  lit-vs-away "$tmp/mesa_shaded.png" "$tmp/mesa_facing.png" --background "$background" \
  --tolerance "$tolerance"
check "lit-vs-away on glpt's shaded image (faces toward the light are not brighter)" \
  lit-vs-away "$tmp/glpt_shaded.png" "$tmp/mesa_facing.png" --background "$background" \
  --tolerance "$tolerance"

if [ ${#failures[@]} -gt 0 ]; then
  echo "gears_vs_mesa_test: ${#failures[@]} check(s) failed; images kept in $tmp" \
    "(coverage_diff.png: red = only glpt, green = only Mesa, white = both)" >&2
  exit 1
fi
rm -rf "$tmp"
echo "gears_vs_mesa_test: PASS"
