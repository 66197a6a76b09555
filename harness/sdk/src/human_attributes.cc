// Per-person attributes of a request, with the sim's values as the fallback.
#include <algorithm>

#include "crowdsim/world_source.h"

namespace crowdsim {

HumanAttributes HumanAttributesOf(const ScenarioRequest& request, int i) {
  if (i >= 0 && static_cast<size_t>(i) < request.humans.size())
    return request.humans[static_cast<size_t>(i)];
  return HumanAttributes{request.sim.human_radius, request.sim.human_v_pref, false};
}

double LargestHumanRadius(const ScenarioRequest& request) {
  double largest = request.sim.human_radius;
  if (request.humans.empty()) return largest;
  largest = 0.0;
  for (const HumanAttributes& a : request.humans) largest = std::max(largest, a.radius);
  return largest;
}

void ApplyHumanAttributes(const ScenarioRequest& request, int i, HumanSpec* spec) {
  const HumanAttributes a = HumanAttributesOf(request, i);
  spec->radius = a.radius;
  spec->v_pref = a.v_pref;
  spec->ignores_robot = a.ignores_robot;
}

}  // namespace crowdsim
