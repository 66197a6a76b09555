// The `sarl` plugin: SARL and SARL++ (value_rl with the attention network).
#include "crowdsim/plugin_abi.h"
#include "value_rl/value_policy.h"

namespace crowdsim::sarl {
namespace {

ParamSchema Schema() { return value_rl::Schema(value_rl::Model::kSarl); }
std::unique_ptr<Policy> Make(const Params& p) { return MakeValuePolicy(value_rl::Model::kSarl, p); }

}  // namespace

extern "C++" const PluginDescriptor kDescriptor{
    kPluginAbiVersion,
    PluginKind::kPolicy,
    "sarl",
    "SARL / SARL++: self-attention value network over humans, optional lidar; one-step lookahead",
    &Schema,
    &Make,
    nullptr,
    nullptr,
    nullptr};

}  // namespace crowdsim::sarl

CROWDSIM_EXPORT_PLUGIN(crowdsim::sarl::kDescriptor)
