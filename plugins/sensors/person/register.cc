#include "crowdsim/plugin_abi.h"
#include "person_sensor.h"

namespace crowdsim::person {

extern "C++" const PluginDescriptor kDescriptor = SensorPlugin<PersonSensor>(
    "person", "people detector: every human's position, velocity and radius in the robot frame",
    &Schema);

}  // namespace crowdsim::person

CROWDSIM_EXPORT_PLUGIN(crowdsim::person::kDescriptor)
