// The crowdsim-bench subcommands; each returns the process exit code.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/spec_file_kind.h"
#include "crowdsim/bench/suite.h"

namespace crowdsim::cli {

/// Loads a suite with its --set overrides, or prints every error (for a training file, instead,
/// that it is one and to train it; `command` is the one that wanted a suite) and returns nothing.
std::optional<Suite> LoadOrReport(const std::string& file, PluginRegistry& registry,
                                  const std::vector<std::string>& overrides,
                                  const std::string& command);

int RunCommand(const std::vector<std::string>& args);
int MergeCommand(const std::vector<std::string>& args);
int ValidateCommand(const std::vector<std::string>& args);
int ListPluginsCommand(const std::vector<std::string>& args);
int TrainCommand(const std::vector<std::string>& args);
int TrainAllCommand(const std::vector<std::string>& args);
int RenderCommand(const std::vector<std::string>& args);
int ReportCommand(const std::vector<std::string>& args);
int ScoreCommand(const std::vector<std::string>& args);

}  // namespace crowdsim::cli
