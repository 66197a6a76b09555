#include "torchscript_policy.h"

#include <ATen/Parallel.h>
#include <c10/core/InferenceMode.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "value_rl/action_space.h"
#include "module_file.h"
#include "module_output.h"
#include "observation_tensors.h"

namespace crowdsim::torchscript {

struct TorchScriptPolicy::Impl {
  TorchScriptConfig config;
  torch::jit::Module module;
  double actions_v_pref = -1.0;  ///< v_pref of `actions`
  std::vector<Action> actions;   ///< CrowdNav's holonomic actions at actions_v_pref

  c10::IValue Forward(ObservationDict obs) {
    c10::InferenceMode guard;
    try {
      return module.forward({c10::IValue(std::move(obs))});
    } catch (const c10::Error& e) {
      throw std::runtime_error("torchscript: forward of '" + config.weights +
                               "' failed: " + e.what_without_backtrace());
    }
  }

  void CheckLidar(const Observation& obs) const {
    for (const SensorReading& reading : obs.readings) {
      if (reading.ranges.empty()) continue;
      if (config.UsesLidar() && static_cast<int>(reading.ranges.size()) != config.lidar_beams) {
        throw std::runtime_error("torchscript: the " + reading.sensor + " sensor has " +
                                 std::to_string(reading.ranges.size()) +
                                 " beams but parameter lidar_beams is " +
                                 std::to_string(config.lidar_beams) + "; set lidar_beams: " +
                                 std::to_string(reading.ranges.size()));
      }
      return;
    }
  }

  const std::vector<Action>& ActionsAt(double v_pref) {
    if (v_pref != actions_v_pref) {
      actions = value_rl::BuildActionSpace(kSpeeds, kDirections, /*stop_action=*/true, v_pref);
      actions_v_pref = v_pref;
    }
    return actions;
  }
};

TorchScriptPolicy::TorchScriptPolicy(const Params& params)
    : TorchScriptPolicy(ConfigFromParams(params)) {}

TorchScriptPolicy::TorchScriptPolicy(const TorchScriptConfig& config)
    : impl_(std::make_unique<Impl>()) {
  impl_->config = config;
  at::set_num_threads(config.torch_threads);
  impl_->module = LoadPolicyModule(config.weights);
  // The output is checked once on a stand-in observation: a module that returns the wrong
  // thing is refused before the first episode, naming the file and what `output` expects.
  const int beams = config.UsesLidar() ? config.lidar_beams : 0;
  CheckOutput(impl_->Forward(ProbeObservationDict(config.humans, beams)), config.output,
              config.weights);
}

TorchScriptPolicy::~TorchScriptPolicy() = default;

PolicyNeeds TorchScriptPolicy::Needs() const {
  PolicyNeeds needs;
  needs.sensors = SensorPlugins(impl_->config);
  return needs;
}

Action TorchScriptPolicy::Decide(const Observation& obs) {
  impl_->CheckLidar(obs);
  const c10::IValue out = impl_->Forward(MakeObservationDict(obs, impl_->config.humans));
  return ActionFromOutput(out, impl_->config.output, impl_->ActionsAt(obs.self.v_pref),
                          impl_->config.weights);
}

}  // namespace crowdsim::torchscript
