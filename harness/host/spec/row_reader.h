// Internal: the row spec reader (policy, weights, sensors, world, humans), shared by suite rows and
// training files.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "crowdsim/bench/suite.h"
#include "spec/schema_defaults.h"
#include "spec/suite_reader.h"

namespace crowdsim::suite_internal {

/// The keys of a row spec.
inline const std::vector<std::string> kRowSpecKeys = {"policy",     "params", "weights", "sensors",
                                                      "kinematics", "world",  "humans"};

/// The keys of a `humans:` map.
inline const std::vector<std::string> kHumansKeys = {"count",  "policy", "params",     "goal_mode",
                                                     "radius", "v_pref", "distracted", "groups"};
/// What a `humans:` map holds, for "must be a map of ...".
inline constexpr const char* kHumansWhat =
    "count, policy, params, goal_mode, radius, v_pref, distracted, groups";

/// Fallbacks for what a row lacks: a suite's top-level `world`, `humans` (per key),
/// `robot.sensors` and `robot.kinematics`, then schema defaults.
struct RowDefaults {
  const SchemaDefaults& schema;
  YAML::Node world{YAML::NodeType::Undefined};
  YAML::Node humans{YAML::NodeType::Undefined};
  YAML::Node sensors{YAML::NodeType::Undefined};
  YAML::Node kinematics{YAML::NodeType::Undefined};
};

/// Where the files that hold row specs differ.
struct RowRules {
  std::string policy_hint;        ///< what `policy` names, for "missing key 'policy' (...)"
  std::string missing_world;      ///< the error when neither the row nor the defaults give a world
  bool sensors_required = false;  ///< a row without sensors is an error (else: no sensors)
  /// `humans.count` may be a range [min, max], drawn per episode (training files).
  bool humans_range = false;
};

/// Reads the row spec in map `n` at `path` ("": top level) into `row`; the caller checks keys.
/// `base` resolves relative paths.
void ReadRowSpec(Reader& r, const YAML::Node& n, const std::string& path, const RowDefaults& d,
                 const RowRules& rules, const std::filesystem::path& base, RowSpec* row);

/// Reads a world map (`source:` plus the world plugin's parameters).
void ReadWorld(Reader& r, const YAML::Node& n, const std::string& path,
               const std::filesystem::path& base, PluginUse* out);

/// Reads a sensors list (names or maps with `type:` and parameters).
void ReadSensors(Reader& r, const YAML::Node& n, const std::string& path,
                 const std::filesystem::path& base, std::vector<PluginUse>* out);

}  // namespace crowdsim::suite_internal
