#include "orca_policy.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>

#include "crowdsim/agent_index.h"

namespace crowdsim::orca {
namespace {

YieldSettings YieldSettingsFrom(const Params& params) {
  YieldSettings settings;
  settings.jam_steps = static_cast<int>(params.GetInt("yield_steps"));
  settings.min_time = params.GetDouble("yield_time");
  settings.max_time = params.GetDouble("yield_max_time");
  if (settings.max_time < settings.min_time) {
    throw std::invalid_argument("orca: yield_max_time (" + std::to_string(settings.max_time) +
                                " s) is shorter than yield_time (" +
                                std::to_string(settings.min_time) +
                                " s); raise yield_max_time or lower yield_time");
  }
  return settings;
}

}  // namespace

ParamSchema Schema() {
  return {
      {"neighbor_dist",
       ParamType::kDouble,
       10.0,
       0.0,
       100.0,
       {},
       "m; only agents whose centre is closer than this are avoided"},
      {"max_neighbors",
       ParamType::kInt,
       std::int64_t{10},
       0,
       100,
       {},
       "number of nearest agents avoided (0: obstacles only)"},
      {"time_horizon",
       ParamType::kDouble,
       5.0,
       0.1,
       60.0,
       {},
       "s; collisions with agents are avoided this far ahead"},
      {"time_horizon_obst",
       ParamType::kDouble,
       5.0,
       0.1,
       60.0,
       {},
       "s; collisions with obstacles are avoided this far ahead"},
      {"radius_padding",
       ParamType::kDouble,
       0.01,
       0.0,
       1.0,
       {},
       "m; added to every radius in the solve (CrowdNav: 0.01)"},
      {"safety_space",
       ParamType::kDouble,
       0.0,
       0.0,
       1.0,
       {},
       "m; added to every radius (0.15 for the IL teacher of an invisible robot)"},
      {"max_speed_factor",
       ParamType::kDouble,
       1.0,
       0.0,
       3.0,
       {},
       "max speed as a multiple of v_pref (CrowdNav: 1)"},
      {"guidance",
       ParamType::kBool,
       true,
       0,
       1,
       {},
       "follow a visibility roadmap around the map's rectangles (false: ORCA alone)"},
      {"guidance_margin",
       ParamType::kDouble,
       0.2,
       0.0,
       2.0,
       {},
       "m; roadmap corners sit this much farther out than the agent's radius"},
      {"stall_steps",
       ParamType::kInt,
       std::int64_t{8},
       1,
       1000,
       {},
       "decisions without progress along the path before replanning"},
      {"yield",
       ParamType::kBool,
       true,
       0,
       1,
       {},
       "resolve jams in narrow passages: the agent of lower rank backs off (humans among "
       "rectangles, with guidance; see README)"},
      {"yield_steps",
       ParamType::kInt,
       std::int64_t{8},
       1,
       1000,
       {},
       "decisions of near standstill (< 0.5 m moved) against a jammed agent of higher rank "
       "before giving way"},
      {"yield_time",
       ParamType::kDouble,
       2.0,
       0.0,
       60.0,
       {},
       "s; a yield lasts at least this long, longer while the other still comes at the agent"},
      {"yield_max_time",
       ParamType::kDouble,
       8.0,
       0.0,
       60.0,
       {},
       "s; a yield never lasts longer than this (>= yield_time)"},
      {"group_cohesion",
       ParamType::kBool,
       true,
       0,
       1,
       {},
       "a walking group's member farther than (N-1)/2 m from the group's centre heads half "
       "towards it (Moussaid et al. 2010's threshold; README)",
       /*hashed_at_default=*/false},
      {"others_pref_zero",
       ParamType::kBool,
       true,
       0,
       1,
       {},
       "CrowdNav's model of the others (stand still, reciprocal); see README: the only "
       "model of a one-agent solve, false is rejected"},
  };
}

OrcaPolicy::OrcaPolicy(const Params& params)
    : neighbor_dist_(params.GetDouble("neighbor_dist")),
      max_neighbors_(static_cast<int>(params.GetInt("max_neighbors"))),
      time_horizon_(params.GetDouble("time_horizon")),
      time_horizon_obst_(params.GetDouble("time_horizon_obst")),
      radius_padding_(params.GetDouble("radius_padding")),
      safety_space_(params.GetDouble("safety_space")),
      max_speed_factor_(params.GetDouble("max_speed_factor")),
      guidance_enabled_(params.GetBool("guidance")),
      guidance_margin_(params.GetDouble("guidance_margin")),
      yield_enabled_(params.GetBool("yield")),
      group_cohesion_(params.GetBool("group_cohesion")),
      guidance_(static_cast<int>(params.GetInt("stall_steps"))),
      yielding_(YieldSettingsFrom(params)) {
  if (!params.GetBool("others_pref_zero")) {
    throw std::invalid_argument(
        "orca: others_pref_zero: false is not supported. In a decentralised solve only this "
        "agent's velocity is computed, so the others' preferred velocities never enter it; "
        "remove the key or set it to true");
  }
}

PolicyNeeds OrcaPolicy::Needs() const {
  PolicyNeeds needs;
  needs.map = true;
  needs.heading_frame = false;  // a human's neighbours come in world coordinates
  needs.non_holonomic = NonHolonomicDrive::kTrackVelocity;  // turn-then-go (docs/kinematics.md)
  return needs;
}

void OrcaPolicy::Reset(const EpisodeContext& ctx) {
  ctx_map_ = ctx.map;
  ctx_time_step_ = ctx.sim.time_step;
  const double radius = ctx.role == AgentRole::kRobot ? ctx.sim.robot_radius : ctx.sim.human_radius;
  UseMap(ctx.map, radius + radius_padding_ + safety_space_);
  guidance_.Reset(roadmap_);  // a new episode: new start and goal
  yielding_.Reset();
}

void OrcaPolicy::UseMap(const StaticMap* map, double radius) {
  const bool same_map = map == map_ && (map == nullptr || map->rectangles == map_rects_);
  if (!same_map) {
    map_ = map;
    map_rects_ = map ? map->rectangles : std::vector<Rect>{};
    obstacles_ = map ? OrcaObstacles::FromMap(*map) : OrcaObstacles();
  }
  if (!same_map || radius != map_radius_) {
    map_radius_ = radius;
    const bool plan = guidance_enabled_ && map != nullptr && !map->rectangles.empty();
    roadmap_ = plan ? SharedRoadmap(*map, radius, guidance_margin_) : nullptr;
    guidance_.Reset(roadmap_);
  }
}

OrcaPolicy::Scratch& OrcaPolicy::ThreadScratch() {
  // A plain pointer, set on the thread's first call: a thread-local object with a destructor
  // would cost two lookups per call (its guard's and its own), this costs one.
  thread_local Scratch* scratch = nullptr;
  if (scratch == nullptr) scratch = &MakeThreadScratch();
  return *scratch;
}

OrcaPolicy::Scratch& OrcaPolicy::MakeThreadScratch() {
  thread_local Scratch scratch;  // destroyed at the thread's exit
  return scratch;
}

void OrcaPolicy::GatherNeighbours(const Observation& obs, Scratch* s) const {
  std::vector<OrcaAgent>& neighbours = s->neighbours;
  const double padding = radius_padding_ + safety_space_;
  if (obs.agents != nullptr) {
    // Human: ground truth from the harness's grid, nearest first.
    obs.agents->Nearest(obs.self.position, neighbor_dist_, max_neighbors_, obs.self_index,
                        &s->neighbour_ids);
    const auto all = obs.agents->agents();
    const std::span<const int> ids = s->neighbour_ids;
    neighbours.resize(ids.size());  // not cleared first: no construction when the size repeats
    // Field by field: a braced OrcaAgent was built on the stack and then copied.
    OrcaAgent* out = neighbours.data();
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const AgentState& a = all[ids[k]];
      out[k].position = a.position;
      out[k].velocity = a.velocity;
      out[k].radius = a.radius + padding;
    }
    return;
  }
  // Robot: the people its person sensor reports, in the sensor frame.
  const SensorReading* reading = obs.Reading("person");
  if (reading == nullptr || max_neighbors_ <= 0) {
    neighbours.clear();
    return;
  }
  // The max_neighbors_ nearest in range, nearest first, equal distances in the sensor's
  // order: kept sorted while the people arrive, each moved into place past the farther ones
  // (a handful of slots; no sort of everybody, no vector insert).
  std::vector<Scratch::Seen>& seen = s->seen;
  const auto max_seen = static_cast<std::size_t>(max_neighbors_);
  if (seen.size() < max_seen + 1) seen.resize(max_seen + 1);  // a spare slot for the newcomer
  std::size_t n = 0;
  const double range_sq = neighbor_dist_ * neighbor_dist_;
  for (const PersonObservation& person : reading->people) {
    const Vec2 position = obs.frame.origin + obs.frame.VectorToWorld(person.position);
    const double dist_sq = (position - obs.self.position).squaredNorm();
    if (dist_sq >= range_sq) continue;
    if (n == max_seen && !(dist_sq < seen[n - 1].dist_sq)) continue;
    std::size_t j = n;
    for (; j > 0 && dist_sq < seen[j - 1].dist_sq; --j) seen[j] = seen[j - 1];
    seen[j] = {dist_sq,
               {position, obs.frame.VectorToWorld(person.velocity), person.radius + padding}};
    if (n < max_seen) ++n;
  }
  neighbours.resize(n);
  for (std::size_t k = 0; k < n; ++k) neighbours[k] = seen[k].agent;
}

