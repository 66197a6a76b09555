// Per-person attributes of a request, with the sim's values as the fallback.
#include <algorithm>

#include "crowdsim/world_source.h"

namespace crowdsim {

HumanAttributes HumanAttributesOf(const ScenarioRequest& request, int i) {
  if (i >= 0 && static_cast<size_t>(i) < request.humans.size())
    return request.humans[static_cast<size_t>(i)];
  return HumanAttributes{request.sim.human_radius, request.sim.human_v_pref, false, -1};
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
  spec->group = a.group;
}

int GroupLeaderOf(const ScenarioRequest& request, int i) {
  const int group = HumanAttributesOf(request, i).group;
  if (group < 0) return -1;
  int leader = i;
  while (leader > 0 && HumanAttributesOf(request, leader - 1).group == group) --leader;
  return leader == i ? -1 : leader;
}

}  // namespace crowdsim
