#include "value_rl/state_encoding.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "crowdsim/kinematics.h"

namespace crowdsim::value_rl {

void AppendSelf(const AgentState& robot, const Frame& frame, bool heading,
                std::vector<float>* out) {
  const Vec2 v = frame.VectorToLocal(robot.velocity);
  out->push_back(static_cast<float>((robot.goal - robot.position).norm()));
  out->push_back(static_cast<float>(robot.v_pref));
  // CrowdNav's theta - rot: the heading from the goal's direction; 0 for a holonomic robot.
  out->push_back(heading ? static_cast<float>(WrapAngle(robot.heading - HeadingToGoal(robot)))
                         : 0.0f);
  out->push_back(static_cast<float>(robot.radius));
  out->push_back(static_cast<float>(v.x()));
  out->push_back(static_cast<float>(v.y()));
}

void AppendHuman(const PersonObservation& person, double robot_radius, std::vector<float>* out) {
  out->push_back(static_cast<float>(person.position.x()));
  out->push_back(static_cast<float>(person.position.y()));
  out->push_back(static_cast<float>(person.velocity.x()));
  out->push_back(static_cast<float>(person.velocity.y()));
  out->push_back(static_cast<float>(person.radius));
  out->push_back(static_cast<float>(person.position.norm()));
  out->push_back(static_cast<float>(robot_radius + person.radius));
}

namespace {

const SensorReading& Find(std::span<const SensorReading> readings, const char* name) {
  for (const auto& r : readings) {
    if (r.sensor == name) return r;
  }
  throw std::runtime_error(std::string("the observation has no '") + name +
                           "' reading; add the sensor to the row's sensors list");
}

}  // namespace

EncodedState EncodeState(const ValueRlConfig& config, const AgentState& robot, const Frame& frame,
                         std::span<const SensorReading> readings) {
  EncodedState state;
  std::vector<float>& v = state.values;
  v.reserve(SelfInputs(config) + config.LidarInputs() + 6 * kHumanDim);
  AppendSelf(robot, frame, config.unicycle_actions, &v);
  if (config.route) {
    const SensorReading& route = Find(readings, "route");
    if (static_cast<int>(route.values.size()) != kRouteDim) {
      throw std::runtime_error("the route reading has " + std::to_string(route.values.size()) +
                               " values, expected " + std::to_string(kRouteDim));
    }
    for (double x : route.values) v.push_back(static_cast<float>(x));
  }
  if (UsesLidar(config.sensors)) {
    const SensorReading& lidar = Find(readings, "lidar2d");
    if (static_cast<int>(lidar.ranges.size()) != config.lidar_beams) {
      throw std::runtime_error("the lidar2d reading has " + std::to_string(lidar.ranges.size()) +
                               " beams but the policy was built for lidar_beams = " +
                               std::to_string(config.lidar_beams) + "; make the two equal");
    }
    // Ranges scaled to [0, 1] so that every beam weighs alike whatever max_range is.
    const double scale = lidar.max_range > 0.0 ? 1.0 / lidar.max_range : 1.0;
    for (double r : lidar.ranges) v.push_back(static_cast<float>(std::min(r * scale, 1.0)));
  }
  if (UsesPerson(config.sensors)) {
    const SensorReading& people = Find(readings, "person");
    for (const auto& p : people.people) AppendHuman(p, robot.radius, &v);
    if (people.people.empty()) {
      AppendHuman(PersonObservation{Vec2(-kAbsentHumanDistance, 0.0), Vec2::Zero(), robot.radius},
                  robot.radius, &v);
    }
  }
  return state;
}

int HumanRows(const ValueRlConfig& config, const EncodedState& state) {
  const int rest =
      static_cast<int>(state.values.size()) - SelfInputs(config) - config.LidarInputs();
  return rest > 0 ? rest / kHumanDim : 0;
}

}  // namespace crowdsim::value_rl
