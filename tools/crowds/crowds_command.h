// `crowdsim-bench crowds import | dataset`: the crowd importer's command line, registered in
// crowdsim-bench's command table (harness/app/main.cc), which reports its errors.
#pragma once

#include <string>
#include <vector>

namespace crowdsim::crowds {

/// The command's usage, as `crowdsim-bench help crowds` prints it.
extern const char kCrowdsUsage[];

/// Runs one crowds command; `args` follow the word "crowds". Returns 0; throws cli::UsageError
/// for a usage problem (exit 2) and crowd_tracks::TrackFileError, naming file and line, when a
/// scene file is bad (exit 1), nothing written.
int CrowdsCommand(const std::vector<std::string>& args);

}  // namespace crowdsim::crowds
