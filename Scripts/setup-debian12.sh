#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
# SPDX-License-Identifier: BSD-3-Clause
# Installs what the project needs on a fresh Debian 12 machine (run as root), then configures
# and builds it in ./build. Used by run-main.sh, run-tests.sh and .ci/run.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
packages=(cmake g++ make paraview-dev paraview python3-paraview libeigen3-dev qtbase5-dev
  libqt5svg5-dev qttools5-dev libqt5opengl5-dev qtxmlpatterns5-dev-tools libutfcpp-dev libhdf5-dev libhdf5-openmpi-dev
  libnetcdf-dev libogg-dev libtheora-dev libgl2ps-dev libglew-dev libproj-dev liblz4-dev liblzma-dev
  libdouble-conversion-dev libexpat1-dev libfreetype-dev libjpeg-dev libpng-dev libtiff-dev
  libavformat-dev libavcodec-dev libavutil-dev libswscale-dev libswresample-dev libgdal-dev
  libopenmpi-dev libnanoflann-dev xvfb xauth python3-numpy python3-scipy python3-h5py clang-format git
  clang libclang-rt-14-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  apt-get install -y --no-install-recommends "${missing[@]}"
fi
cmake -S "$here" -B "$here/build" -DCMAKE_BUILD_TYPE=Release
cmake --build "$here/build" -j "$(nproc)"
