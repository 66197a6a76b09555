// Internal to the core: the reader of a row spec (the robot policy with its parameters and
// weights, its sensors, the world and the humans), the one part suites and training files
// share. A suite's rows are row specs with a label, info and a reference; a training file's
// top level is one row spec plus name, seed, sim and a `training:` block.
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
inline const std::vector<std::string> kRowSpecKeys = {"policy",  "params", "weights",
                                                      "sensors", "world",  "humans"};

/// The keys of a `humans:` map.
inline const std::vector<std::string> kHumansKeys = {"count", "policy", "params", "goal_mode"};

/// What a row uses for what it does not give itself: a suite's top-level `world`, `humans` (key
/// by key) and `robot.sensors` (a training file has none: its top level is the row), then the
/// schema defaults (the humans' policy).
struct RowDefaults {
  const SchemaDefaults& schema;
  YAML::Node world{YAML::NodeType::Undefined};
  YAML::Node humans{YAML::NodeType::Undefined};
  YAML::Node sensors{YAML::NodeType::Undefined};
};

/// Where the files that hold row specs differ.
struct RowRules {
  std::string policy_hint;        ///< what `policy` names, for "missing key 'policy' (...)"
  std::string missing_world;      ///< the error when neither the row nor the defaults give a world
  bool sensors_required = false;  ///< a row without sensors is an error (else: no sensors)
  /// `humans.count` may be a range [min, max], drawn per episode (training files).
  bool humans_range = false;
};

/// Reads the row spec in map `n` (at key path `path`, "" for the top level) into `row`; the
/// caller checks the map's keys (kRowSpecKeys plus its own). `base` resolves relative paths.
void ReadRowSpec(Reader& r, const YAML::Node& n, const std::string& path, const RowDefaults& d,
                 const RowRules& rules, const std::filesystem::path& base, RowSpec* row);

/// Reads a world map (`source:` plus the world plugin's parameters).
void ReadWorld(Reader& r, const YAML::Node& n, const std::string& path,
               const std::filesystem::path& base, PluginUse* out);

/// Reads a sensors list (names or maps with `type:` and parameters).
void ReadSensors(Reader& r, const YAML::Node& n, const std::string& path,
                 const std::filesystem::path& base, std::vector<PluginUse>* out);

}  // namespace crowdsim::suite_internal
