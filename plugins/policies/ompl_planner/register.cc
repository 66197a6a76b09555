#include "crowdsim/plugin_abi.h"
#include "ompl_planner_policy.h"

namespace crowdsim::ompl_planner {

extern "C++" const PluginDescriptor kDescriptor = PolicyPlugin<OmplPlannerPolicy>(
    "ompl_planner",
    "global path planned with OMPL on the known map (deterministic sample budget), "
    "followed with ORCA or an action set avoiding people",
    &Schema);

}  // namespace crowdsim::ompl_planner

CROWDSIM_EXPORT_PLUGIN(crowdsim::ompl_planner::kDescriptor)
