#include "replay_policy.h"

#include <stdexcept>
#include <string>

#include "crowd_tracks/track_position.h"

namespace crowdsim::replay {

ParamSchema Schema() { return {}; }

PolicyNeeds ReplayPolicy::Needs() const {
  PolicyNeeds needs;
  needs.heading_frame = false;  // it reads no frame
  return needs;
}

void ReplayPolicy::Reset(const EpisodeContext& ctx) {
  if (ctx.role != AgentRole::kHuman) {
    throw std::invalid_argument("replay moves recorded people: it is a humans' policy only");
  }
  track_ = ctx.track;
  time_step_ = ctx.sim.time_step;
  agent_id_ = ctx.agent_id;
}

Action ReplayPolicy::Decide(const Observation& obs) {
  if (track_.empty()) {
    throw std::invalid_argument(
        "replay: human " + std::to_string(agent_id_ - 1) +
        " has no recorded track: the replay policy moves the people of a recorded crowd "
        "(world: {source: crowds}, docs/crowds.md)");
  }
  // Aimed at the track's next position from where the person is, so no rounding accumulates.
  const Vec2 next = crowd_tracks::TrackPosition(track_, obs.time + time_step_);
  return Action{(next - obs.self.position) / time_step_};
}

}  // namespace crowdsim::replay
