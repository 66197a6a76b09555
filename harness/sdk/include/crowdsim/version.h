// What build this is and what processor runs it, for self-describing results.
#pragma once

#include <string>

#include "crowdsim/export.h"

namespace crowdsim {

/// The project version (CMake's project version).
CROWDSIM_SDK_API const char* Version();

/// The git commit the library was built from ("-dirty" with uncommitted changes, "unknown"
/// outside a git checkout); refreshed at every build.
CROWDSIM_SDK_API const char* GitCommit();

/// The processor's model name from /proc/cpuinfo ("unknown" where there is none): results
/// and trainings record it, since BLAS kernels differ between processors.
CROWDSIM_SDK_API std::string CpuModel();

}  // namespace crowdsim
