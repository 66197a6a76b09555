#include "crowdsim/plugin_abi.h"
#include "replay_policy.h"

namespace crowdsim::replay {

extern "C++" const PluginDescriptor kDescriptor = PolicyPlugin<ReplayPolicy>(
    "replay", "recorded people along their tracks, interpolated, blind to the robot (crowds world)",
    &Schema);

}  // namespace crowdsim::replay

CROWDSIM_EXPORT_PLUGIN(crowdsim::replay::kDescriptor)
