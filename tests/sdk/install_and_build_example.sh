#!/usr/bin/env bash
# The SDK end to end: install the build into a temporary prefix, build the out-of-tree example
# plugin (examples/my_policy) against it with find_package(crowdsim), and run its suite with the
# installed CLI, which must find its plugins and data relative to itself.
#   tests/sdk/install_and_build_example.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build="$1"
source="$2"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

cmake --install "$build" --prefix "$work/prefix" > "$work/install.log" || { cat "$work/install.log"; fail "install"; }
for f in bin/crowdsim-bench lib/libcrowdsim_sdk.so lib/crowdsim-bench/plugins/crowdsim_orca.so \
         include/crowdsim/plugin_abi.h lib/cmake/crowdsim/crowdsimConfig.cmake \
         share/crowdsim-bench/worlds/random_rect share/crowdsim-bench/suites/quick.yaml; do
  [[ -e "$work/prefix/$f" ]] || fail "the install lacks $f"
done
# The documentation the CLI's messages name (docs/plugins.md, docs/training.md,
# tools/floorplan/README.md, examples/my_policy), in the source tree's layout under
# share/doc/crowdsim-bench: a user of the .deb has no source tree to read them in.
doc="$work/prefix/share/doc/crowdsim-bench"
for f in README.md docs/plugins.md docs/training.md docs/metrics.md tools/floorplan/README.md \
         plugins/policies/torchscript/README.md plugins/sensors/lidar2d/README.md examples/floorplan/two_rooms.png; do
  [[ -f "$doc/$f" ]] || fail "the install lacks the documentation share/doc/crowdsim-bench/$f"
done
diff -r -x build "$source/examples/my_policy" "$doc/examples/my_policy" > "$work/example.diff" ||
  { cat "$work/example.diff"; fail "the installed examples/my_policy differs from the source's"; }
# Exactly the SDK folder's headers are installed (none of the host's bench/), and each one
# compiles on its own against the prefix.
installed=$(cd "$work/prefix/include/crowdsim" && find . -type f | sed 's|^\./||' | sort)
sdk=$(cd "$source/harness/sdk/include/crowdsim" && ls *.h | sort)
[[ "$installed" == "$sdk" ]] || fail "installed headers differ from the SDK folder: $(diff <(echo "$sdk") <(echo "$installed") | tr '\n' ' ')"
for h in $sdk; do
  echo "#include \"crowdsim/$h\"" | ${CXX:-c++} -std=c++20 -fsyntax-only -x c++ - -I "$work/prefix/include" \
    -I /usr/include/eigen3 2> "$work/header.log" || { cat "$work/header.log"; fail "installed header $h does not compile on its own"; }
done

cmake -S "$source/examples/my_policy" -B "$work/example" -DCMAKE_PREFIX_PATH="$work/prefix" \
  > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; fail "configure the example"; }
cmake --build "$work/example" > "$work/build.log" 2>&1 || { cat "$work/build.log"; fail "build the example"; }
[[ -f "$work/example/crowdsim_yielding_straight.so" ]] || fail "the example plugin was not built"
# The host is never installed, and a plugin built with the installed SDK's crowdsim_add_plugin
# that calls a host function fails to link (tests/fixtures/host_symbol_plugin.cc).
[[ -z "$(find "$work/prefix" -name 'libcrowdsim_host*')" ]] || fail "the install holds the host library"
mkdir -p "$work/host_symbol"
cat > "$work/host_symbol/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.22)
project(host_symbol LANGUAGES CXX)
find_package(crowdsim REQUIRED)
crowdsim_add_plugin(host_symbol "$source/tests/fixtures/host_symbol_plugin.cc")
target_compile_definitions(crowdsim_plugin_host_symbol PRIVATE CROWDSIM_FIXTURE_CALLS_HOST=1)
CMAKE
cmake -S "$work/host_symbol" -B "$work/host_symbol/build" -DCMAKE_PREFIX_PATH="$work/prefix" \
  > "$work/host_symbol.log" 2>&1 || { cat "$work/host_symbol.log"; fail "configure the host-symbol plugin"; }
if cmake --build "$work/host_symbol/build" > "$work/host_symbol.log" 2>&1; then
  fail "a plugin calling a host function linked against the installed SDK"
fi
grep -q "undefined reference to .crowdsim::IsShippedPluginName" "$work/host_symbol.log" ||
  { cat "$work/host_symbol.log"; fail "the host-symbol plugin failed, but not at the link"; }

# The installed CLI searches its own plugin folder, not the build tree's.
plugins=$(cd "$work" && "$work/prefix/bin/crowdsim-bench" list-plugins)
grep -q "plugin folders: $(cd "$work/prefix/lib" && pwd -P)/crowdsim-bench/plugins" <<< "$plugins" ||
  fail "the installed CLI does not search its own plugins: $(head -1 <<< "$plugins")"

cd "$work"
CROWDSIM_PLUGIN_PATH="$work/example" "$work/prefix/bin/crowdsim-bench" run \
  "$source/examples/my_policy/suite.yaml" --episodes 5 --out "$work/run" --quiet > "$work/run.log" 2>&1 ||
  { cat "$work/run.log"; fail "run the example suite"; }
grep -q "^1,yielding_straight,person," "$work/run/table.csv" || fail "no yielding_straight row: $(cat "$work/run/table.csv")"
grep -q ",0.0000,5," "$work/run/table.csv" || fail "policy errors in $(cat "$work/run/table.csv")"
# The installed Python package (when built): imported from the prefix, it runs with the
# installed core library and plugins.
if [[ -d "$build/python/crowdsim_bench" ]]; then
  py=$(sed -n 's/^CROWDSIM_PYTHON_EXECUTABLE:INTERNAL=//p' "$build/CMakeCache.txt")
  py_dir=$(sed -n 's/^CROWDSIM_PYTHON_INSTALL_DIR:INTERNAL=//p' "$build/CMakeCache.txt")
  [[ -d "$work/prefix/$py_dir/crowdsim_bench" ]] || fail "no Python package in $work/prefix/$py_dir"
  PYTHONPATH="$work/prefix/$py_dir" "${py:-python3}" -c "
import crowdsim_bench as cb
assert cb.__file__.startswith('$work/prefix'), cb.__file__
env = cb.Env('$source/suites/quick.yaml', row='orca')
obs, info = env.reset(seed=0)
env.step([0.0, 0.0])
" || fail "the installed Python package does not run"
fi
echo "SDK install, example build and run: ok"
