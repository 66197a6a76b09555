// Settings of the value-based policies (CADRL, SARL and their lidar "++" variants), read from
// the plugin parameters. Shared by the `cadrl` and `sarl` plugins.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "crowdsim/params.h"

namespace crowdsim::value_rl {

/// The value network family.
enum class Model { kCadrl, kSarl };

/// Which readings enter the network (the paper's three sensor configurations).
enum class SensorSet { kPerson, kLidar, kLidarPerson };

/// Name of the model as written in weights files ("cadrl", "sarl").
const char* ModelName(Model m);
/// Name of the sensor set as written in parameters and weights files ("lidar+person").
const char* SensorSetName(SensorSet s);

inline bool UsesPerson(SensorSet s) { return s != SensorSet::kLidar; }
inline bool UsesLidar(SensorSet s) { return s != SensorSet::kPerson; }

/// How the route prior enters the value (`route_prior_shape`).
enum class RoutePriorShape {
  kLinear,      ///< value less w per metre of path distance
  kDiscounted,  ///< value plus w x gamma^(path distance): the discounted reward of the free route
};

/// Name as written in parameters and weights files ("linear", "discounted").
const char* RoutePriorShapeName(RoutePriorShape s);

/// Everything a value policy is built from.
struct ValueRlConfig {
  Model model = Model::kCadrl;
  SensorSet sensors = SensorSet::kPerson;
  int lidar_beams = 45;      ///< beams of the lidar reading (network input size)
  int lidar_hidden = 64;     ///< width of the lidar encoder's hidden layer
  int lidar_features = 32;   ///< size of the lidar feature joined to the self state
  bool route = false;        ///< the route sensor's distance and waypoint join the self state
  double route_prior = 0.0;  ///< weight of the route prior (+route only); 0 = none
  RoutePriorShape route_prior_shape = RoutePriorShape::kLinear;
  int speed_samples = 2;     ///< speeds per direction, exponentially spaced up to v_pref
  int rotation_samples = 8;  ///< directions in [0, 2 pi), or rotations (unicycle_actions)
  /// CrowdNav's unicycle actions: (speed, rotation) commands, rotations linspace(-pi/4, pi/4).
  bool unicycle_actions = false;
  bool stop_action = false;     ///< prepend CrowdNav's stop action
  std::string weights;          ///< resolved path of a weights file; empty = untrained
  std::uint64_t init_seed = 0;  ///< seed of the untrained weights
  int torch_threads = 1;        ///< intra-op threads of libtorch

  /// Number of actions of the action space.
  int ActionCount() const { return speed_samples * rotation_samples + (stop_action ? 1 : 0); }
  /// Lidar beams entering the network (0 without lidar).
  int LidarInputs() const { return UsesLidar(sensors) ? lidar_beams : 0; }
};

/// The `sensors` parameter as written ("lidar+person", "lidar+person+route").
std::string SensorsLabel(const ValueRlConfig& c);

/// Plugin names of the sensors the network reads (checked against the row's sensors).
std::vector<std::string> SensorPlugins(const ValueRlConfig& c);

/// The plugin parameters of `model` (both plugins share them).
ParamSchema Schema(Model model);

/// Reads validated parameters; throws std::invalid_argument on inconsistent values.
ValueRlConfig ConfigFromParams(Model model, const Params& params);

}  // namespace crowdsim::value_rl
