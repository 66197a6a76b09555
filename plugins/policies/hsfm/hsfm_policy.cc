#include "hsfm_policy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "crowdsim/agent_index.h"
#include "crowdsim/static_map.h"
#include "walking/contact.h"

namespace crowdsim::hsfm {
namespace {

// One row of the schema: a number in [lo, hi].
ParamSpec Number(std::string name, double value, double lo, double hi, std::string doc) {
  return {std::move(name), ParamType::kDouble, value, lo, hi, {}, std::move(doc)};
}

}  // namespace

ParamSchema Schema() {
  const Constants c;
  const GroupConstants g;
  return {
      Number("mass", c.mass, 1.0, 500.0, "kg; m (JHSFM: 75)"),
      Number("tau", c.tau, 0.05, 10.0, "s; relaxation time (Helbing 2000, HSFM: 0.5)"),
      Number("a", c.a, 0.0, 1e5,
             "N; A, strength of another person's repulsion (Helbing 2000: 2000)"),
      Number("b", c.b, 0.01, 10.0, "m; B, its range (Helbing 2000: 0.08)"),
      Number("a_wall", c.a_wall, 0.0, 1e5,
             "N; A_w, strength of a rectangle's repulsion (HSFM: 2000)"),
      Number("b_wall", c.b_wall, 0.01, 10.0, "m; B_w, its range (HSFM: 0.08)"),
      Number("k_body", c.k_body, 0.0, 1e7, "kg/s^2; k, body compression (Helbing 2000: 1.2e5)"),
      Number("k_friction", c.k_friction, 0.0, 1e7,
             "kg/(m s); κ, sliding friction (Helbing 2000: 2.4e5)"),
      Number("k_o", c.k_o, 0.0, 10.0, "share of the interaction forces pushing sideways (HSFM: 1)"),
      Number("k_d", c.k_d, 0.0, 1e5, "kg/s; damping of the sideways velocity (HSFM: 500)"),
      Number("k_lambda", c.k_lambda, 0.0, 100.0,
             "1/(kg m); turning stiffness per newton (JHSFM: 0.1; HSFM: 0.3 with turn_to: "
             "desired)"),
      Number("alpha", c.alpha, 0.01, 100.0, "ratio of the heading's time constants (HSFM: 3)"),
      {"turn_to",
       ParamType::kString,
       std::string("total"),
       0,
       0,
       {"total", "desired"},
       "the heading turns to the total force (JHSFM) or to the driving force (HSFM)"},
      Number("max_speed_factor", 1.0, 0.1, 3.0,
             "max speed as a multiple of v_pref (Social-Navigation-PyEnvs: 1)"),
      Number("sub_step", 0.025, 0.001, 1.0,
             "s; longest integration step within a decision (stable at the stiffness)"),
      Number("neighbor_dist", 3.0, 0.0, 100.0,
             "m; only people whose centre is closer push (there: < 1e-10 A, radii <= 0.5 m)"),
      {"max_neighbors",
       ParamType::kInt,
       std::int64_t{10},
       0,
       100,
       {},
       "number of nearest people that push (as social_force's)"},
      Number("wall_range", 1.5, 0.0, 100.0,
             "m; only rectangles closer push (there: < 4e-6 A_w, radius <= 0.5 m)"),
      {"guidance",
       ParamType::kBool,
       true,
       0,
       1,
       {},
       "follow the ORCA humans' roadmap around the map's rectangles (false: straight to goal)"},
      Number("guidance_margin", 0.2, 0.0, 2.0,
             "m; roadmap corners sit this much farther out than the agent's radius (as ORCA's)"),
      Number("group_k_forward", g.k_forward, 0.0, 1e5,
             "N; forward group cohesion beyond group_d_forward (HSFM code: 200)"),
      Number("group_k_sideways", g.k_sideways, 0.0, 1e5,
             "N; sideways group cohesion beyond group_d_sideways (HSFM code: 200)"),
      Number("group_d_forward", g.d_forward, 0.0, 10.0,
             "m; forward distance to the group's centre before cohesion (HSFM code: 1)"),
      Number("group_d_sideways", g.d_sideways, 0.0, 10.0,
             "m; sideways distance to the group's centre before cohesion (HSFM code: 0.5)"),
  };
}

HsfmPolicy::HsfmPolicy(const Params& params)
    : max_speed_factor_(params.GetDouble("max_speed_factor")),
      sub_step_(params.GetDouble("sub_step")),
      neighbor_dist_(params.GetDouble("neighbor_dist")),
      max_neighbors_(static_cast<int>(params.GetInt("max_neighbors"))),
      wall_range_(params.GetDouble("wall_range")),
      guide_(params.GetBool("guidance"), params.GetDouble("guidance_margin")) {
  constants_.mass = params.GetDouble("mass");
  constants_.tau = params.GetDouble("tau");
  constants_.a = params.GetDouble("a");
  constants_.b = params.GetDouble("b");
  constants_.a_wall = params.GetDouble("a_wall");
  constants_.b_wall = params.GetDouble("b_wall");
  constants_.k_body = params.GetDouble("k_body");
  constants_.k_friction = params.GetDouble("k_friction");
  constants_.k_o = params.GetDouble("k_o");
  constants_.k_d = params.GetDouble("k_d");
  constants_.k_lambda = params.GetDouble("k_lambda");
  constants_.alpha = params.GetDouble("alpha");
  constants_.turn_to_total = params.GetString("turn_to") == "total";
  group_constants_.k_forward = params.GetDouble("group_k_forward");
  group_constants_.k_sideways = params.GetDouble("group_k_sideways");
  group_constants_.d_forward = params.GetDouble("group_d_forward");
  group_constants_.d_sideways = params.GetDouble("group_d_sideways");
}

PolicyNeeds HsfmPolicy::Needs() const {
  PolicyNeeds needs;
  needs.map = true;
  needs.heading_frame = false;                              // neighbours in world coordinates
  needs.non_holonomic = NonHolonomicDrive::kTrackVelocity;  // turn-then-go (docs/kinematics.md)
  return needs;
}

void HsfmPolicy::Reset(const EpisodeContext& ctx) {
  map_ = ctx.map;
  time_step_ = ctx.sim.time_step;
  guide_.Reset(ctx.map);
  started_ = false;
  body_ = Body{};
  returned_ = Vec2::Zero();
}

void HsfmPolicy::SyncBody(const AgentState& self, const Vec2& desired) {
  if (!started_) {
    const Vec2& face = self.velocity.squaredNorm() > 1e-12 ? self.velocity : desired;
    body_.theta = face.squaredNorm() > 0.0 ? std::atan2(face.y(), face.x()) : 0.0;
    body_.omega = 0.0;
    started_ = true;
  } else if (self.velocity == returned_) {
    return;  // the body walked what it was told: its own velocity stands
  }
  // The first decision, or the harness moved the agent otherwise (a robot's tracker).
  body_.forward = self.velocity.dot(body_.Heading());
  body_.sideways = self.velocity.dot(body_.Left());
}

Vec2 HsfmPolicy::InteractionForce(const Body& body, double radius, double elapsed) const {
  const Vec2 v = body.Velocity();
  Vec2 f = Vec2::Zero();
  for (const walking::Neighbour& other : others_) {
    const Vec2 r = body.position - (other.position + elapsed * other.velocity);
    // Beyond 20 B past contact the repulsion is below 2e-9 A: skip its exponential.
    const double reach = radius + other.radius + 20.0 * constants_.b;
    if (r.squaredNorm() < reach * reach)
      f += PersonForce(r, radius + other.radius, v, other.velocity, constants_);
  }
  if (map_ == nullptr) return f;
  for (const Rect& rect : map_->rectangles) {
    const Vec2 r = body.position - walking::NearestPoint(rect, body.position);
    if (r.squaredNorm() < wall_range_ * wall_range_) f += WallForce(r, radius, v, constants_);
  }
  return f;
}

Action HsfmPolicy::Decide(const Observation& obs) {
  const AgentState& self = obs.self;
  const orca::GuidanceTarget target = guide_.Target(self);
  walking::GatherNeighbours(obs, neighbor_dist_, max_neighbors_, &ids_, &others_);
  group_.clear();
  if (obs.agents != nullptr) GroupMates(obs.agents->agents(), obs.self_index, &group_);
  Vec2 mates = Vec2::Zero();
  for (const Vec2& p : group_) mates += p;
  SyncBody(self, orca::PreferredVelocity(self.position, target, self.v_pref));
  body_.position = self.position;

  // Sub-steps short enough for the stiffest term (README.md: stability).
  const int steps = std::max(1, static_cast<int>(std::ceil(time_step_ / sub_step_ - 1e-9)));
  const double h = time_step_ / steps;
  const double max_speed = max_speed_factor_ * self.v_pref;
  for (int k = 0; k < steps; ++k) {
    const Vec2 desired = orca::PreferredVelocity(body_.position, target, self.v_pref);
    const Vec2 f0 = DrivingForce(body_.Velocity(), desired, constants_);
    const Vec2 fe = InteractionForce(body_, self.radius, k * h);
    Vec2 group = Vec2::Zero();
    if (!group_.empty()) {
      const Vec2 centre = (mates + body_.position) / (static_cast<double>(group_.size()) + 1.0);
      group = GroupCohesion(centre - body_.position, body_, group_constants_);
    }
    Advance(&body_, f0, fe, group, h, max_speed, constants_);
  }
  // The step's mean velocity: the harness then moves the agent where the model took it.
  const Vec2 walked = (body_.position - self.position) / time_step_;
  const Vec2 velocity =
      walking::SlideAlongRectangles(map_, time_step_, self.position, self.radius, walked);
  if (velocity != walked) {  // blocked: the body keeps only what it walked
    body_.forward = velocity.dot(body_.Heading());
    body_.sideways = velocity.dot(body_.Left());
  }
  returned_ = velocity;
  return Action{velocity};
}

}  // namespace crowdsim::hsfm
