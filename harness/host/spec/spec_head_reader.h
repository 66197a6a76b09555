// Internal: the top-level keys of every experiment spec: `name`, `description`, `seed`, `sim:`.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <string>

#include "crowdsim/sim_config.h"
#include "spec/suite_reader.h"

namespace crowdsim::suite_internal {

/// What names an experiment and decides its randomness and physics.
struct SpecHead {
  std::string name;
  std::string description;
  std::uint64_t seed = 0;
  SimConfig sim;
};

/// The keys SpecHead is read from.
inline const std::vector<std::string> kSpecHeadKeys = {"name", "description", "seed", "sim"};

/// Reads name (naming the output folder `folder`, for messages), description, seed and sim.
SpecHead ReadSpecHead(Reader& r, const YAML::Node& root, const std::string& folder);

/// Reads the `sim:` map into `sim` (unknown keys and out-of-range values are errors).
void ReadSim(Reader& r, const YAML::Node& n, SimConfig* sim);

}  // namespace crowdsim::suite_internal
