#include "python_policy.h"

#include <pybind11/numpy.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "crowdsim/plugin_abi.h"
#include "observation_arrays.h"

namespace py = pybind11;

namespace crowdsim::python {
namespace {

constexpr std::size_t kSlots = PythonPolicyBinding::kMaxAlive;

/// What the policies of one binding are made with.
struct Slot {
  bool used = false;
  std::vector<std::string> sensors;
  int max_humans = 0;
  py::object callable;  // null in Env mode
  PythonStop* stop = nullptr;
};

std::mutex& SlotMutex() {
  static std::mutex mutex;
  return mutex;
}
// Never destroyed: a slot may still hold an object when the interpreter is already gone.
std::array<Slot, kSlots>& Slots() {
  static auto* slots = new std::array<Slot, kSlots>();
  return *slots;
}

std::unique_ptr<Policy> MakeFromSlot(std::size_t k) {
  std::lock_guard<std::mutex> lock(SlotMutex());
  const Slot& slot = Slots()[k];
  if (!slot.used) throw std::logic_error("python policy: its Env or evaluate() is gone");
  return std::make_unique<PythonPolicy>(slot.sensors, slot.max_humans, slot.callable.ptr(),
                                        slot.stop);
}

template <std::size_t K>
std::unique_ptr<Policy> MakeInSlot(const Params&) {
  return MakeFromSlot(K);
}

ParamSchema NoParams() { return {}; }

template <std::size_t... K>
std::array<PluginDescriptor, kSlots> MakeDescriptors(std::index_sequence<K...>) {
  return {PluginDescriptor{kPluginAbiVersion, PluginKind::kPolicy, "python",
                           "a policy written in Python (crowdsim_bench)", &NoParams, &MakeInSlot<K>,
                           nullptr, nullptr, nullptr}...};
}

const std::array<LoadedPlugin, kSlots>& SlotPlugins() {
  static const std::array<PluginDescriptor, kSlots> descriptors =
      MakeDescriptors(std::make_index_sequence<kSlots>());
  static const std::array<LoadedPlugin, kSlots> plugins = [] {
    std::array<LoadedPlugin, kSlots> p;
    for (std::size_t k = 0; k < kSlots; ++k) {
      p[k].path = "<python>";
      p[k].descriptor = &descriptors[k];
      p[k].schema = NoParams();
    }
    return p;
  }();
  return plugins;
}

/// Two numbers from a policy: a velocity, or (`velocity` false) a non-holonomic robot's command.
Vec2 VelocityOf(const py::handle& v, const char* what, bool velocity = true) {
  const std::string form = velocity ? " must be a velocity (vx, vy) in m/s, world frame"
                                    : " must be a command (linear m/s, angular rad/s) for this "
                                      "non-holonomic robot";
  // None (a policy without `return`) reads as one NaN: "got 1 numbers" hid the missing return.
  if (v.is_none()) {
    throw std::invalid_argument(std::string(what) + form + ": 2 numbers (got None: does the " +
                                "policy `return` its " + (velocity ? "velocity" : "command") +
                                "?)");
  }
  // Any array-like of two numbers: (2,), (1, 2) as Env.step takes it, a list, a tensor.
  using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
  const Array a = Array::ensure(v);  // null, with Python's error cleared, when it cannot be
  std::string why;
  if (!a) {
    try {  // the conversion again, for its message (a tensor that requires grad: detach())
      py::module_::import("numpy").attr("asarray")(v, py::arg("dtype") = "float64");
    } catch (const py::error_already_set& e) {
      why = std::string(" (") + e.what() + ")";
    }
  }
  if (!a || a.size() != 2) {
    if (a) why = " (got " + std::to_string(a.size()) + (a.size() == 1 ? " number)" : " numbers)");
    throw std::invalid_argument(std::string(what) + form + ": 2 numbers" + why);
  }
  return Vec2(a.data()[0], a.data()[1]);
}

}  // namespace

bool PythonStop::Requested() {
  if (stop_) return true;
  if (std::this_thread::get_id() != owner_) return false;
  py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() == 0) return false;  // only the main thread runs the handlers
  Keep(py::error_already_set());
  return true;
}

void PythonStop::Keep(const py::error_already_set& error) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!error_) error_ = error;
  stop_ = true;
}

void PythonStop::RaiseIfKept() {
  std::optional<py::error_already_set> error;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    error.swap(error_);
  }
  if (error) throw *error;
}

Action PythonPolicy::Decide(const Observation& obs) {
  if (callable_ == nullptr) {
    if (!next_) throw std::logic_error("python policy: no action was given for this step");
    const Vec2 v = *next_;
    next_.reset();
    return holonomic_ ? Action(v) : Action::Command(v.x(), v.y());
  }
  py::gil_scoped_acquire gil;
  try {
    const py::object out = py::handle(callable_)(ObservationDict(obs, max_humans_));
    if (!holonomic_) {
      const Vec2 c = VelocityOf(out, "the policy's return value", false);
      return Action::Command(c.x(), c.y());
    }
    return Action{VelocityOf(out, "the policy's return value")};
  } catch (py::error_already_set& e) {
    // Ctrl-C or exit() inside the policy stops the run (and is raised again to the caller);
    // any other exception ends the episode as policy_error with Python's message.
    if (e.matches(PyExc_KeyboardInterrupt) || e.matches(PyExc_SystemExit)) {
      if (stop_ != nullptr) stop_->Keep(e);
      throw AbortRun(std::string("python policy raised ") + e.what());
    }
    throw std::runtime_error(std::string("python policy raised ") + e.what());
  }
}

PythonPolicyBinding::PythonPolicyBinding(std::vector<std::string> sensors, int max_humans,
                                         py::object callable, PythonStop* stop) {
  std::lock_guard<std::mutex> lock(SlotMutex());
  std::array<Slot, kSlots>& slots = Slots();
  for (slot_ = 0; slot_ < kSlots && slots[slot_].used; ++slot_) {
  }
  if (slot_ == kSlots) {
    throw std::runtime_error(
        "more than " + std::to_string(kSlots) +
        " Python rows are in use at once (each Env, VectorEnv and running evaluate() holds "
        "one): close those you no longer use (del env) first");
  }
  slots[slot_] = Slot{true, std::move(sensors), max_humans, std::move(callable), stop};
}

PythonPolicyBinding::~PythonPolicyBinding() {
  Slot freed;
  {
    std::lock_guard<std::mutex> lock(SlotMutex());
    std::swap(freed, Slots()[slot_]);
  }
  // `freed` (and with it the callable's reference) goes here, outside the lock.
}

const LoadedPlugin& PythonPolicyBinding::plugin() const { return SlotPlugins()[slot_]; }

}  // namespace crowdsim::python
