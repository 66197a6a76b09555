#include "crowdsim/plugin_abi.h"
#include "route_sensor.h"

namespace crowdsim::route {

extern "C++" const PluginDescriptor kDescriptor = SensorPlugin<RouteSensor>(
    "route", "global route: path distance to the goal around obstacles and a waypoint along it",
    &Schema);

}  // namespace crowdsim::route

CROWDSIM_EXPORT_PLUGIN(crowdsim::route::kDescriptor)
