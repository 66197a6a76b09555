#include "observation_tensors.h"

#include <ATen/ops/full.h>
#include <ATen/ops/zeros.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace crowdsim::torchscript {

namespace {

constexpr int kRobotValues = 9;
constexpr int kHumanValues = 5;
constexpr int kRouteValues = 3;  // plugins/sensors/route: distance, waypoint x, y

size_t PeopleSeen(std::span<const SensorReading> readings) {
  size_t seen = 0;
  for (const SensorReading& reading : readings) seen += reading.people.size();
  return seen;
}

/// The first range sensor's reading (the `lidar` key), or null.
const SensorReading* RangeReading(std::span<const SensorReading> readings) {
  for (const SensorReading& reading : readings) {
    if (!reading.ranges.empty()) return &reading;
  }
  return nullptr;
}

/// The route sensor's reading; an error naming the fix when there is none or it is another
/// shape.
const SensorReading& RouteReading(std::span<const SensorReading> readings) {
  for (const SensorReading& reading : readings) {
    if (reading.sensor != "route") continue;
    if (reading.values.size() != kRouteValues) {
      throw std::runtime_error("torchscript: the route reading has " +
                               std::to_string(reading.values.size()) + " values, expected " +
                               std::to_string(kRouteValues));
    }
    return reading;
  }
  throw std::runtime_error(
      "torchscript: params.route is true but the observation has no route reading; add "
      "`route` to the row's robot sensors");
}

/// `count` observations as tensors with a leading dimension of `count`, filled row by row.
class ObservationStack {
 public:
  ObservationStack(int64_t count, int64_t human_rows, int64_t beams, bool route)
      : robot_(at::zeros({count, kRobotValues}, at::kDouble)),
        humans_(at::zeros({count, human_rows, kHumanValues}, at::kDouble)),
        mask_(at::zeros({count, human_rows}, at::kBool)),
        time_(at::zeros({count}, at::kDouble)),
        human_rows_(human_rows),
        beams_(beams) {
    if (beams > 0) lidar_ = at::zeros({count, beams}, at::kDouble);
    if (route) route_ = at::zeros({count, kRouteValues}, at::kDouble);
  }

  void Put(int64_t i, const AgentState& s, std::span<const SensorReading> readings, double time) {
    const double robot[kRobotValues] = {s.position.x(), s.position.y(), s.velocity.x(),
                                        s.velocity.y(), s.goal.x(),     s.goal.y(),
                                        s.radius,       s.v_pref,       s.heading};
    std::copy(robot, robot + kRobotValues, robot_.data_ptr<double>() + i * kRobotValues);
    double* h = humans_.data_ptr<double>() + i * human_rows_ * kHumanValues;
    bool* m = mask_.data_ptr<bool>() + i * human_rows_;
    for (const SensorReading& reading : readings) {
      for (const PersonObservation& p : reading.people) {
        const double values[kHumanValues] = {p.position.x(), p.position.y(), p.velocity.x(),
                                             p.velocity.y(), p.radius};
        h = std::copy(values, values + kHumanValues, h);
        *m++ = true;
      }
    }
    time_.data_ptr<double>()[i] = time;
    if (const SensorReading* lidar = RangeReading(readings); lidar != nullptr && beams_ > 0) {
      std::copy(lidar->ranges.begin(), lidar->ranges.end(), lidar_.data_ptr<double>() + i * beams_);
    }
    if (route_.defined()) {
      const SensorReading& route = RouteReading(readings);
      std::copy(route.values.begin(), route.values.end(),
                route_.data_ptr<double>() + i * kRouteValues);
    }
  }

  /// The stacked tensors; `single` drops the leading dimension (one observation).
  ObservationDict Dict(bool single) const {
    auto shaped = [single](const at::Tensor& t) { return single ? t.select(0, 0) : t; };
    ObservationDict dict;
    dict.insert("robot", shaped(robot_));
    dict.insert("time", shaped(time_));
    dict.insert("humans", shaped(humans_));
    dict.insert("humans_mask", shaped(mask_));
    if (lidar_.defined()) dict.insert("lidar", shaped(lidar_));
    if (route_.defined()) dict.insert("route", shaped(route_));
    return dict;
  }

 private:
  at::Tensor robot_, humans_, mask_, time_, lidar_, route_;
  int64_t human_rows_;
  int64_t beams_;
};

int64_t BeamsOf(std::span<const SensorReading> readings) {
  const SensorReading* lidar = RangeReading(readings);
  return lidar != nullptr ? static_cast<int64_t>(lidar->ranges.size()) : 0;
}

}  // namespace

ObservationDict MakeObservationDict(const Observation& obs, int humans, bool route) {
  const int64_t rows = std::max<int64_t>(humans, static_cast<int64_t>(PeopleSeen(obs.readings)));
  ObservationStack stack(1, rows, BeamsOf(obs.readings), route);
  stack.Put(0, obs.self, obs.readings, obs.time);
  return stack.Dict(/*single=*/true);
}

ObservationDict MakeLookaheadDict(std::span<const LookaheadOutcome> outcomes, double time,
                                  int humans, bool route) {
  int64_t rows = humans;
  int64_t beams = 0;
  for (const LookaheadOutcome& o : outcomes) {
    rows = std::max<int64_t>(rows, static_cast<int64_t>(PeopleSeen(o.readings)));
    beams = std::max(beams, BeamsOf(o.readings));
  }
  ObservationStack stack(static_cast<int64_t>(outcomes.size()), rows, beams, route);
  for (size_t i = 0; i < outcomes.size(); ++i) {
    stack.Put(static_cast<int64_t>(i), outcomes[i].robot, outcomes[i].readings, time);
  }
  return stack.Dict(/*single=*/false);
}

namespace {

// The probe's route: 4 m straight to the goal, the waypoint 1 m ahead.
SensorReading ProbeRoute() {
  SensorReading route;
  route.sensor = "route";
  route.values = {4.0, 1.0, 0.0};
  return route;
}

}  // namespace

ObservationDict ProbeObservationDict(int humans, int lidar_beams, bool route) {
  Observation obs;
  obs.self.goal = Vec2(4.0, 0.0);
  obs.self.v_pref = 1.0;
  obs.self.radius = 0.3;
  if (route) obs.readings.push_back(ProbeRoute());
  ObservationDict dict = MakeObservationDict(obs, humans, route);
  if (lidar_beams > 0) dict.insert("lidar", at::full({lidar_beams}, 5.0, at::kDouble));
  return dict;
}

ObservationDict ProbeLookaheadDict(int actions, int humans, int lidar_beams, bool route) {
  std::vector<LookaheadOutcome> outcomes(static_cast<size_t>(actions));
  for (LookaheadOutcome& o : outcomes) {
    o.robot.goal = Vec2(4.0, 0.0);
    o.robot.v_pref = 1.0;
    o.robot.radius = 0.3;
    if (route) o.readings.push_back(ProbeRoute());
  }
  ObservationDict dict = MakeLookaheadDict(outcomes, 0.0, humans, route);
  if (lidar_beams > 0) dict.insert("lidar", at::full({actions, lidar_beams}, 5.0, at::kDouble));
  return dict;
}

}  // namespace crowdsim::torchscript
