// What build this is and what processor runs it, for self-describing results.
#pragma once

#include <string>

namespace crowdsim {

/// The project version (CMake's project version).
const char* Version();

/// The git commit the library was built from ("-dirty" with uncommitted changes, "unknown"
/// outside a git checkout); refreshed at every build.
const char* GitCommit();

/// The processor's model name from /proc/cpuinfo ("unknown" where there is none): results
/// and trainings record it, since BLAS kernels differ between processors.
std::string CpuModel();

}  // namespace crowdsim
