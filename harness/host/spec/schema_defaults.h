// Internal: defaults that name plugins (humans' policy, teacher), read from
// DataRoot()/suites/schema/defaults.yaml so code names no plugin.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "crowdsim/bench/suite.h"

namespace crowdsim::suite_internal {

struct SchemaDefaults {
  std::filesystem::path file;            ///< where they are read from, for messages
  std::string humans_policy;             ///< humans.policy when a row has humans
  std::string humans_policy_without;     ///< humans.policy when humans.count is 0
  std::string il_policy;                 ///< training.il_policy
  YAML::Node il_params_robot_invisible;  ///< maps: parameter -> value, given unless il_params
  YAML::Node il_params_robot_visible;    ///  does, where the teacher has the parameter
};

/// The defaults file's path: DataRoot()/suites/schema/defaults.yaml.
std::filesystem::path SchemaDefaultsFile();

/// Reads the defaults; nullopt with `errors` (naming the defaults file) when it is missing or
/// malformed.
std::optional<SchemaDefaults> LoadSchemaDefaults(std::vector<SuiteError>* errors);

}  // namespace crowdsim::suite_internal