GuidanceTarget OrcaPolicy::Target(const Observation& obs, double radius, double time_step,
                                  Scratch* s) {
  const AgentState& self = obs.self;
  // Without rectangles there is no roadmap: neither guidance nor yielding has anything to do
  // (the guidance would return the goal itself).
  if (!guidance_enabled_ || guidance_.roadmap() == nullptr) return {self.goal, true};
  // Jams happen in the narrow passages between rectangles; in the open plane ORCA alone is
  // CrowdNav's model and stays untouched. The robot (no ground truth) never yields.
  if (yield_enabled_ && obs.agents != nullptr && yielding_.Observe(self.position)) {
    s->yield_neighbours.clear();
    const auto all = obs.agents->agents();
    for (std::size_t k = 0; k < s->neighbour_ids.size(); ++k) {
      const AgentState& a = all[s->neighbour_ids[k]];
      s->yield_neighbours.push_back({a.position, a.velocity, s->neighbours[k].radius, a.v_pref,
                                     YieldRank(a, s->neighbour_ids[k])});
    }
    Vec2 back;
    if (yielding_.Step(self.position, radius, YieldRank(self, obs.self_index), time_step,
                       s->yield_neighbours, &back)) {
      return {back, false};
    }
    if (yielding_.finished()) guidance_.Restart();  // off the old path: plan from here
  }
  return guidance_.Next(self.position, self.goal);
}

Action OrcaPolicy::Decide(const Observation& obs) {
  const AgentState& self = obs.self;
  const double radius = self.radius + radius_padding_ + safety_space_;
  // Reset synced the map; within an episode only the radius can differ from Reset's.
  if (radius != map_radius_) UseMap(ctx_map_, radius);
  const double time_step = ctx_time_step_;

  Scratch& scratch = ThreadScratch();
  GatherNeighbours(obs, &scratch);
  Vec2 pref =
      PreferredVelocity(self.position, Target(obs, radius, time_step, &scratch), self.v_pref);
  if (group_cohesion_ && obs.agents != nullptr) {
    GroupMates(obs.agents->agents(), obs.self_index, &scratch.group);
    pref = KeepWithGroup(self.position, pref, self.v_pref, scratch.group);
  }

  OrcaParams params;
  params.time_horizon = time_horizon_;
  params.time_horizon_obst = time_horizon_obst_;
  params.max_speed = self.v_pref * max_speed_factor_;
  const OrcaAgent me{self.position, self.velocity, radius};
  return Action{ComputeOrcaVelocity(me, scratch.neighbours, obstacles_, params, pref, time_step,
                                    &scratch.solve)};
}

}  // namespace crowdsim::orca
