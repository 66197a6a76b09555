// Internal: a row's `kinematics:` (the robot's motion model) and its canonical text.
#pragma once

#include <yaml-cpp/yaml.h>

#include <ostream>
#include <string>
#include <vector>

#include "crowdsim/kinematics.h"
#include "spec/suite_reader.h"

namespace crowdsim::suite_internal {

/// The keys of a `kinematics:` map.
inline const std::vector<std::string> kKinematicsKeys = {"model", "angular_speed_max", "accel_max",
                                                         "angular_accel_max", "track_velocity"};

/// Reads `kinematics: unicycle` or `kinematics: {model: unicycle, accel_max: 1.0, ...}`.
void ReadKinematics(Reader& r, const YAML::Node& n, const std::string& path, RobotKinematics* out);

/// Appends " kinematics:..." unless `k` is the default robot, so old config hashes hold.
void CanonicalKinematics(const RobotKinematics& k, std::ostream& os);

}  // namespace crowdsim::suite_internal
