// Key functions of the plugin interfaces: their vtables and type info live once, in the SDK.
#include "crowdsim/lookahead.h"
#include "crowdsim/plugin_abi.h"
#include "crowdsim/policy.h"
#include "crowdsim/sensor.h"
#include "crowdsim/world_source.h"

namespace crowdsim {

Policy::~Policy() = default;
void Policy::Reset(const EpisodeContext&) {}
AbortRun::~AbortRun() = default;
Sensor::~Sensor() = default;
WorldSource::~WorldSource() = default;
Lookahead::~Lookahead() = default;

const char* PluginKindName(PluginKind k) {
  switch (k) {
    case PluginKind::kPolicy:
      return "policy";
    case PluginKind::kSensor:
      return "sensor";
    case PluginKind::kWorld:
      return "world";
  }
  return "unknown";
}

}  // namespace crowdsim
