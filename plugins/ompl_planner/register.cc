#include "crowdsim/plugin_abi.h"
#include "ompl_planner_policy.h"

namespace crowdsim::ompl_planner {
namespace {

std::unique_ptr<Policy> Make(const Params& params) {
  return std::make_unique<OmplPlannerPolicy>(params);
}

}  // namespace

extern "C++" const PluginDescriptor kDescriptor{
    kPluginAbiVersion,
    PluginKind::kPolicy,
    "ompl_planner",
    "global path planned with OMPL on the known map (deterministic sample budget), followed "
    "with ORCA or an action set avoiding people",
    &Schema,
    &Make,
    nullptr,
    nullptr};

}  // namespace crowdsim::ompl_planner

CROWDSIM_EXPORT_PLUGIN(crowdsim::ompl_planner::kDescriptor)
