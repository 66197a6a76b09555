// The `orca` policy: CrowdNav's decentralised ORCA (each agent solves for itself, treating the
// others as reciprocal agents), plus the static map's rectangles as ORCA obstacles and a
// roadmap for global guidance. The humans' motion model, the ORCA robot baseline and the
// imitation-learning teacher.
#pragma once

#include <memory>
#include <vector>

#include "crowdsim/params.h"
#include "crowdsim/policy.h"
#include "orca/guidance.h"
#include "orca/obstacles.h"
#include "orca/solver.h"
#include "orca/yielding.h"

namespace crowdsim::orca {

/// The plugin's parameters (CrowdNav's defaults).
ParamSchema Schema();

class OrcaPolicy final : public Policy {
 public:
  explicit OrcaPolicy(const Params& params);

  PolicyNeeds Needs() const override;
  void Reset(const EpisodeContext& ctx) override;
  Action Decide(const Observation& obs) override;

 private:
  /// Rebuilds the obstacles and the roadmap when the map or the radius changed.
  void UseMap(const StaticMap* map, double radius);
  /// What one decision gathers and drops: one per thread, not per policy, so that a crowd of
  /// a thousand policies writes its neighbours into memory that is still in cache.
  struct Scratch {
    std::vector<OrcaAgent> neighbours;
    std::vector<int> neighbour_ids;  ///< humans: the neighbours' indices in obs.agents
    std::vector<YieldNeighbour> yield_neighbours;
    struct Seen {
      double dist_sq;
      OrcaAgent agent;
    };
    std::vector<Seen> seen;
    std::vector<Vec2> group;  ///< the walking group's other members
    OrcaSolveScratch solve;
  };
  /// The calling thread's scratch: one thread-local lookup (a call in a plugin) per decision.
  static Scratch& ThreadScratch();
  /// ThreadScratch's first call on a thread: makes the scratch, destroyed at the thread's exit.
  [[gnu::noinline, gnu::cold]] static Scratch& MakeThreadScratch();

  /// Fills s->neighbours from the ground-truth agents (humans) or the person sensor (robot).
  void GatherNeighbours(const Observation& obs, Scratch* s) const;
  /// Where to head this decision: the guidance's waypoint, or a point to back off to while
  /// giving way in a jam (humans among rectangles only).
  GuidanceTarget Target(const Observation& obs, double radius, double time_step, Scratch* s);

  // Settings.
  double neighbor_dist_;
  int max_neighbors_;
  double time_horizon_;
  double time_horizon_obst_;
  double radius_padding_;
  double safety_space_;
  double max_speed_factor_;
  bool guidance_enabled_;
  double guidance_margin_;
  bool yield_enabled_;
  bool group_cohesion_;

  // Episode state.
  const StaticMap* ctx_map_ = nullptr;
  double ctx_time_step_ = SimConfig{}.time_step;
  const StaticMap* map_ = nullptr;  // the map the obstacles below were built from
  std::vector<Rect> map_rects_;     // its rectangles, to notice a new map at the same address
  double map_radius_ = -1.0;        // radius the roadmap was built for
  OrcaObstacles obstacles_;
  std::shared_ptr<const Roadmap> roadmap_;  // null without guidance or rectangles
  Guidance guidance_;
  Yielding yielding_;
};

}  // namespace crowdsim::orca
