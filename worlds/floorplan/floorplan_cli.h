// `floorplan import | preview | dataset`: the command line of the floor-plan importer.
#pragma once

#include <string>
#include <vector>

namespace crowdsim::floorplan {

/// Runs one floorplan command; `args` excludes the program and "floorplan" words (e.g.
/// {"import", "plan.png", "--out", "w.yaml"}). Returns the exit code: 0 ok, 1 failed, 2 usage.
int RunFloorplanCli(const std::vector<std::string>& args);

}  // namespace crowdsim::floorplan
