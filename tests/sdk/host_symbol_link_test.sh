#!/usr/bin/env bash
# A plugin that uses a host symbol fails to link: tests/fixtures/host_symbol_plugin.cc built as
# every plugin is (crowdsim_plugin_link) must stop at the link naming the host function, and
# the same source without the call must link. The host must define that function, so the
# failure is the boundary's and not a misspelt name.
#   tests/sdk/host_symbol_link_test.sh BUILD_DIR
set -uo pipefail
build="$1"
fail() { echo "FAIL: $*" >&2; exit 1; }
nm -C --defined-only "$build"/harness/libcrowdsim_host.a 2>/dev/null |
  grep -q ' T crowdsim::IsShippedPluginName' || fail "the host library defines no crowdsim::IsShippedPluginName"
cmake --build "$build" --target fixture_sdk_only_plugin > /tmp/sdk_only.$$ 2>&1 ||
  { cat /tmp/sdk_only.$$; rm -f /tmp/sdk_only.$$; fail "the control plugin (SDK symbols only) does not link"; }
rm -f /tmp/sdk_only.$$
out=$(cmake --build "$build" --target fixture_host_symbol_plugin 2>&1) &&
  fail "a plugin calling the host's IsShippedPluginName linked: $out"
grep -q "undefined reference to .crowdsim::IsShippedPluginName" <<< "$out" ||
  fail "the link failed, but not on the host symbol: $out"
echo "host_symbol_link_test: a plugin using the host's IsShippedPluginName fails to link; the SDK-only control links"
