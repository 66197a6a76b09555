// The robot policy a Python program drives: it returns the velocity the program chose for
// this step (Env.step) or asks a Python callable (evaluate). Lives in the Python module only.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/policy.h"

namespace crowdsim::python {

class PythonPolicy final : public Policy {
 public:
  PythonPolicy(std::vector<std::string> sensors, int max_humans, PyObject* callable)
      : sensors_(std::move(sensors)), max_humans_(max_humans), callable_(callable) {}

  PolicyNeeds Needs() const override { return PolicyNeeds{false, false, sensors_}; }
  void Reset(const EpisodeContext& ctx) override {}
  Action Decide(const Observation& obs) override;

  /// Env.step: the velocity of the next Decide (world frame, m/s).
  void SetNextVelocity(const Vec2& v) { next_ = v; }

 private:
  std::vector<std::string> sensors_;
  int max_humans_ = 0;
  /// Borrowed (evaluate() holds it; no reference counting off the GIL); null: Env mode.
  PyObject* callable_ = nullptr;
  std::optional<Vec2> next_;
};

/// A plugin made in this process (no shared library) whose factory makes a PythonPolicy: put
/// in a row in place of the suite's robot policy, the harness runs the row unchanged
/// otherwise. A factory takes only Params, so what the next PythonPolicy gets (sensors it
/// needs, humans to pad to, callable or None) is set just before the row's objects are made.
const LoadedPlugin& PythonPolicyPlugin();
void SetNextPythonPolicy(std::vector<std::string> sensors, int max_humans, PyObject* callable);

}  // namespace crowdsim::python
