// Global guidance for a force-model person: the ORCA humans' roadmap path around the map's
// rectangles, made for the person's radius at its first decision.
#pragma once

#include "crowdsim/agent_state.h"
#include "crowdsim/static_map.h"
#include "orca/guidance.h"

namespace crowdsim::walking {

class RoadmapGuide {
 public:
  /// `enabled` false: always straight to the goal; `margin` (m): roadmap corners sit this much
  /// farther out than the radius.
  RoadmapGuide(bool enabled, double margin) : enabled_(enabled), margin_(margin) {}

  /// A new episode on `map` (null: no map).
  void Reset(const StaticMap* map);
  /// Where `self` heads now: the next roadmap waypoint, or its goal.
  orca::GuidanceTarget Target(const AgentState& self);

 private:
  bool enabled_;
  double margin_;
  const StaticMap* map_ = nullptr;
  double roadmap_radius_ = -1.0;
  orca::Guidance guidance_;
};

}  // namespace crowdsim::walking
