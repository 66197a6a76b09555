// `crowdsim-bench floorplan import | preview | dataset`: the importer's command line, registered
// in crowdsim-bench's command table (harness/app/main.cc), which reports its errors.
#pragma once

#include <string>
#include <vector>

namespace crowdsim::floorplan {

/// The command's usage, as `crowdsim-bench help floorplan` prints it.
extern const char kFloorplanUsage[];

/// Runs one floorplan command; `args` follow the word "floorplan" (e.g. {"import", "plan.png",
/// "--out", "w.yaml"}). Returns 0; throws cli::UsageError for a usage problem (exit 2) and
/// FloorplanError, or another exception, when the work fails (exit 1), nothing written.
int FloorplanCommand(const std::vector<std::string>& args);

}  // namespace crowdsim::floorplan
