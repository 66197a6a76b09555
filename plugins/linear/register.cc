#include "crowdsim/plugin_abi.h"
#include "linear_policy.h"

namespace crowdsim::linear {
namespace {

std::unique_ptr<Policy> Make(const Params& params) { return std::make_unique<LinearPolicy>(params); }

}  // namespace

extern "C++" const PluginDescriptor kDescriptor{
    kPluginAbiVersion, PluginKind::kPolicy, "linear",
    "straight to the goal at v_pref, ignoring everybody (trivial baseline)",
    &Schema, &Make, nullptr, nullptr};

}  // namespace crowdsim::linear

CROWDSIM_EXPORT_PLUGIN(crowdsim::linear::kDescriptor)
