#include "crowdsim/plugin_abi.h"
#include "linear_policy.h"

namespace crowdsim::linear {

extern "C++" const PluginDescriptor kDescriptor = PolicyPlugin<LinearPolicy>(
    "linear", "straight to the goal at v_pref, ignoring everybody (trivial baseline)", &Schema);

}  // namespace crowdsim::linear

CROWDSIM_EXPORT_PLUGIN(crowdsim::linear::kDescriptor)
