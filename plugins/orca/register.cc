#include "crowdsim/plugin_abi.h"
#include "orca_policy.h"

namespace crowdsim::orca {
namespace {

std::unique_ptr<Policy> Make(const Params& params) { return std::make_unique<OrcaPolicy>(params); }

}  // namespace

extern "C++" const PluginDescriptor kDescriptor{
    kPluginAbiVersion,
    PluginKind::kPolicy,
    "orca",
    "ORCA (RVO2's algorithm, CrowdNav's wrapper) with the map's rectangles as obstacles and "
    "roadmap guidance; the humans' default",
    &Schema,
    &Make,
    nullptr,
    nullptr};

}  // namespace crowdsim::orca

CROWDSIM_EXPORT_PLUGIN(crowdsim::orca::kDescriptor)
