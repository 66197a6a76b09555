// What build this is, for self-describing results.
#pragma once

namespace crowdsim {

/// The project version (CMake's project version).
const char* Version();

/// The git commit the library was built from ("-dirty" with uncommitted changes, "unknown"
/// outside a git checkout); refreshed at every build.
const char* GitCommit();

}  // namespace crowdsim
