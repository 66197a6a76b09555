// The `social_scenarios` world: the named interaction scenarios of the social navigation
// guidelines (Francis et al. 2023), each a small fixed geometry whose people vary per episode.
#pragma once

#include <memory>
#include <string>

#include "crowdsim/params.h"
#include "crowdsim/world_source.h"
#include "scenario_layouts.h"

namespace crowdsim::social_scenarios {

/// Parameters of the plugin (scenario).
ParamSchema Schema();

class SocialScenariosWorld final : public WorldSource {
 public:
  explicit SocialScenariosWorld(const Params& params);

  /// "social_scenarios:scenario=S".
  std::string Identity() const override { return identity_; }
  /// The scenario's geometry with request.num_humans people, varied by the request's seed.
  /// Thread-safe.
  Scenario Make(const ScenarioRequest& request) const override;

 private:
  std::string name_;
  std::string identity_;
  Layout layout_;
  std::shared_ptr<const StaticMap> map_;
};

}  // namespace crowdsim::social_scenarios
