#!/usr/bin/env bash
# Installs every Debian 12 package stanceplan needs. Idempotent: a second run installs nothing.
# Called by both README commands; needs root (or sudo) only when something is missing.
set -euo pipefail

packages=(
  cmake g++ make pkg-config
  libeigen3-dev coinor-libipopt-dev libfcl-dev liburdfdom-dev libassimp-dev
  libosmesa6-dev libimgui-dev libglfw3-dev libgl-dev libglx-dev libopengl-dev
  nlohmann-json3-dev libyaml-cpp-dev libcli11-dev libstb-dev libpng-dev
  libqhull-dev libgtest-dev libgmock-dev libbenchmark-dev
  libompl-dev libboost-serialization-dev libboost-filesystem-dev libboost-system-dev  # guide path
  libavcodec-dev libavformat-dev libswscale-dev  # render --video (MP4; optional at build time)
  fonts-dejavu-core
  xvfb xauth libgl1-mesa-dri
  clang-14 libclang-rt-14-dev  # libFuzzer targets (fuzz/, scripts/run_fuzz.sh)
  clang-format                 # scripts/check_format.sh (a test)
  git                          # scripts/check_format.sh lists the tracked files
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "bootstrap: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "bootstrap: missing packages (${missing[*]}) and not root" >&2; exit 1; }
  sudo="sudo"
fi
echo "bootstrap: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq "${missing[@]}" >/dev/null
echo "bootstrap: done"
