// The robot policy a Python program drives: it returns the velocity the program chose for
// this step (Env.step) or asks a Python callable (evaluate). Lives in the Python module only.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <cstddef>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/policy.h"

namespace crowdsim::python {

/// Whether a run driven from Python must stop, and the Python exception that says why:
/// Ctrl-C (Python's handler only sets a flag while C++ runs; it is checked between episodes)
/// or a policy that raised KeyboardInterrupt or SystemExit. Raised again to the caller once
/// the run has stopped, with its traceback.
class PythonStop {
 public:
  /// Made by the thread that starts the run (with the GIL): the only one that checks for
  /// Ctrl-C (Python runs signal handlers in the main thread alone; other workers taking the
  /// GIL between episodes only queued for it).
  PythonStop() : owner_(std::this_thread::get_id()) {}
  /// RunOptions::stop_requested (any thread, GIL not held).
  bool Requested();
  /// Keeps `error` as the reason (the first one kept wins); GIL held.
  void Keep(const pybind11::error_already_set& error);
  /// Raises the kept exception, if any; GIL held.
  void RaiseIfKept();

 private:
  std::thread::id owner_;
  std::atomic<bool> stop_{false};
  std::mutex mutex_;
  std::optional<pybind11::error_already_set> error_;
};

class PythonPolicy final : public Policy {
 public:
  /// `callable` borrowed (its binding keeps it alive); null: Env mode. `stop` may be null.
  PythonPolicy(std::vector<std::string> sensors, int max_humans, PyObject* callable,
               PythonStop* stop)
      : sensors_(std::move(sensors)), max_humans_(max_humans), callable_(callable), stop_(stop) {}

  /// A non-holonomic robot gets its two numbers as a (linear, angular) command.
  PolicyNeeds Needs() const override {
    PolicyNeeds needs{false, false, sensors_};
    needs.non_holonomic = NonHolonomicDrive::kCommands;
    return needs;
  }
  void Reset(const EpisodeContext& ctx) override { holonomic_ = ctx.kinematics.Holonomic(); }
  Action Decide(const Observation& obs) override;

  /// Env.step: the next Decide's velocity (world frame, m/s) or, for a non-holonomic robot,
  /// its (linear m/s, angular rad/s) command.
  void SetNextVelocity(const Vec2& v) { next_ = v; }

 private:
  std::vector<std::string> sensors_;
  int max_humans_ = 0;
  PyObject* callable_ = nullptr;
  PythonStop* stop_ = nullptr;
  std::optional<Vec2> next_;
  bool holonomic_ = true;
};

/// The Python policy of one Env, VectorEnv or evaluate() call: a plugin of its own (made in
/// this process, no shared library) whose factory makes PythonPolicy objects with this
/// binding's sensors, humans to pad to and callable. A factory takes only Params, so each live
/// binding holds one of a fixed number of slots, each with a factory of its own: two threads
/// evaluating two policies at once each get theirs (one shared "next policy" gave one thread
/// the other's policy, or a freed one). Made and destroyed with the GIL held.
class PythonPolicyBinding {
 public:
  /// How many bindings can be alive at once.
  static constexpr std::size_t kMaxAlive = 256;

  /// `callable`: evaluate()'s policy, kept alive here; a null object for Env mode. `stop` (may
  /// be null) receives a KeyboardInterrupt or SystemExit the callable raises.
  PythonPolicyBinding(std::vector<std::string> sensors, int max_humans, pybind11::object callable,
                      PythonStop* stop);
  ~PythonPolicyBinding();
  PythonPolicyBinding(const PythonPolicyBinding&) = delete;
  PythonPolicyBinding& operator=(const PythonPolicyBinding&) = delete;

  /// The plugin to put in the row in place of its robot policy.
  const LoadedPlugin& plugin() const;

 private:
  std::size_t slot_;
};

}  // namespace crowdsim::python
