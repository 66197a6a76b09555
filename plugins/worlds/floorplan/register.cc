#include "crowdsim/plugin_abi.h"
#include "floorplan_world.h"

namespace crowdsim::floorplan {

extern "C++" const PluginDescriptor kDescriptor = WorldPlugin<FloorplanWorld>(
    "floorplan",
    "real floor plans (Gibson / HM3D) imported as rectangles, with precomputed robot pairs",
    &Schema);

}  // namespace crowdsim::floorplan

CROWDSIM_EXPORT_PLUGIN(crowdsim::floorplan::kDescriptor)
