#include "crowdnav_world.h"
#include "crowdsim/plugin_abi.h"

namespace crowdsim::crowdnav {

extern "C++" const PluginDescriptor kDescriptor = WorldPlugin<CrowdNavWorld>(
    "crowdnav", "CrowdNav's obstacle-free circle_crossing / square_crossing scenarios, exact",
    &Schema);

}  // namespace crowdsim::crowdnav

CROWDSIM_EXPORT_PLUGIN(crowdsim::crowdnav::kDescriptor)
