#!/usr/bin/env bash
# Installs the Debian packages RTK needs, if any is missing. Needs root (or sudo).
set -euo pipefail
packages=(cmake g++ make doctest-dev libstb-dev libglfw3-dev libbenchmark-dev libtbb-dev
          libpugixml-dev libpng-dev libjpeg-dev libopenexr-dev doxygen graphviz gnuplot-nox xvfb xauth clang libclang-rt-14-dev
          libembree-dev embree-tools libgl1-mesa-dri python3 libjs-mathjax doxygen-awesome-css chromium
          valgrind)
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
sudo=""
if [ "$(id -u)" -ne 0 ]; then
  sudo="sudo"
fi
echo "installing: ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
