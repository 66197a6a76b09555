#include "torchscript_config.h"

#include <filesystem>
#include <stdexcept>

namespace crowdsim::torchscript {

const char* OutputName(Output output) {
  switch (output) {
    case Output::kVelocity:
      return "velocity";
    case Output::kCommand:
      return "command";
    case Output::kAction:
      return "action";
    case Output::kValues:
      return "values";
  }
  return "?";
}

ParamSchema Schema() {
  return {
      {"weights",
       ParamType::kString,
       std::string(""),
       0,
       0,
       {},
       "TorchScript file (torch.jit.script(model).save(path)); the row's `weights:` key sets it"},
      {"sensors",
       ParamType::kString,
       std::string("person"),
       0,
       0,
       {"person", "lidar", "lidar+person"},
       "readings the module gets (the row must configure the matching sensors)"},
      {"humans",
       ParamType::kInt,
       std::int64_t{5},
       0,
       1000,
       {},
       "rows of `humans` and `humans_mask` (the row's human count; more when more are seen)"},
      {"lidar_beams",
       ParamType::kInt,
       std::int64_t{45},
       1,
       3600,
       {},
       "size of `lidar` (must match the lidar2d sensor's `beams`)"},
      {"output",
       ParamType::kString,
       std::string("velocity"),
       0,
       0,
       {"velocity", "command", "action", "values"},
       "velocity: (vx, vy) m/s world frame; command: (linear m/s, angular rad/s) for a unicycle "
       "or diff_drive robot; action: an index or one score per action; values: "
       "V(s') of every action's lookahead observation (stacked), the best r + gamma^(dt v_pref) "
       "V(s') acts (as cadrl and sarl)"},
      {"speed_samples",
       ParamType::kInt,
       std::int64_t{kCrowdNavSpeeds},
       1,
       64,
       {},
       "action set of `action` / `values`: speeds per direction, (e^((i+1)/S) - 1)/(e - 1) * "
       "v_pref (CrowdNav's 5 by default; cadrl and sarl use 2)"},
      {"rotation_samples",
       ParamType::kInt,
       std::int64_t{kCrowdNavDirections},
       1,
       360,
       {},
       "action set: directions k * 360/R degrees in the world frame (CrowdNav's 16; cadrl and "
       "sarl use 8)"},
      {"stop_action",
       ParamType::kBool,
       true,
       0,
       1,
       {},
       "action set: the stop action first (CrowdNav's; cadrl and sarl have none)"},
      {"action_space",
       ParamType::kString,
       std::string("holonomic"),
       0,
       0,
       {"holonomic", "unicycle"},
       "action set of `action` / `values`: holonomic velocities, or CrowdNav's unicycle "
       "commands (R rotations linspace(-45, 45) degrees per step x speeds) for a unicycle or "
       "diff_drive robot",
       /*hashed_at_default=*/false},
      {"route",
       ParamType::kBool,
       false,
       0,
       1,
       {},
       "true: the route sensor's reading as `route` (3,): path distance (m), waypoint x, y "
       "(robot frame), as crowdsim_bench's observations (the row must configure `route`)",
       /*hashed_at_default=*/false},
      {"torch_threads",
       ParamType::kInt,
       std::int64_t{1},
       1,
       256,
       {},
       "libtorch intra-op threads (1: deterministic, best for one observation at a time)"},
  };
}

TorchScriptConfig ConfigFromParams(const Params& params) {
  TorchScriptConfig c;
  const std::string& w = params.GetString("weights");
  if (w.empty()) {
    throw std::invalid_argument(
        "torchscript: parameter 'weights' is empty; give the TorchScript file of the policy "
        "(row key `weights: model.pt`, written by torch.jit.script(model).save('model.pt'))");
  }
  c.weights = params.ResolvePath(w).string();
  if (!std::filesystem::exists(c.weights)) {  // named with every place ResolvePath looked in
    throw std::runtime_error("torchscript: weights file " + params.MissingFile(w) +
                             "; export the policy with torch.jit.script(model).save(path) and "
                             "name that file in `weights`");
  }
  c.sensors = params.GetString("sensors");
  c.humans = static_cast<int>(params.GetInt("humans"));
  c.lidar_beams = static_cast<int>(params.GetInt("lidar_beams"));
  const std::string& output = params.GetString("output");
  c.output = output == "action"    ? Output::kAction
             : output == "values"  ? Output::kValues
             : output == "command" ? Output::kCommand
                                   : Output::kVelocity;
  c.speed_samples = static_cast<int>(params.GetInt("speed_samples"));
  c.rotation_samples = static_cast<int>(params.GetInt("rotation_samples"));
  c.stop_action = params.GetBool("stop_action");
  c.unicycle_actions = params.GetString("action_space") == "unicycle";
  c.torch_threads = static_cast<int>(params.GetInt("torch_threads"));
  c.route = params.GetBool("route");
  return c;
}

std::vector<std::string> SensorPlugins(const TorchScriptConfig& config) {
  std::vector<std::string> names;
  if (config.UsesLidar()) names.push_back("lidar2d");
  if (config.UsesPerson()) names.push_back("person");
  if (config.route) names.push_back("route");
  return names;
}

}  // namespace crowdsim::torchscript
