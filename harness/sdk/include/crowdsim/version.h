// What build this is and what processor runs it, for self-describing results.
#pragma once

#include <string>

#include "crowdsim/export.h"

namespace crowdsim {

/// The project version (CMake's project version).
CROWDSIM_SDK_API const char* Version();

/// The git commit of this build ("-dirty" with uncommitted changes, "unknown" outside git).
CROWDSIM_SDK_API const char* GitCommit();

/// The processor's model name from /proc/cpuinfo ("unknown" if absent): BLAS kernels differ between
/// processors.
CROWDSIM_SDK_API std::string CpuModel();

}  // namespace crowdsim
