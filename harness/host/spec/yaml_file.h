// The host's YAML loading: loader problems as SuiteErrors; a run folder stands for its suite.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "crowdsim/bench/suite.h"

namespace crowdsim::suite_internal {

/// The document of `file`, or a null node with `errors` saying why (duplicate keys count); `what`:
/// the file's kind.
YAML::Node LoadYamlFile(const std::filesystem::path& file, const std::string& what,
                        std::vector<SuiteError>* errors);

}  // namespace crowdsim::suite_internal
