// Dev entry point: crowdsim-floorplan <command> ... (the same as `crowdsim-bench floorplan`).
#include <string>
#include <vector>

#include "floorplan_cli.h"

int main(int argc, char** argv) {
  return crowdsim::floorplan::RunFloorplanCli(std::vector<std::string>(argv + 1, argv + argc));
}
