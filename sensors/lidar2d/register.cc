#include "crowdsim/plugin_abi.h"
#include "lidar2d_sensor.h"

namespace crowdsim::lidar2d {
namespace {

std::unique_ptr<Sensor> Make(const Params& params) {
  return std::make_unique<Lidar2dSensor>(params);
}

}  // namespace

extern "C++" const PluginDescriptor kDescriptor{
    kPluginAbiVersion, PluginKind::kSensor, "lidar2d",
    "planar lidar: ranges to obstacles (and humans) along a fan of beams",
    &Schema, nullptr, &Make, nullptr};

}  // namespace crowdsim::lidar2d

CROWDSIM_EXPORT_PLUGIN(crowdsim::lidar2d::kDescriptor)
