#include "crowdsim/agent_state.h"

#include <cmath>

namespace crowdsim {

Frame Frame::Make(const Vec2& origin, double heading) {
  Frame f;
  f.origin = origin;
  f.heading = heading;
  f.cos_h = std::cos(heading);
  f.sin_h = std::sin(heading);
  return f;
}

double HeadingToGoal(const AgentState& s) {
  const Vec2 d = s.goal - s.position;
  if (d.squaredNorm() == 0.0) return s.heading;
  return std::atan2(d.y(), d.x());
}

void GroupMates(std::span<const AgentState> agents, int self, std::vector<Vec2>* out) {
  out->clear();
  if (self < 0 || static_cast<size_t>(self) >= agents.size()) return;
  const AgentState& me = agents[static_cast<size_t>(self)];
  if (me.group < 0 || (me.goal - me.position).squaredNorm() < kGroupReleaseDist * kGroupReleaseDist)
    return;
  for (size_t k = static_cast<size_t>(self); k-- > 0 && agents[k].group == me.group;)
    out->push_back(agents[k].position);
  for (size_t k = static_cast<size_t>(self) + 1; k < agents.size() && agents[k].group == me.group;
       ++k) {
    out->push_back(agents[k].position);
  }
}

}  // namespace crowdsim
