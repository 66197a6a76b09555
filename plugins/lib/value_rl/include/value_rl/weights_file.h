// Weights files (.pt, libtorch archives) that carry what they were trained for, so a
// mismatch is an error naming the file and the values instead of a shape crash.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "value_rl/config.h"
#include "value_rl/value_network.h"

namespace torch::serialize {
class OutputArchive;
}

namespace crowdsim::value_rl {

/// What a weights file was trained for.
struct WeightsMeta {
  std::string model;    ///< cadrl | sarl
  std::string sensors;  ///< person | lidar | lidar+person, each optionally +route
  int64_t actions = 0;
  int64_t lidar_beams = 0;   ///< 0 without lidar
  double route_prior = 0.0;  ///< written only when not 0 (files before it have none)
  RoutePriorShape route_prior_shape = RoutePriorShape::kLinear;  ///< written beside it
  std::string action_space = "holonomic";  ///< written only when not holonomic
};

/// The metadata a policy with `config` expects.
WeightsMeta MetaOf(const ValueRlConfig& config);

/// Writes the network and `meta` (atomically: a temporary file, then a rename).
void SaveWeightsFile(const ValueNetwork& net, const WeightsMeta& meta,
                     const std::filesystem::path& file);

/// Writes `archive` to `file` whole or not at all; a full disk throws std::runtime_error naming
/// the file and the reason, the previous file unchanged.
void SaveArchive(torch::serialize::OutputArchive& archive, const std::filesystem::path& file);

/// Loads into `net`; throws std::runtime_error naming the file, the expected and the found
/// values when the metadata differ, the entry when the file is damaged (CRC-32 or size of an
/// entry wrong, truncated), or what else is wrong with the file.
void LoadWeightsFile(const WeightsMeta& expected, const std::filesystem::path& file,
                     ValueNetwork* net);

}  // namespace crowdsim::value_rl
