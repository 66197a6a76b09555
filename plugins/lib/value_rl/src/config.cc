#include "value_rl/config.h"

#include <filesystem>
#include <stdexcept>

namespace crowdsim::value_rl {
namespace {

/// Appended to a sensor set: the route sensor's reading joins the self state.
constexpr const char* kRouteSuffix = "+route";

}  // namespace

const char* ModelName(Model m) { return m == Model::kCadrl ? "cadrl" : "sarl"; }

const char* SensorSetName(SensorSet s) {
  switch (s) {
    case SensorSet::kPerson:
      return "person";
    case SensorSet::kLidar:
      return "lidar";
    case SensorSet::kLidarPerson:
      return "lidar+person";
  }
  return "unknown";
}

const char* RoutePriorShapeName(RoutePriorShape s) {
  return s == RoutePriorShape::kLinear ? "linear" : "discounted";
}

std::string SensorsLabel(const ValueRlConfig& c) {
  return std::string(SensorSetName(c.sensors)) + (c.route ? kRouteSuffix : "");
}

std::vector<std::string> SensorPlugins(const ValueRlConfig& c) {
  std::vector<std::string> names;
  if (UsesLidar(c.sensors)) names.push_back("lidar2d");
  if (UsesPerson(c.sensors)) names.push_back("person");
  if (c.route) names.push_back("route");
  return names;
}

ParamSchema Schema(Model /*model: both families take the same parameters*/) {
  return {
      {"sensors",
       ParamType::kString,
       std::string("person"),
       0,
       0,
       {"person", "lidar", "lidar+person", "person+route", "lidar+route", "lidar+person+route"},
       "readings that enter the network (the row must configure the matching sensors; "
       "+route: the route sensor's path distance and waypoint too, beyond the paper)"},
      {"weights",
       ParamType::kString,
       std::string(""),
       0,
       0,
       {},
       "trained weights (.pt from `crowdsim-bench train`); empty = untrained network"},
      {"route_prior",
       ParamType::kDouble,
       0.0,
       0.0,
       1.0,
       {},
       "with +route: weight of a fixed prior added to the network's value (route_prior_shape); "
       "0 = none",
       /*hashed_at_default=*/false},
      {"route_prior_shape",
       ParamType::kString,
       std::string("linear"),
       0,
       0,
       {"linear", "discounted"},
       "linear: value less route_prior per metre of the route's path distance (potential-based "
       "shaping); discounted: value plus route_prior x gamma^(path distance), the discounted "
       "success reward of following the free route at v_pref, so the network learns only what "
       "people and turns change",
       /*hashed_at_default=*/false},
      {"lidar_beams",
       ParamType::kInt,
       std::int64_t{45},
       1,
       3600,
       {},
       "beams of the lidar2d reading (must match the sensor's `beams`)"},
      {"speed_samples",
       ParamType::kInt,
       std::int64_t{2},
       1,
       64,
       {},
       "speeds per direction, (e^((i+1)/S) - 1)/(e - 1) * v_pref"},
      {"rotation_samples",
       ParamType::kInt,
       std::int64_t{8},
       1,
       360,
       {},
       "holonomic: directions k * 360/R degrees in the world frame; unicycle: rotations "
       "linspace(-45, 45, R) degrees per step"},
      {"action_space",
       ParamType::kString,
       std::string("holonomic"),
       0,
       0,
       {"holonomic", "unicycle"},
       "holonomic: velocities in R world directions (a unicycle robot tracks them); unicycle: "
       "CrowdNav's (speed, rotation) commands, R rotations in [-45, 45] degrees per step, for "
       "rows with kinematics unicycle or diff_drive",
       /*hashed_at_default=*/false},
      {"stop_action",
       ParamType::kBool,
       false,
       0,
       1,
       {},
       "prepend CrowdNav's stop action (16 + 1 actions by default)"},
      {"init_seed",
       ParamType::kInt,
       std::int64_t{0},
       0,
       1e15,
       {},
       "seed of the untrained weights (no `weights`)"},
      {"torch_threads",
       ParamType::kInt,
       std::int64_t{1},
       1,
       256,
       {},
       "libtorch intra-op threads (1: deterministic, best for many small batches)"},
  };
}

ValueRlConfig ConfigFromParams(Model model, const Params& params) {
  ValueRlConfig c;
  c.model = model;
  const std::string& given = params.GetString("sensors");
  std::string s = given;
  if (s.ends_with(kRouteSuffix)) {
    c.route = true;
    s.resize(s.size() - std::string_view(kRouteSuffix).size());
  }
  if (s == "person") {
    c.sensors = SensorSet::kPerson;
  } else if (s == "lidar") {
    c.sensors = SensorSet::kLidar;
  } else if (s == "lidar+person") {
    c.sensors = SensorSet::kLidarPerson;
  } else {
    throw std::invalid_argument(
        std::string(ModelName(model)) + ": sensors '" + given +
        "' is not valid; valid: person, lidar, lidar+person, each optionally +route");
  }
  c.route_prior = params.GetDouble("route_prior");
  if (c.route_prior > 0.0 && !c.route) {
    throw std::invalid_argument(
        std::string(ModelName(model)) + ": route_prior " + std::to_string(c.route_prior) +
        " needs the route sensor in the state; use sensors '" + given + "+route' or route_prior 0");
  }
  c.route_prior_shape =
      params.GetString("route_prior_shape") == RoutePriorShapeName(RoutePriorShape::kDiscounted)
          ? RoutePriorShape::kDiscounted
          : RoutePriorShape::kLinear;
  if (c.route_prior_shape != RoutePriorShape::kLinear && c.route_prior == 0.0) {
    throw std::invalid_argument(std::string(ModelName(model)) +
                                ": route_prior_shape discounted has no effect with route_prior 0; "
                                "give route_prior a weight (e.g. 1, the success reward)");
  }
  c.lidar_beams = static_cast<int>(params.GetInt("lidar_beams"));
  c.speed_samples = static_cast<int>(params.GetInt("speed_samples"));
  c.rotation_samples = static_cast<int>(params.GetInt("rotation_samples"));
  c.stop_action = params.GetBool("stop_action");
  c.unicycle_actions = params.GetString("action_space") == "unicycle";
  c.init_seed = static_cast<std::uint64_t>(params.GetInt("init_seed"));
  c.torch_threads = static_cast<int>(params.GetInt("torch_threads"));
  const std::string& w = params.GetString("weights");
  if (!w.empty()) {
    c.weights = params.ResolvePath(w).string();
    // Named with every place ResolvePath looked in (the missing path alone named only the
    // suite's folder).
    if (!std::filesystem::exists(c.weights)) {
      throw std::runtime_error("weights file " + params.MissingFile(w) +
                               "; train one with `crowdsim-bench train`");
    }
  }
  return c;
}

}  // namespace crowdsim::value_rl
