// The crowdsim-bench subcommands; each returns the process exit code.
#pragma once

#include <string>
#include <vector>

namespace crowdsim::cli {

int RunCommand(const std::vector<std::string>& args);
int MergeCommand(const std::vector<std::string>& args);
int ValidateCommand(const std::vector<std::string>& args);
int ListPluginsCommand(const std::vector<std::string>& args);
int TrainCommand(const std::vector<std::string>& args);
int TrainAllCommand(const std::vector<std::string>& args);
int RenderCommand(const std::vector<std::string>& args);
int ReportCommand(const std::vector<std::string>& args);

}  // namespace crowdsim::cli
