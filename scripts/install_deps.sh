#!/usr/bin/env bash
# Installs the Debian 12 packages crowdsim-bench needs. Idempotent: installs only what is
# missing, runs `apt-get update` at most once, and does nothing when all is present.
# Usage: scripts/install_deps.sh [--no-torch] [--fuzz]
#   --fuzz  also clang and libFuzzer (libclang-rt-dev), for scripts/fuzz.sh
set -euo pipefail

packages=(
  build-essential cmake ccache pkg-config clang-format-14
  libeigen3-dev libbullet-dev libyaml-cpp-dev nlohmann-json3-dev
  libboost-dev libboost-filesystem-dev libboost-system-dev
  libboost-serialization-dev libboost-program-options-dev
  libompl-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libpng-dev libcairo2-dev libgif-dev zlib1g-dev
  libavcodec-dev libavformat-dev libswscale-dev  # render --animate to .mp4, tested like .gif
  libopenmpi-dev openmpi-bin
  python3-dev python3-pybind11 python3-numpy
  chromium  # the report's test opens the page in headless Chromium
)
with_torch=1
with_fuzz=0
for arg in "$@"; do
  case "$arg" in
    --no-torch) with_torch=0 ;;
    --fuzz) with_fuzz=1 ;;
    *) echo "install_deps: unknown option '$arg' (valid: --no-torch, --fuzz)" >&2; exit 2 ;;
  esac
done
if [[ $with_fuzz -eq 1 ]]; then
  packages+=(clang libclang-rt-dev)
fi
if [[ $with_torch -eq 1 ]]; then
  # python3-torch: the torchscript plugin's test scripts and saves tiny TorchScript modules
  # with it (and examples/python/ train and export policies); the C++ side needs only libtorch.
  packages+=(libtorch-dev libopenblas0-pthread python3-torch)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then sudo_cmd=(sudo); fi
echo "install_deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
