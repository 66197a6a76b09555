// Settings of the `torchscript` policy, read from its plugin parameters. No libtorch here.
#pragma once

#include <string>
#include <vector>

#include "crowdsim/params.h"

namespace crowdsim::torchscript {

/// What the module returns.
enum class Output {
  kVelocity,  ///< 2 numbers: vx, vy in m/s, world frame
  kCommand,   ///< 2 numbers: linear m/s, angular rad/s (a unicycle or diff_drive robot)
  kAction,    ///< an index into, or one score per action of, the action set
  /// V(s') of each action's lookahead state, batched (a value network such as CADRL's or
  /// SARL's): the plugin acts on the best r + gamma^(dt v_pref) V(s')
  kValues,
};

/// CrowdNav's holonomic action set (crowdsim_bench.holonomic_actions()), the default: stop,
/// then 16 directions x 5 exponentially spaced speeds up to v_pref, direction the outer loop.
inline constexpr int kCrowdNavSpeeds = 5;
inline constexpr int kCrowdNavDirections = 16;

/// Everything the policy is built from.
struct TorchScriptConfig {
  std::string weights;             ///< resolved path of the TorchScript file
  std::string sensors = "person";  ///< person | lidar | lidar+person
  int humans = 5;                  ///< rows of `humans` / `humans_mask` (more when more are seen)
  int lidar_beams = 45;            ///< size of `lidar` (must equal the lidar2d sensor's beams)
  Output output = Output::kVelocity;
  /// The action set of `action` and `values` (value_rl's BuildActionSpace, as cadrl and sarl).
  int speed_samples = kCrowdNavSpeeds;
  int rotation_samples = kCrowdNavDirections;
  bool stop_action = true;
  /// CrowdNav's unicycle commands (value_rl's BuildUnicycleActionSpace) instead of velocities.
  bool unicycle_actions = false;
  int torch_threads = 1;  ///< libtorch intra-op threads
  bool route = false;     ///< the route sensor's reading as `route` (3,)

  bool UsesPerson() const { return sensors != "lidar"; }
  bool UsesLidar() const { return sensors != "person"; }
  bool UsesLookahead() const { return output == Output::kValues; }
  /// It returns (linear, angular) commands: for unicycle and diff_drive robots only.
  bool Commands() const {
    return output == Output::kCommand || (output != Output::kVelocity && unicycle_actions);
  }
  int ActionCount() const { return speed_samples * rotation_samples + (stop_action ? 1 : 0); }
};

/// The plugin parameters.
ParamSchema Schema();

/// Reads validated parameters; throws std::invalid_argument naming the parameter, its value
/// and the fix when they cannot make a policy (e.g. no `weights`).
TorchScriptConfig ConfigFromParams(const Params& params);

/// Plugin names of the sensors the configuration reads (checked against the row's sensors).
std::vector<std::string> SensorPlugins(const TorchScriptConfig& config);

/// "velocity" | "command" | "action" | "values".
const char* OutputName(Output output);

}  // namespace crowdsim::torchscript
