#include "torchscript_policy.h"

#include <ATen/Parallel.h>
#include <c10/core/InferenceMode.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "module_file.h"
#include "module_output.h"
#include "observation_tensors.h"
#include "value_rl/action_space.h"
#include "value_rl/value_policy.h"

namespace crowdsim::torchscript {

struct TorchScriptPolicy::Impl {
  TorchScriptConfig config;
  torch::jit::Module module;
  double actions_v_pref = -1.0;              ///< v_pref of `actions`
  std::vector<Action> actions;               ///< CrowdNav's holonomic actions at actions_v_pref
  double gamma = 0.9;                        ///< the episode's discount (`values` mode)
  double time_step = SimConfig{}.time_step;  ///< the episode's, s between decisions
  std::vector<LookaheadOutcome> outcomes;

  c10::IValue Forward(ObservationDict obs) {
    c10::InferenceMode guard;
    std::string keys;  // for a module that reads a key the row does not give
    for (const auto& entry : obs) keys += (keys.empty() ? "" : ", ") + entry.key();
    try {
      return module.forward({c10::IValue(std::move(obs))});
    } catch (const c10::Error& e) {
      throw std::runtime_error(Failed(e.what_without_backtrace(), keys));
    } catch (const std::exception& e) {  // torch::jit::JITException: an error raised in forward
      throw std::runtime_error(Failed(e.what(), keys));
    }
  }

  std::string Failed(const std::string& what, const std::string& keys) const {
    const char* input = config.UsesLookahead()
                            ? "the stacked lookahead observations (output: values: robot (A, 9), "
                              "humans (A, H, 5), ...; one row per action)"
                            : "the observation";
    std::string message =
        "torchscript: forward of '" + config.weights + "' failed on " + input + ": " + what;
    // A dictionary lookup of a missing key raises KeyError in TorchScript: the usual cause is a
    // module trained with a sensor this row's `sensors` parameter leaves out.
    if (what.find("KeyError") != std::string::npos) {
      message += "\nThe observation has the keys " + keys + " (params.sensors: " + config.sensors +
                 "); a module that reads lidar needs sensors: lidar or lidar+person, and the "
                 "row the lidar2d sensor.";
    }
    return message;
  }

  void CheckLidar(const Observation& obs) const {
    for (const SensorReading& reading : obs.readings) {
      if (reading.ranges.empty()) continue;
      if (config.UsesLidar() && static_cast<int>(reading.ranges.size()) != config.lidar_beams) {
        throw std::runtime_error("torchscript: the " + reading.sensor + " sensor has " +
                                 std::to_string(reading.ranges.size()) +
                                 " beams but parameter lidar_beams is " +
                                 std::to_string(config.lidar_beams) +
                                 "; set lidar_beams: " + std::to_string(reading.ranges.size()));
      }
      return;
    }
  }

  const std::vector<Action>& ActionsAt(double v_pref) {
    if (v_pref != actions_v_pref) {
      actions =
          config.unicycle_actions
              ? value_rl::BuildUnicycleActionSpace(config.speed_samples, config.rotation_samples,
                                                   config.stop_action, v_pref, time_step)
              : value_rl::BuildActionSpace(config.speed_samples, config.rotation_samples,
                                           config.stop_action, v_pref);
      actions_v_pref = v_pref;
    }
    return actions;
  }

  /// `values` mode: the earliest action whose r + gamma^(dt v_pref) V(s') is within
  /// ValuePolicy's tie tolerance of the best, as the built-in cadrl and sarl decide.
  Action DecideByValues(const Observation& obs) {
    if (obs.lookahead == nullptr) {
      throw std::runtime_error(
          "torchscript: output: values needs the lookahead (robot policies only)");
    }
    const std::vector<Action>& candidates = ActionsAt(obs.self.v_pref);
    obs.lookahead->Evaluate(candidates, &outcomes);
    const std::vector<double> next = ValuesFromOutput(
        Forward(MakeLookaheadDict(outcomes, obs.time + time_step, config.humans, config.route)),
        config.ActionCount(), config.weights);
    const double discount = std::pow(gamma, time_step * obs.self.v_pref);
    std::vector<float> values(next.size());
    for (size_t k = 0; k < next.size(); ++k) {
      values[k] = static_cast<float>(outcomes[k].reward + discount * next[k]);
    }
    return candidates[value_rl::EarliestBest(values)];
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
  const ObservationDict probe =
      config.UsesLookahead()
          ? ProbeLookaheadDict(config.ActionCount(), config.humans, beams, config.route)
          : ProbeObservationDict(config.humans, beams, config.route);
  CheckOutput(impl_->Forward(probe), config.output, config.ActionCount(), config.weights);
}

TorchScriptPolicy::~TorchScriptPolicy() = default;

PolicyNeeds TorchScriptPolicy::Needs() const {
  PolicyNeeds needs;
  needs.sensors = SensorPlugins(impl_->config);
  needs.lookahead = impl_->config.UsesLookahead();
  // The output names the form: commands drive a unicycle robot; velocities only when tracked.
  if (impl_->config.Commands()) needs.non_holonomic = NonHolonomicDrive::kCommands;
  return needs;
}

void TorchScriptPolicy::Reset(const EpisodeContext& ctx) {
  if (impl_->config.Commands() && ctx.role == AgentRole::kRobot && ctx.kinematics.Holonomic()) {
    throw std::runtime_error(
        std::string("torchscript: output: ") + OutputName(impl_->config.output) +
        (impl_->config.output == Output::kCommand ? "" : " with action_space: unicycle") +
        " returns (linear, angular) commands, which a holonomic robot does not take; give the "
        "row `kinematics: unicycle`, or return velocities");
  }
  if (impl_->time_step != ctx.sim.time_step) impl_->actions_v_pref = -1.0;  // turns per step
  impl_->gamma = ctx.sim.gamma;
  impl_->time_step = ctx.sim.time_step;
}

Action TorchScriptPolicy::Decide(const Observation& obs) {
  impl_->CheckLidar(obs);
  if (impl_->config.UsesLookahead()) return impl_->DecideByValues(obs);
  const c10::IValue out =
      impl_->Forward(MakeObservationDict(obs, impl_->config.humans, impl_->config.route));
  return ActionFromOutput(out, impl_->config.output, impl_->ActionsAt(obs.self.v_pref),
                          impl_->config.weights);
}

}  // namespace crowdsim::torchscript
