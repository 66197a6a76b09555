// The `crowdnav` world: CrowdNav's obstacle-free scenarios (circle_crossing, square_crossing)
// reproduced draw for draw, with our portable Rng in place of numpy's.
#pragma once

#include <memory>
#include <string>

#include "crowdsim/params.h"
#include "crowdsim/world_source.h"

namespace crowdsim::crowdnav {

/// CrowdNav's human generation rules.
enum class Crossing { kCircle, kSquare };

/// Parameters of the plugin (scenario, circle_radius, square_width, new_goal_count).
ParamSchema Schema();

/// CrowdNav's open-space scenarios; one empty map shared by every scenario.
class CrowdNavWorld final : public WorldSource {
 public:
  /// From validated plugin parameters.
  explicit CrowdNavWorld(const Params& params);

  /// "crowdnav:scenario=S", plus the non-default sizes.
  std::string Identity() const override { return identity_; }
  /// The robot goes from (0, -circle_radius) to (0, circle_radius); humans as CrowdNav's
  /// generate_*_human. Thread-safe.
  Scenario Make(const ScenarioRequest& request) const override;

 private:
  Crossing crossing_;
  double circle_radius_;
  double square_width_;
  int new_goal_count_;
  std::string identity_;
  std::shared_ptr<const StaticMap> map_;  // empty, shared by all scenarios
};

}  // namespace crowdsim::crowdnav
