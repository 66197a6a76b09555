#include "crowdsim/plugin_abi.h"
#include "social_force_policy.h"

namespace crowdsim::social_force {

extern "C++" const PluginDescriptor kDescriptor = PolicyPlugin<SocialForcePolicy>(
    "social_force",
    "Helbing & Molnár's social force model (1995): driving force, anisotropic repulsion from "
    "people and rectangles, roadmap guidance",
    &Schema);

}  // namespace crowdsim::social_force

CROWDSIM_EXPORT_PLUGIN(crowdsim::social_force::kDescriptor)
