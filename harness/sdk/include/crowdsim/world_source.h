// World plugin interface: produces the scenario of every episode.
#pragma once

#include <cstdint>
#include <string>

#include "crowdsim/export.h"
#include "crowdsim/scenario.h"
#include "crowdsim/sim_config.h"

namespace crowdsim {

enum class HumanGoalMode { kStay, kNewGoal };

/// What the harness asks a world for.
struct CROWDSIM_SDK_API ScenarioRequest {
  std::uint64_t seed = 0;  ///< episode seed (DeriveSeed)
  std::int64_t episode_index = 0;
  int num_humans = 5;
  HumanGoalMode goal_mode = HumanGoalMode::kStay;
  SimConfig sim;  ///< radii and speeds
};

class CROWDSIM_SDK_API WorldSource {
 public:
  virtual ~WorldSource();
  /// Stable identity used in seeds and manifests (e.g. "random_rect:obstacles=1:split=test").
  virtual std::string Identity() const = 0;
  /// Number of distinct frozen layouts (0 if generated on the fly).
  virtual int LayoutCount() const { return 0; }
  /// The scenario of one episode; the same request always gives the same scenario.
  virtual Scenario Make(const ScenarioRequest& request) const = 0;
};

}  // namespace crowdsim
