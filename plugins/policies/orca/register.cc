#include "crowdsim/plugin_abi.h"
#include "orca_policy.h"

namespace crowdsim::orca {

extern "C++" const PluginDescriptor kDescriptor = PolicyPlugin<OrcaPolicy>(
    "orca",
    "ORCA (RVO2's algorithm, CrowdNav's wrapper) with the map's rectangles as obstacles "
    "and roadmap guidance; the humans' default",
    &Schema);

}  // namespace crowdsim::orca

CROWDSIM_EXPORT_PLUGIN(crowdsim::orca::kDescriptor)
