#include "walking/roadmap_guide.h"

#include "orca/roadmap.h"

namespace crowdsim::walking {

void RoadmapGuide::Reset(const StaticMap* map) {
  map_ = map;
  roadmap_radius_ = -1.0;  // the roadmap is made for the agent's radius at its first decision
  guidance_.Reset(nullptr);
}

orca::GuidanceTarget RoadmapGuide::Target(const AgentState& self) {
  if (enabled_ && map_ != nullptr && !map_->rectangles.empty() && self.radius != roadmap_radius_) {
    roadmap_radius_ = self.radius;
    guidance_.Reset(orca::SharedRoadmap(*map_, self.radius, margin_));
  }
  return guidance_.roadmap() != nullptr ? guidance_.Next(self.position, self.goal)
                                        : orca::GuidanceTarget{self.goal, true};
}

}  // namespace crowdsim::walking
