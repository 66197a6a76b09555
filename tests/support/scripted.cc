#include "scripted.h"

#include <algorithm>

namespace crowdsim::testing {

Action GoStraightPolicy::Decide(const Observation& obs) {
  const Vec2 d = obs.self.goal - obs.self.position;
  const double dist = d.norm();
  if (dist < 1e-12) return Action{};
  const double speed = std::min(obs.self.v_pref, dist / time_step_);
  return Action{d / dist * speed};
}

std::shared_ptr<const StaticMap> MakeMap(std::vector<Rect> rects, Rect bounds) {
  auto m = std::make_shared<StaticMap>();
  m->name = "test-map";
  m->bounds = bounds;
  m->rectangles = std::move(rects);
  return m;
}

std::shared_ptr<const StaticMap> MakeRoom(std::vector<Rect> obstacles) {
  std::vector<Rect> rects = {
      Rect::FromCorners(-5.5, -5.5, 5.5, -5.0), Rect::FromCorners(-5.5, 5.0, 5.5, 5.5),
      Rect::FromCorners(-5.5, -5.0, -5.0, 5.0), Rect::FromCorners(5.0, -5.0, 5.5, 5.0)};
  rects.insert(rects.end(), obstacles.begin(), obstacles.end());
  return MakeMap(std::move(rects), Rect::FromCorners(-5.5, -5.5, 5.5, 5.5));
}

Scenario MakeScenario(std::shared_ptr<const StaticMap> map, Vec2 robot_start, Vec2 robot_goal,
                      std::vector<std::pair<Vec2, Vec2>> humans) {
  Scenario s;
  s.map = std::move(map);
  s.robot_start = robot_start;
  s.robot_goal = robot_goal;
  for (const auto& [start, goal] : humans) {
    HumanSpec h;
    h.start = start;
    h.goals = {goal};
    s.humans.push_back(h);
  }
  s.seed = 1;
  s.layout = "scripted";
  return s;
}

}  // namespace crowdsim::testing
