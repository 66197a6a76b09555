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

}  // namespace crowdsim
