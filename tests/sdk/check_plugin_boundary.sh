#!/usr/bin/env bash
# The plugin SDK's boundary, from the folder names: harness/sdk/ is the SDK (its include/crowdsim/
# headers are what `cmake --install` ships), harness/host/ the host's own code.
# Fails when an SDK header includes anything but the SDK, when an SDK source (or the common
# code compiled into the SDK) includes a host header, or when plugin code (plugins/, examples/)
# includes a host header.
#   tests/sdk/check_plugin_boundary.sh [SOURCE_DIR]
set -euo pipefail
cd "${1:-$(dirname "$0")/../..}"
status=0
# An SDK header's project includes are "crowdsim/NAME.h" of another SDK header, nothing deeper.
while IFS= read -r hit; do
  echo "SDK header includes a non-SDK header: $hit"
  status=1
done < <(grep -Hn '#include "' harness/sdk/include/crowdsim/*.h | grep -v -E '#include "crowdsim/[a-z_]+\.h"' || true)
# The SDK's sources include the SDK, their own folder and harness/common, never the host.
while IFS= read -r hit; do
  echo "SDK source includes a host header (the SDK must not depend on the host): $hit"
  status=1
done < <(git ls-files 'harness/sdk/*' 'harness/common/*' | grep -E '\.(cc|h)$' |
         xargs grep -Hn -E '#include "(crowdsim/(bench|cli|render)/|(spec|sim|loader|run|results|train)/)' || true)
while IFS= read -r hit; do
  echo "plugin code includes a host header (move what it needs into the SDK): $hit"
  status=1
done < <(git ls-files 'plugins/*' 'examples/*' | grep -E '\.(cc|h)$' |
         xargs grep -Hn -E '#include "crowdsim/(bench|cli|render)/' || true)
sdk=$(ls harness/sdk/include/crowdsim/*.h | wc -l)
[[ $status -ne 0 ]] || echo "check_plugin_boundary: $sdk SDK headers and the SDK's sources include only the SDK; no plugin includes a host header"
exit $status
