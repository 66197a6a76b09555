#include "python_policy.h"

#include <pybind11/numpy.h>

#include <cmath>
#include <stdexcept>

#include "crowdsim/plugin_abi.h"
#include "observation_arrays.h"

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

const PluginDescriptor kDescriptor = {kPluginAbiVersion,
                                      PluginKind::kPolicy,
                                      "python",
                                      "a policy written in Python (crowdsim_bench)",
                                      &NoParams,
                                      &MakePythonPolicy,
                                      nullptr,
                                      nullptr,
                                      nullptr};

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

}  // namespace crowdsim::python
