#include "observation_arrays.h"

#include <pybind11/numpy.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace py = pybind11;

namespace crowdsim::python {

void WriteRobotState(const Observation& obs, double* out) {
  const AgentState& s = obs.self;
  const double values[kRobotStateSize] = {s.position.x(), s.position.y(), s.velocity.x(),
                                          s.velocity.y(), s.goal.x(),     s.goal.y(),
                                          s.radius,       s.v_pref,       s.heading};
  std::copy(values, values + kRobotStateSize, out);
}

int PeopleSeen(const Observation& obs) {
  size_t n = 0;
  for (const SensorReading& reading : obs.readings) n += reading.people.size();
  return static_cast<int>(n);
}

void WriteHumans(const Observation& obs, int rows, double* humans, bool* mask) {
  const int seen = PeopleSeen(obs);
  if (seen > rows) {
    throw std::length_error("the person sensors see " + std::to_string(seen) +
                            " people, more than the " + std::to_string(rows) +
                            " rows of the humans array");
  }
  int i = 0;
  for (const SensorReading& reading : obs.readings) {
    for (const PersonObservation& p : reading.people) {
      double* h = humans + 5 * i;
      h[0] = p.position.x();
      h[1] = p.position.y();
      h[2] = p.velocity.x();
      h[3] = p.velocity.y();
      h[4] = p.radius;
      mask[i++] = true;
    }
  }
  std::fill(humans + 5 * i, humans + 5 * rows, 0.0);
  std::fill(mask + i, mask + rows, false);
}

const std::vector<double>* FirstRanges(const Observation& obs) {
  for (const SensorReading& reading : obs.readings)
    if (!reading.ranges.empty()) return &reading.ranges;
  return nullptr;
}

py::dict ObservationDict(const Observation& obs, int max_humans) {
  py::dict d;
  py::array_t<double> robot(kRobotStateSize);
  WriteRobotState(obs, robot.mutable_data());
  d["robot"] = robot;
  d["time"] = obs.time;
  const int rows = std::max(max_humans, PeopleSeen(obs));
  py::array_t<double> humans({rows, 5});
  py::array_t<bool> mask(rows);
  WriteHumans(obs, rows, humans.mutable_data(), mask.mutable_data());
  d["humans"] = humans;
  d["humans_mask"] = mask;
  if (const std::vector<double>* ranges = FirstRanges(obs)) {
    py::array_t<double> lidar(static_cast<py::ssize_t>(ranges->size()));
    std::copy(ranges->begin(), ranges->end(), lidar.mutable_data());
    d["lidar"] = lidar;
  }
  // Any other sensor's features under its name (route: distance, waypoint x, y).
  for (const SensorReading& reading : obs.readings) {
    if (reading.values.empty()) continue;
    py::array_t<double> values(static_cast<py::ssize_t>(reading.values.size()));
    std::copy(reading.values.begin(), reading.values.end(), values.mutable_data());
    d[py::str(reading.sensor)] = values;
  }
  return d;
}

}  // namespace crowdsim::python
