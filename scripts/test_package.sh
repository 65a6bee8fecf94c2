#!/usr/bin/env bash
# Builds the Debian package (cpack -G DEB) from build/ (or $GLPT_BUILD_DIR), installs it with
# apt as a user would (apt install ./glpt_*.deb, which resolves its dependencies), runs the
# installed glpt doctor and glpt replay from another directory, and removes the package again.
# Changes the system: CI runs it on its fresh machine (.ci/run); needs root.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${GLPT_BUILD_DIR:-$root/build}
work=$(mktemp -d "${TMPDIR:-/tmp}/glpt-deb.XXXXXX")
trap 'rm -rf "$work"' EXIT
(cd "$build" && cpack -G DEB -B "$work/package" >"$work/cpack.log") ||
  { cat "$work/cpack.log" >&2; exit 1; }
deb=$(ls "$work"/package/glpt_*.deb)
dpkg-deb -f "$deb" Depends | grep -q "mesa-vulkan-drivers (>= 24.1)" ||
  { echo "test_package: the package does not depend on lavapipe with ray queries" >&2; exit 1; }
# A package removed earlier (apt-get remove) leaves "config-files" behind: only an installed one
# belongs to somebody else.
if [ "$(dpkg-query -W -f='${db:Status-Status}' glpt 2>/dev/null)" = installed ]; then
  echo "test_package: a glpt package is installed already; not touching it" >&2
  exit 1
fi
trap 'apt-get purge -y -q glpt >/dev/null 2>&1 || true; rm -rf "$work"' EXIT
apt-get install -y -q "$deb" >"$work/apt.log" || { cat "$work/apt.log" >&2; exit 1; }
cd "$work"
[ "$(command -v glpt)" = /usr/bin/glpt ] || { echo "test_package: glpt is not /usr/bin/glpt" >&2; exit 1; }
[ -f /usr/lib/glpt/libGL.so.1 ] || { echo "test_package: no /usr/lib/glpt/libGL.so.1" >&2; exit 1; }
/usr/bin/glpt doctor >doctor.txt || { cat doctor.txt >&2; exit 1; }
grep -q "^ok    glpt.s libGL.so.1   /usr/lib/glpt/libGL.so.1" doctor.txt || { cat doctor.txt >&2; exit 1; }
GLPT_QUIET=1 /usr/bin/glpt replay "$root/tests/replay/data/gearsdet.trace" --quiet --mode raster \
  --frames 0 --out frames >replay.log 2>&1 || { cat replay.log >&2; exit 1; }
/usr/bin/glpt diff "$root/tests/golden/images/golden.gearsdet.raster/frame_000000.png" \
  frames/frame_000000.png --threshold 0.01
man -w glpt-run >/dev/null
echo "test_package: $(basename "$deb") installs with apt, and its glpt works"
