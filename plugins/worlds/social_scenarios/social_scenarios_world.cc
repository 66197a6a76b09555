#include "social_scenarios_world.h"

#include <stdexcept>

namespace crowdsim::social_scenarios {

ParamSchema Schema() {
  return {{"scenario", ParamType::kString, std::string("frontal_approach"), 0, 0, kScenarioNames,
           "the interaction (README.md: geometry, people, what varies)"}};
}

SocialScenariosWorld::SocialScenariosWorld(const Params& params)
    : name_(params.GetString("scenario")),
      identity_("social_scenarios:scenario=" + name_),
      layout_(MakeLayout(name_)),
      map_(std::make_shared<const StaticMap>(layout_.map)) {}

Scenario SocialScenariosWorld::Make(const ScenarioRequest& request) const {
  if (request.num_humans > kMaxPeople) {
    throw std::invalid_argument("social_scenarios: scenario '" + name_ + "' places at most " +
                                std::to_string(kMaxPeople) + " people, asked for " +
                                std::to_string(request.num_humans) + ": set humans.count to 0-" +
                                std::to_string(kMaxPeople));
  }
  Scenario s;
  s.map = map_;
  s.seed = request.seed;
  s.layout = name_;
  s.robot_start = layout_.robot_start;
  s.robot_goal = layout_.robot_goal;
  Rng rng(request.seed);
  for (int k = 0; k < request.num_humans; ++k) {
    const PersonPlan p = MakePerson(name_, k, request.num_humans, rng);
    HumanSpec h;
    h.start = p.start;
    h.goals = {p.goal};
    ApplyHumanAttributes(request, k, &h);
    h.v_pref *= p.speed_factor;
    if (p.group >= 0) h.group = p.group;  // a scripted group, whatever humans.groups says
    s.humans.push_back(std::move(h));
  }
  return s;
}

}  // namespace crowdsim::social_scenarios
