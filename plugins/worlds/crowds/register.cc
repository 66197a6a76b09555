#include "crowds_world.h"
#include "crowdsim/plugin_abi.h"

namespace crowdsim::crowds {

extern "C++" const PluginDescriptor kDescriptor = WorldPlugin<CrowdsWorld>(
    "crowds", "a recorded crowd (ETH/UCY tracks) in its scene's area, the robot crossing its flow",
    &Schema);

}  // namespace crowdsim::crowds

CROWDSIM_EXPORT_PLUGIN(crowdsim::crowds::kDescriptor)
