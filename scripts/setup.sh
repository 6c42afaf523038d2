#!/usr/bin/env bash
# Installs every Debian 12 package slamroute needs to build, test and run. Idempotent: quiet and
# fast when everything is already there. Needs root (or sudo) and apt.
set -euo pipefail

PACKAGES=(
  build-essential cmake ccache git python3
  pkg-config                            # PCL's CMake config finds FLANN through it
  python3-numpy python3-scipy            # bench/*.py analysis scripts
  sumo sumo-tools                       # SUMO binaries, libsumo (libsumocpp.so + headers), tools
  libeigen3-dev libboost-graph-dev libopencv-dev libembree-dev liblemon-dev
  libceres-dev libyaml-cpp-dev libcli11-dev nlohmann-json3-dev libgtest-dev
  libtbb-dev libpugixml-dev libnanoflann-dev zlib1g-dev mpi-default-dev
  libopenmpi-dev openmpi-bin            # `slamroute sweep` over MPI ranks; its tests run mpirun
  libproj-dev                           # net x/y -> WGS84 lon/lat for GPX / KML
  libpcl-dev                            # tests and bench_pcl: PCL checks map.pcd and our ICP
  libxml2-utils                         # xmllint: tests validate GPX against its schema
  clang-format                          # scripts/check_format.sh
  chromium                              # headless browser: the report.html test opens the page
)
# npm vendors Leaflet into the build for report.html (scripts/vendor_js.sh). A Node.js from
# elsewhere (one that brings its own npm) is kept; otherwise Debian's nodejs and npm.
command -v npm >/dev/null 2>&1 || PACKAGES+=(nodejs npm)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if ((${#missing[@]})); then
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
  echo "setup: done"
fi

# libsumo looks for its data files under SUMO_HOME; the Debian package puts them here.
if [ -z "${SUMO_HOME:-}" ] && [ -d /usr/share/sumo ]; then
  export SUMO_HOME=/usr/share/sumo
fi
