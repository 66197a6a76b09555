// The `cadrl` plugin: CADRL and CADRL++ (value_rl with the pairwise network).
#include "crowdsim/plugin_abi.h"
#include "value_rl/value_policy.h"

namespace crowdsim::cadrl {
namespace {

ParamSchema Schema() { return value_rl::Schema(value_rl::Model::kCadrl); }
std::unique_ptr<Policy> Make(const Params& p) {
  return MakeValuePolicy(value_rl::Model::kCadrl, p);
}

}  // namespace

extern "C++" const PluginDescriptor kDescriptor{
    kPluginAbiVersion,
    PluginKind::kPolicy,
    "cadrl",
    "CADRL / CADRL++: pairwise value network, min over humans, optional lidar; one-step lookahead",
    &Schema,
    &Make,
    nullptr,
    nullptr,
    nullptr};

}  // namespace crowdsim::cadrl

CROWDSIM_EXPORT_PLUGIN(crowdsim::cadrl::kDescriptor)
