#include "crowdnav_world.h"
#include "crowdsim/plugin_abi.h"

namespace crowdsim::crowdnav {
namespace {

std::unique_ptr<WorldSource> Make(const Params& params) {
  return std::make_unique<CrowdNavWorld>(params);
}

}  // namespace

extern "C++" const PluginDescriptor kDescriptor{
    kPluginAbiVersion,
    PluginKind::kWorld,
    "crowdnav",
    "CrowdNav's obstacle-free circle_crossing / square_crossing scenarios, exact",
    &Schema,
    nullptr,
    nullptr,
    &Make};

}  // namespace crowdsim::crowdnav

CROWDSIM_EXPORT_PLUGIN(crowdsim::crowdnav::kDescriptor)
