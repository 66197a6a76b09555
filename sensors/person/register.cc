#include "crowdsim/plugin_abi.h"
#include "person_sensor.h"

namespace crowdsim::person {
namespace {

std::unique_ptr<Sensor> Make(const Params& params) {
  return std::make_unique<PersonSensor>(params);
}

}  // namespace

extern "C++" const PluginDescriptor kDescriptor{
    kPluginAbiVersion, PluginKind::kSensor, "person",
    "people detector: every human's position, velocity and radius in the robot frame",
    &Schema, nullptr, &Make, nullptr};

}  // namespace crowdsim::person

CROWDSIM_EXPORT_PLUGIN(crowdsim::person::kDescriptor)
