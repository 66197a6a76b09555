#!/usr/bin/env bash
# The .deb's metadata (BUILD/CPackConfig.cmake, what `make package` hands dpkg-deb): its
# Suggests name what the optional parts it ships need. crowdsim_bench.torchscript_export imports
# torch and reads a model's training.yaml with yaml (python3-torch, python3-yaml); the SDK's
# CMake package finds Eigen and Boost (cmake, g++, libeigen3-dev, libboost-dev).
#   tests/sdk/package_metadata_test.sh BUILD_DIR
set -euo pipefail
config="$1/CPackConfig.cmake"
fail() { echo "FAIL: $*" >&2; exit 1; }
[[ -f "$config" ]] || fail "no $config"
suggests=$(sed -n 's/^set(CPACK_DEBIAN_PACKAGE_SUGGESTS "\(.*\)")$/\1/p' "$config")
for package in cmake g++ libeigen3-dev libboost-dev python3-torch python3-yaml; do
  grep -qE "(^|, )${package//+/\\+}(,|$)" <<< "$suggests" ||
    fail "the package does not suggest $package (Suggests: $suggests)"
done
echo "package metadata: ok"
