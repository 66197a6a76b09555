#!/usr/bin/env bash
# A build that leaves out some of the project's plugins (the learned policies without libtorch,
# a folder named in CROWDSIM_SKIP_MODULES) says why for each, so that a suite naming one is told
# "not in this build: it needs libtorch ..." rather than to look for a plugin of its own:
# configures the sources that way (no build) and reads the generated LeftOutPluginReason.
#   left_out_plugins_test.sh SOURCE_DIR
set -euo pipefail
src="$1"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
cmake -S "$src" -B "$dir" -DCROWDSIM_WITH_TORCH=OFF -DCROWDSIM_BUILD_TESTS=OFF \
  -DCROWDSIM_BUILD_BENCHMARKS=OFF -DCROWDSIM_WITH_PYTHON=OFF -DCROWDSIM_WITH_MPI=OFF \
  -DCROWDSIM_SKIP_MODULES=linear >"$dir/configure.log" 2>&1 ||
  { cat "$dir/configure.log"; exit 1; }
generated="$dir/generated/shipped_plugins.cc"
fail=0
expect() {
  grep -qF -- "$1" "$generated" || { echo "left_out_plugins: missing in $generated: $1"; fail=1; }
}
for name in cadrl sarl torchscript; do
  expect "if (name == \"$name\") return \"it needs libtorch, and this build has CROWDSIM_WITH_TORCH=OFF\";"
done
expect 'if (name == "linear") return "CROWDSIM_SKIP_MODULES names its folder";'
# The plugins it does build are not left out, and neither is the libraries' folder.
for name in orca lidar2d crowdnav lib; do
  if grep -qF "if (name == \"$name\")" "$generated"; then
    echo "left_out_plugins: '$name' is said to be left out"; fail=1
  fi
done
[[ $fail == 0 ]] || { cat "$generated"; exit 1; }
echo "left_out_plugins: ok"
