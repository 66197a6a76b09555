#include "social_force_policy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "crowdsim/agent_index.h"
#include "crowdsim/static_map.h"
#include "walking/contact.h"

namespace crowdsim::social_force {

ParamSchema Schema() {
  const Constants c;
  const GroupConstants g;
  return {
      {"tau", ParamType::kDouble, c.tau, 0.05, 10.0, {}, "s; relaxation time (HM95: 0.5)"},
      {"v0",
       ParamType::kDouble,
       c.v0_ped,
       0.0,
       100.0,
       {},
       "m^2/s^2; strength of another pedestrian's repulsive potential (HM95: 2.1)"},
      {"sigma",
       ParamType::kDouble,
       c.sigma,
       0.01,
       10.0,
       {},
       "m; range of that potential (HM95: 0.3)"},
      {"step_time",
       ParamType::kDouble,
       c.step_time,
       0.0,
       10.0,
       {},
       "s; Δt, another's step width is its speed times this (HM95: 2)"},
      {"u0",
       ParamType::kDouble,
       c.u0_wall,
       0.0,
       1000.0,
       {},
       "m^2/s^2; strength of an obstacle's repulsive potential (HM95: 10)"},
      {"r", ParamType::kDouble, c.r_wall, 0.01, 10.0, {}, "m; range of that potential (HM95: 0.2)"},
      {"view_angle",
       ParamType::kDouble,
       200.0,
       0.0,
       360.0,
       {},
       "degrees; field of view 2φ, others outside it weigh out_of_view (HM95: 200)"},
      {"out_of_view",
       ParamType::kDouble,
       c.out_of_view,
       0.0,
       1.0,
       {},
       "weight c of a pedestrian outside the field of view (HM95: 0.5)"},
      {"max_speed_factor",
       ParamType::kDouble,
       1.3,
       0.1,
       3.0,
       {},
       "max speed as a multiple of v_pref (HM95: 1.3)"},
      {"neighbor_dist",
       ParamType::kDouble,
       5.0,
       0.0,
       100.0,
       {},
       "m; only people whose centre is closer than this push (V at 5 m: 1e-7 of V0)"},
      {"max_neighbors",
       ParamType::kInt,
       std::int64_t{10},
       0,
       100,
       {},
       "number of nearest people that push (as ORCA's max_neighbors)"},
      {"wall_range",
       ParamType::kDouble,
       2.0,
       0.0,
       100.0,
       {},
       "m; only rectangles closer than this push (U at 2 m: 5e-5 of U0)"},
      {"guidance",
       ParamType::kBool,
       true,
       0,
       1,
       {},
       "follow the ORCA humans' roadmap around the map's rectangles (false: straight to goal)"},
      {"guidance_margin",
       ParamType::kDouble,
       0.2,
       0.0,
       2.0,
       {},
       "m; roadmap corners sit this much farther out than the agent's radius (as ORCA's)"},
      // Group forces act on members of walking groups alone: at their defaults they are left
      // out of the config hash, so results without groups keep theirs.
      {"group_coherence",
       ParamType::kDouble,
       g.coherence,
       0.0,
       100.0,
       {},
       "m/s^2; pull towards the group's centre beyond (N-1)/2 m (PySocialForce: 2)",
       /*hashed_at_default=*/false},
      {"group_repulsion",
       ParamType::kDouble,
       g.repulsion,
       0.0,
       100.0,
       {},
       "m/s^2; push from a member closer than group_repulsion_dist (PySocialForce: 1)",
       /*hashed_at_default=*/false},
      {"group_repulsion_dist",
       ParamType::kDouble,
       g.repulsion_dist,
       0.0,
       10.0,
       {},
       "m between centres (PySocialForce: 0.5)",
       /*hashed_at_default=*/false},
      {"group_gaze",
       ParamType::kDouble,
       g.gaze,
       0.0,
       100.0,
       {},
       "m/s^2 per rad; turn towards the other members beyond group_view (PySocialForce: 3)",
       /*hashed_at_default=*/false},
      {"group_view",
       ParamType::kDouble,
       100.0,
       0.0,
       180.0,
       {},
       "degrees between walking direction and the others' centre before gazing (PySocialForce: "
       "100)",
       /*hashed_at_default=*/false},
  };
}

SocialForcePolicy::SocialForcePolicy(const Params& params)
    : max_speed_factor_(params.GetDouble("max_speed_factor")),
      neighbor_dist_(params.GetDouble("neighbor_dist")),
      max_neighbors_(static_cast<int>(params.GetInt("max_neighbors"))),
      wall_range_(params.GetDouble("wall_range")),
      guide_(params.GetBool("guidance"), params.GetDouble("guidance_margin")) {
  constants_.tau = params.GetDouble("tau");
  constants_.v0_ped = params.GetDouble("v0");
  constants_.sigma = params.GetDouble("sigma");
  constants_.step_time = params.GetDouble("step_time");
  constants_.u0_wall = params.GetDouble("u0");
  constants_.r_wall = params.GetDouble("r");
  constants_.cos_view = std::cos(params.GetDouble("view_angle") * M_PI / 360.0);
  constants_.out_of_view = params.GetDouble("out_of_view");
  group_constants_.coherence = params.GetDouble("group_coherence");
  group_constants_.repulsion = params.GetDouble("group_repulsion");
  group_constants_.repulsion_dist = params.GetDouble("group_repulsion_dist");
  group_constants_.gaze = params.GetDouble("group_gaze");
  group_constants_.half_view = params.GetDouble("group_view") * M_PI / 180.0;
}

PolicyNeeds SocialForcePolicy::Needs() const {
  PolicyNeeds needs;
  needs.map = true;
  needs.heading_frame = false;                              // neighbours in world coordinates
  needs.non_holonomic = NonHolonomicDrive::kTrackVelocity;  // turn-then-go (docs/kinematics.md)
  return needs;
}

void SocialForcePolicy::Reset(const EpisodeContext& ctx) {
  map_ = ctx.map;
  time_step_ = ctx.sim.time_step;
  guide_.Reset(ctx.map);
}

Vec2 SocialForcePolicy::Acceleration(const AgentState& self, const orca::GuidanceTarget& target,
                                     const std::vector<walking::Neighbour>& others,
                                     std::span<const Vec2> group) const {
  const Vec2 desired = orca::PreferredVelocity(self.position, target, self.v_pref);
  Vec2 total = DrivingForce(self.velocity, desired, constants_.tau);
  // The heading that decides the field of view: where the agent wants to go.
  const double norm = desired.norm();
  const Vec2 e = norm > 0.0 ? Vec2(desired / norm) : Vec2::Zero();
  for (const walking::Neighbour& other : others) {
    const Vec2 f = PedestrianRepulsion(self.position - other.position, other.velocity, constants_);
    total += ViewWeight(e, f, constants_) * f;
  }
  if (map_ != nullptr) {
    for (const Rect& rect : map_->rectangles) {
      const Vec2 r = self.position - NearestPoint(rect, self.position);
      if (r.squaredNorm() < wall_range_ * wall_range_) total += WallRepulsion(r, constants_);
    }
  }
  if (!group.empty()) total += GroupForce(self.position, e, group, group_constants_);
  return total;
}

Action SocialForcePolicy::Decide(const Observation& obs) {
  const AgentState& self = obs.self;
  const orca::GuidanceTarget target = guide_.Target(self);
  walking::GatherNeighbours(obs, neighbor_dist_, max_neighbors_, &ids_, &others_);
  group_.clear();
  if (obs.agents != nullptr) GroupMates(obs.agents->agents(), obs.self_index, &group_);
  Vec2 velocity = self.velocity + Acceleration(self, target, others_, group_) * time_step_;
  const double max_speed = max_speed_factor_ * self.v_pref;
  if (velocity.norm() > max_speed) velocity *= max_speed / velocity.norm();
  return Action{
      walking::SlideAlongRectangles(map_, time_step_, self.position, self.radius, velocity)};
}

}  // namespace crowdsim::social_force
