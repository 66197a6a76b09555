// The geometry of each named interaction scenario: walls, the robot's start and goal, and where
// its people start and go (README.md draws and sizes each).
#pragma once

#include <string>
#include <vector>

#include "crowdsim/rng.h"
#include "crowdsim/scenario.h"
#include "crowdsim/static_map.h"

namespace crowdsim::social_scenarios {

/// The scenarios, in the order of the `scenario` parameter's choices.
inline const std::vector<std::string> kScenarioNames = {
    "frontal_approach", "overtaking",   "crossing",        "doorway",    "narrow_hallway",
    "blind_corner",     "intersection", "standing_person", "join_group", "leave_group"};

/// One person of a scenario: start, goal, speed factor (times the suite's human v_pref) and,
/// for a scripted group, its group id.
struct PersonPlan {
  Vec2 start;
  Vec2 goal;
  double speed_factor = 1.0;
  int group = -1;
};

/// The most people a scenario places (its geometry holds this many).
inline constexpr int kMaxPeople = 6;

/// A scenario's fixed part.
struct Layout {
  StaticMap map;
  Vec2 robot_start;
  Vec2 robot_goal;
};

/// The layout of scenario `name`.
Layout MakeLayout(const std::string& name);

/// Person `k` of the `count` people of scenario `name`, its variation drawn from `rng`.
PersonPlan MakePerson(const std::string& name, int k, int count, Rng& rng);

}  // namespace crowdsim::social_scenarios
