// The plugins this build ships (generated from CMake's targets): only these, in the harness's
// folder, are the harness's own.
#pragma once

#include <string_view>

namespace crowdsim {

bool IsShippedPluginName(std::string_view name);

/// Why this build lacks the project's plugin `name` (e.g. no libtorch); "" if unknown or built.
std::string_view LeftOutPluginReason(std::string_view name);

}  // namespace crowdsim
