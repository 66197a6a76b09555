// crowdsim-bench: the command-line entry point.
#include <iostream>
#include <string>
#include <vector>

#include "cli_args.h"
#include "commands.h"

namespace {

constexpr const char* kUsage = R"(crowdsim-bench: robot navigation among people and obstacles (CrowdSim++ in C++)

usage:
  crowdsim-bench run SUITE.yaml [--out DIR] [--jobs N] [--episodes N] [--fresh] [--quiet]
      runs a suite; writes DIR/table.md, table.csv, episodes.csv, manifest.json
      (DIR defaults to results/<suite name>/); rerunning resumes finished episodes
  crowdsim-bench validate SUITE.yaml...
      checks suites without running them; reports every error with file:line:col
  crowdsim-bench list-plugins [PLUGIN.so...]
      lists every plugin found, with its kind, description and parameters
  crowdsim-bench help
)";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    std::cout << kUsage;
    return args.empty() ? 2 : 0;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  try {
    if (command == "run") return crowdsim::cli::RunCommand(args);
    if (command == "validate") return crowdsim::cli::ValidateCommand(args);
    if (command == "list-plugins") return crowdsim::cli::ListPluginsCommand(args);
    std::cerr << "error: unknown command '" << command
              << "' (valid: run, validate, list-plugins, help)\n\n" << kUsage;
    return 2;
  } catch (const crowdsim::cli::UsageError& e) {
    std::cerr << "error: " << e.what() << "\n\n" << kUsage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
