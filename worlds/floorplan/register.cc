#include "crowdsim/plugin_abi.h"
#include "floorplan_world.h"

namespace crowdsim::floorplan {
namespace {

std::unique_ptr<WorldSource> Make(const Params& params) {
  return std::make_unique<FloorplanWorld>(params);
}

}  // namespace

extern "C++" const PluginDescriptor kDescriptor{
    kPluginAbiVersion, PluginKind::kWorld, "floorplan",
    "real floor plans (Gibson / HM3D) imported as rectangles, with precomputed robot pairs",
    &Schema, nullptr, nullptr, &Make};

}  // namespace crowdsim::floorplan

CROWDSIM_EXPORT_PLUGIN(crowdsim::floorplan::kDescriptor)
