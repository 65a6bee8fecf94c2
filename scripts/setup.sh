#!/usr/bin/env bash
# Installs everything glpt needs on Debian 12 (bookworm), from Debian's own packages. Idempotent.
#
# The path tracer needs VK_KHR_ray_query on lavapipe, which arrived in Mesa 24.1; bookworm ships
# Mesa 22.3, so mesa-vulkan-drivers comes from bookworm-backports (25.0.x). The backports suite is
# added with the same mirror the machine already uses for bookworm, so no host is hard-coded here.
set -euo pipefail

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive

stamp=/var/lib/glpt-setup.stamp
want_version=8  # bump when the package list below changes
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$want_version" ] && [ "${GLPT_SETUP_FORCE:-0}" != 1 ]; then
  echo "setup: packages already installed (rm $stamp or GLPT_SETUP_FORCE=1 to re-run)"
  exit 0
fi

# --- bookworm-backports -----------------------------------------------------------------------
if ! grep -rqs 'bookworm-backports' /etc/apt/sources.list /etc/apt/sources.list.d/; then
  mirror=""
  # deb822 style (Debian 12 default): find the URIs of the stanza whose Suites include bookworm.
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    mirror=$(awk 'BEGIN{RS=""} /Suites:[^\n]*bookworm([ \n]|$)/ && !/security/ {
                   if (match($0, /URIs:[ \t]*[^ \t\n]+/)) { s=substr($0,RSTART,RLENGTH); sub(/URIs:[ \t]*/,"",s); print s; exit } }' "$f")
    [ -n "$mirror" ] && break
  done
  # one-line style
  if [ -z "$mirror" ] && [ -f /etc/apt/sources.list ]; then
    mirror=$(awk '$1=="deb" && $3=="bookworm" {print $2; exit}' /etc/apt/sources.list)
  fi
  if [ -z "$mirror" ]; then
    echo "setup: could not find the Debian mirror used for bookworm in /etc/apt; add bookworm-backports by hand" >&2
    exit 1
  fi
  echo "setup: adding bookworm-backports from $mirror"
  printf 'Types: deb\nURIs: %s\nSuites: bookworm-backports\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
    "$mirror" | $SUDO tee /etc/apt/sources.list.d/bookworm-backports.sources >/dev/null
fi

$SUDO apt-get update -q

# Build tools and libraries.
build_pkgs=(cmake ninja-build g++ clang pkg-config python3 clang-format
            dpkg-dev bash-completion  # cpack's dependency scan (dpkg-shlibdeps), the completion test
            khronos-api libvulkan-dev glslang-tools libglm-dev
            libx11-dev libx11-xcb-dev libxcb1-dev libxcb-shm0-dev libpng-dev zlib1g-dev libgtest-dev
            libsnappy-dev libbrotli-dev  # apitrace's trace containers (replay/trace)
            libglfw3-dev)                # glpt-replay --window
# Running and testing: Xvfb, real programs (glxgears, xscreensaver's GL hacks, piglit's GL 1.x
# tests), apitrace, Vulkan tools and validation layers.
run_pkgs=(xvfb xauth mesa-utils x11-utils libgl-dev libegl-dev vulkan-tools vulkan-validationlayers
          xscreensaver-gl xscreensaver-gl-extra piglit apitrace
          x11-apps            # xwd: scripts/real_programs.py compares the window with the PNGs
          python3-matplotlib  # glpt tune's and bench/bench_tradeoffs.sh's plots
          libembree-dev)      # bench/ray_ceiling: Embree, the CPU's ray-tracing ceiling
$SUDO apt-get install -y -q --no-install-recommends "${build_pkgs[@]}" "${run_pkgs[@]}"

# Every Mesa package from backports: lavapipe with ray query, and real Mesa GL (GLX, EGL, OSMesa)
# as the raster reference, which must be the same Mesa whose rasterizer lavapipe shares.
mesa_pkgs=(mesa-vulkan-drivers libgl1-mesa-dri libglx-mesa0 libegl-mesa0 libgbm1 libosmesa6
           libosmesa6-dev)
$SUDO apt-get install -y -q --no-install-recommends -t bookworm-backports "${mesa_pkgs[@]}"

ver=$(dpkg-query -W -f='${Version}' mesa-vulkan-drivers)
major=${ver%%.*}; rest=${ver#*.}; minor=${rest%%.*}
if [ "$major" -lt 24 ] || { [ "$major" -eq 24 ] && [ "$minor" -lt 1 ]; }; then
  echo "setup: mesa-vulkan-drivers $ver is older than 24.1: lavapipe has no VK_KHR_ray_query" >&2
  exit 1
fi
echo "setup: mesa-vulkan-drivers $ver (lavapipe with VK_KHR_ray_query)"
for p in "${mesa_pkgs[@]}"; do
  v=$(dpkg-query -W -f='${Version}' "$p")
  if [ "$v" != "$ver" ]; then
    echo "setup: $p is $v but mesa-vulkan-drivers is $ver: the GL reference must be the same Mesa" >&2
    exit 1
  fi
done
echo "$want_version" | $SUDO tee "$stamp" >/dev/null
