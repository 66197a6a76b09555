#include "crowdsim/plugin_abi.h"
#include "hsfm_policy.h"

namespace crowdsim::hsfm {

extern "C++" const PluginDescriptor kDescriptor = PolicyPlugin<HsfmPolicy>(
    "hsfm",
    "Farina et al.'s headed social force model (2017): Helbing 2000 forces on a body with a "
    "heading, torque towards the force, roadmap guidance",
    &Schema);

}  // namespace crowdsim::hsfm

CROWDSIM_EXPORT_PLUGIN(crowdsim::hsfm::kDescriptor)
