// The host's YAML loading for suites and training files: the shared loader's problems as
// SuiteErrors, and a run's output folder given as a file named with the suite it ran.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "crowdsim/bench/suite.h"

namespace crowdsim::suite_internal {

/// The document of `file`, or a null node with `errors` saying why (`what` names the kind of
/// file in messages, e.g. "suite file"). Duplicate keys count; any problem returns null.
YAML::Node LoadYamlFile(const std::filesystem::path& file, const std::string& what,
                        std::vector<SuiteError>* errors);

}  // namespace crowdsim::suite_internal
