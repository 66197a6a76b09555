#!/usr/bin/env bash
# The plugin SDK's boundary, from the folder names: harness/include/crowdsim/*.h is the SDK
# (what `cmake --install` ships), harness/include/crowdsim/bench/ the host's own headers.
# Fails when an SDK header includes anything but the SDK (a host header, the CLI, render), or
# when plugin code (plugins/, sensors/, worlds/, examples/) includes a host header.
#   tests/sdk/check_plugin_boundary.sh [SOURCE_DIR]
set -euo pipefail
cd "${1:-$(dirname "$0")/../..}"
status=0
# An SDK header's project includes are "crowdsim/NAME.h" of another SDK header, nothing deeper.
while IFS= read -r hit; do
  echo "SDK header includes a non-SDK header: $hit"
  status=1
done < <(grep -Hn '#include "' harness/include/crowdsim/*.h | grep -v -E '#include "crowdsim/[a-z_]+\.h"' || true)
while IFS= read -r hit; do
  echo "plugin code includes a host header (move what it needs into the SDK): $hit"
  status=1
done < <(git ls-files 'plugins/*' 'sensors/*' 'worlds/*' 'examples/*' | grep -E '\.(cc|h)$' |
         xargs grep -Hn -E '#include "crowdsim/(bench|cli|render)/' || true)
sdk=$(ls harness/include/crowdsim/*.h | wc -l)
[[ $status -ne 0 ]] || echo "check_plugin_boundary: $sdk SDK headers include only the SDK; no plugin includes a host header"
exit $status
