#include "observation_tensors.h"

#include <ATen/ops/full.h>
#include <ATen/ops/scalar_tensor.h>
#include <ATen/ops/zeros.h>

#include <algorithm>

namespace crowdsim::torchscript {

namespace {

constexpr int kRobotValues = 9;
constexpr int kHumanValues = 5;

at::Tensor RobotTensor(const AgentState& s) {
  at::Tensor robot = at::zeros({kRobotValues}, at::kDouble);
  double* r = robot.data_ptr<double>();
  const double values[kRobotValues] = {s.position.x(), s.position.y(), s.velocity.x(),
                                       s.velocity.y(), s.goal.x(),     s.goal.y(),
                                       s.radius,       s.v_pref,       s.heading};
  std::copy(values, values + kRobotValues, r);
  return robot;
}

}  // namespace

ObservationDict MakeObservationDict(const Observation& obs, int humans) {
  size_t seen = 0;
  for (const SensorReading& reading : obs.readings) seen += reading.people.size();
  const int64_t rows = std::max<int64_t>(humans, static_cast<int64_t>(seen));
  at::Tensor people = at::zeros({rows, kHumanValues}, at::kDouble);
  at::Tensor mask = at::zeros({rows}, at::kBool);
  double* h = people.data_ptr<double>();
  bool* m = mask.data_ptr<bool>();
  for (const SensorReading& reading : obs.readings) {
    for (const PersonObservation& p : reading.people) {
      const double values[kHumanValues] = {p.position.x(), p.position.y(), p.velocity.x(),
                                           p.velocity.y(), p.radius};
      h = std::copy(values, values + kHumanValues, h);
      *m++ = true;
    }
  }
  ObservationDict dict;
  dict.insert("robot", RobotTensor(obs.self));
  dict.insert("time", at::scalar_tensor(obs.time, at::kDouble));
  dict.insert("humans", people);
  dict.insert("humans_mask", mask);
  for (const SensorReading& reading : obs.readings) {
    if (reading.ranges.empty()) continue;
    at::Tensor lidar = at::zeros({static_cast<int64_t>(reading.ranges.size())}, at::kDouble);
    std::copy(reading.ranges.begin(), reading.ranges.end(), lidar.data_ptr<double>());
    dict.insert("lidar", lidar);
    break;
  }
  return dict;
}

ObservationDict ProbeObservationDict(int humans, int lidar_beams) {
  Observation obs;
  obs.self.goal = Vec2(4.0, 0.0);
  obs.self.v_pref = 1.0;
  obs.self.radius = 0.3;
  ObservationDict dict = MakeObservationDict(obs, humans);
  if (lidar_beams > 0) dict.insert("lidar", at::full({lidar_beams}, 5.0, at::kDouble));
  return dict;
}

}  // namespace crowdsim::torchscript
