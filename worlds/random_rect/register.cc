#include "crowdsim/plugin_abi.h"
#include "random_rect_world.h"

namespace crowdsim::random_rect {
namespace {

std::unique_ptr<WorldSource> Make(const Params& params) {
  return std::make_unique<RandomRectWorld>(params);
}

}  // namespace

extern "C++" const PluginDescriptor kDescriptor{
    kPluginAbiVersion,
    PluginKind::kWorld,
    "random_rect",
    "10 x 10 m rooms with random rectangular obstacles (frozen sets, CrowdSim++ 4.1)",
    &Schema,
    nullptr,
    nullptr,
    &Make};

}  // namespace crowdsim::random_rect

CROWDSIM_EXPORT_PLUGIN(crowdsim::random_rect::kDescriptor)
