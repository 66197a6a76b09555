#include "crowdsim/plugin_abi.h"
#include "random_rect_world.h"

namespace crowdsim::random_rect {

extern "C++" const PluginDescriptor kDescriptor = WorldPlugin<RandomRectWorld>(
    "random_rect",
    "10 x 10 m rooms with random rectangular obstacles (frozen sets, CrowdSim++ 4.1)", &Schema);

}  // namespace crowdsim::random_rect

CROWDSIM_EXPORT_PLUGIN(crowdsim::random_rect::kDescriptor)
