#include "python_policy.h"

#include <pybind11/numpy.h>

#include <cmath>
#include <stdexcept>

#include "crowdsim/plugin_abi.h"

namespace py = pybind11;

namespace crowdsim::python {
namespace {

struct NextPolicy {
  std::vector<std::string> sensors;
  int max_humans = 0;
  PyObject* callable = nullptr;
};
NextPolicy& Next() {
  static NextPolicy next;
  return next;
}

std::unique_ptr<Policy> MakePythonPolicy(const Params&) {
  NextPolicy& n = Next();
  return std::make_unique<PythonPolicy>(n.sensors, n.max_humans, n.callable);
}

ParamSchema NoParams() { return {}; }

const PluginDescriptor kDescriptor = {kPluginAbiVersion, PluginKind::kPolicy, "python",
                                      "a policy written in Python (crowdsim_bench)", &NoParams,
                                      &MakePythonPolicy, nullptr, nullptr};

Vec2 VelocityOf(const py::handle& v, const char* what) {
  py::array_t<double, py::array::c_style | py::array::forcecast> a;
  try {
    a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v);
  } catch (const py::error_already_set&) {
  }
  if (!a || a.size() != 2) {
    throw std::invalid_argument(std::string(what) +
                                " must be a velocity (vx, vy) in m/s, world frame: 2 numbers");
  }
  return Vec2(a.at(0), a.at(1));
}

}  // namespace

Action PythonPolicy::Decide(const Observation& obs) {
  if (callable_ == nullptr) {
    if (!next_) throw std::logic_error("python policy: no action was given for this step");
    const Vec2 v = *next_;
    next_.reset();
    return Action{v};
  }
  py::gil_scoped_acquire gil;
  try {
    const py::object out = py::handle(callable_)(ObservationDict(obs, max_humans_));
    return Action{VelocityOf(out, "the policy's return value")};
  } catch (py::error_already_set& e) {
    // The episode ends as policy_error with Python's message (the run goes on).
    throw std::runtime_error(std::string("python policy raised ") + e.what());
  }
}

const LoadedPlugin& PythonPolicyPlugin() {
  static const LoadedPlugin plugin = [] {
    LoadedPlugin p;
    p.path = "<python>";
    p.descriptor = &kDescriptor;
    p.schema = NoParams();
    return p;
  }();
  return plugin;
}

void SetNextPythonPolicy(std::vector<std::string> sensors, int max_humans, PyObject* callable) {
  Next() = NextPolicy{std::move(sensors), max_humans, callable};
}

py::dict ObservationDict(const Observation& obs, int max_humans) {
  py::dict d;
  const AgentState& s = obs.self;
  py::array_t<double> robot(9);
  double* r = robot.mutable_data();
  const double values[9] = {s.position.x(), s.position.y(), s.velocity.x(), s.velocity.y(),
                            s.goal.x(),     s.goal.y(),     s.radius,       s.v_pref,
                            s.heading};
  std::copy(values, values + 9, r);
  d["robot"] = robot;
  d["time"] = obs.time;

  // Humans seen by the person sensors, in the robot's frame (x towards the goal), padded.
  std::vector<const PersonObservation*> people;
  for (const SensorReading& reading : obs.readings)
    for (const PersonObservation& p : reading.people) people.push_back(&p);
  const int rows = std::max<int>(max_humans, static_cast<int>(people.size()));
  py::array_t<double> humans({rows, 5});
  py::array_t<bool> mask(rows);
  auto h = humans.mutable_unchecked<2>();
  auto m = mask.mutable_unchecked<1>();
  for (int i = 0; i < rows; ++i) {
    const bool seen = i < static_cast<int>(people.size());
    m(i) = seen;
    const PersonObservation* p = seen ? people[i] : nullptr;
    h(i, 0) = seen ? p->position.x() : 0.0;
    h(i, 1) = seen ? p->position.y() : 0.0;
    h(i, 2) = seen ? p->velocity.x() : 0.0;
    h(i, 3) = seen ? p->velocity.y() : 0.0;
    h(i, 4) = seen ? p->radius : 0.0;
  }
  d["humans"] = humans;
  d["humans_mask"] = mask;

  // The first range sensor's ranges (m; max_range where nothing is hit).
  for (const SensorReading& reading : obs.readings) {
    if (reading.ranges.empty()) continue;
    py::array_t<double> ranges(static_cast<py::ssize_t>(reading.ranges.size()));
    std::copy(reading.ranges.begin(), reading.ranges.end(), ranges.mutable_data());
    d["lidar"] = ranges;
    break;
  }
  return d;
}

}  // namespace crowdsim::python
