#include "crowdsim/plugin_abi.h"
#include "lidar2d_sensor.h"

namespace crowdsim::lidar2d {

extern "C++" const PluginDescriptor kDescriptor = SensorPlugin<Lidar2dSensor>(
    "lidar2d", "planar lidar: ranges to obstacles (and humans) along a fan of beams", &Schema);

}  // namespace crowdsim::lidar2d

CROWDSIM_EXPORT_PLUGIN(crowdsim::lidar2d::kDescriptor)
