#!/usr/bin/env bash
# The one install step shared by run.sh and test.sh: installs whatever Debian packages are missing.
# Idempotent, and it touches apt only when something is missing.
set -euo pipefail

packages=(
  cmake g++ make pkg-config clang-format
  clang-14 libclang-rt-14-dev libomp-14-dev  # the sanitizer build and its fuzzers (docs/fuzzing.md)
  libeigen3-dev libboost-math-dev nlohmann-json3-dev libcli11-dev librandom123-dev
  libhdf5-dev hdf5-tools python3-h5py
  pybind11-dev python3-dev python3-numpy python3-matplotlib python3-pytest
  libgtest-dev libgmock-dev libbenchmark-dev
  libosmesa6-dev libglm-dev libstb-dev
  libglfw3-dev libimgui-dev
  xvfb xauth xdotool imagemagick
  libembree-dev libtbb-dev
  libopenmpi-dev openmpi-bin
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if ((${#missing[@]} == 0)); then
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
if [[ $(id -u) -ne 0 ]]; then
  echo "install-deps: missing packages and not root; run as root or install: ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
