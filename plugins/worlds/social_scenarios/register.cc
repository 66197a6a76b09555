#include "crowdsim/plugin_abi.h"
#include "social_scenarios_world.h"

namespace crowdsim::social_scenarios {

extern "C++" const PluginDescriptor kDescriptor = WorldPlugin<SocialScenariosWorld>(
    "social_scenarios",
    "named interaction scenarios of the social navigation guidelines (frontal approach, "
    "overtaking, crossing, doorway, narrow hallway, blind corner, intersection, standing person)",
    &Schema);

}  // namespace crowdsim::social_scenarios

CROWDSIM_EXPORT_PLUGIN(crowdsim::social_scenarios::kDescriptor)
