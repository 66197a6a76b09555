#include "crowdnav_world.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "crowdsim/geometry.h"
#include "crowdsim/human_placement.h"
#include "crowdsim/rng.h"

namespace crowdsim::crowdnav {
namespace {

// CrowdNav retries forever; a bound turns an impossible request into a clear error.
constexpr int kMaxTries = 100000;
constexpr double kDefaultCircleRadius = 4.0;
constexpr double kDefaultSquareWidth = 10.0;
constexpr int kDefaultNewGoalCount = 16;

std::string Number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%g", x);
  return buf;
}

// An agent already placed, as CrowdNav's rejection tests see it.
struct Placed {
  Vec2 position;
  Vec2 goal;
  double radius;
};

// Rejection sampling cannot tell "unlucky" from "full": after kMaxTries the placed humans have
// left no spot, and the message says how crowded that is and how large a world would hold them:
// a circle's room grows with its circumference, a square's with its area, and random placement
// jams before the room is full, so the size that held `human` of them is scaled up with a 25%
// margin (enough for every seed tried in the test).
[[noreturn]] void Fail(int human, const ScenarioRequest& request, bool circle, double size) {
  const double gap = 2.0 * request.sim.human_radius + request.sim.discomfort_dist;
  const double n = request.num_humans;
  const double placed = std::max(1, human);
  std::string where, fix;
  if (circle) {
    where = "circle_crossing (circle_radius " + Number(size) +
            " m: " + Number(std::round(n / (2.0 * std::numbers::pi * size) * 100.0) / 100.0) +
            " humans per metre of circle)";
    fix = "circle_radius >= ~" + Number(std::ceil(1.25 * size * n / placed * 10.0) / 10.0);
  } else {
    where = "square_crossing (square_width " + Number(size) +
            " m: " + Number(std::round(n / (size * size) * 100.0) / 100.0) + " humans per m^2)";
    fix =
        "square_width >= ~" + Number(std::ceil(1.25 * size * std::sqrt(n / placed) * 10.0) / 10.0);
  }
  throw std::runtime_error("crowdnav: cannot place human " + std::to_string(human + 1) + " of " +
                           std::to_string(request.num_humans) + " in " + where + ": after " +
                           std::to_string(kMaxTries) + " tries no spot is " + Number(gap) +
                           " m from every start and goal placed so far. Fix: fewer humans, or " +
                           fix + " for " + std::to_string(request.num_humans) + " humans");
}

// generate_circle_crossing_human: angle, x noise, y noise; rejected when closer than
// r_h + r_A + discomfort_dist to any placed agent's position or goal; goal = -start. A group
// member draws its start near its leader's first (HumanPlacementOptions::group_spread).
void CircleHuman(double radius, const ScenarioRequest& request, int index,
                 const std::vector<Placed>& placed, const Vec2* leader, Rng& rng, Vec2* start,
                 Vec2* goal) {
  const HumanAttributes self = HumanAttributesOf(request, index);
  const double r_h = self.radius;
  const double v_pref = self.v_pref;
  const PointSampler near =
      leader ? DiscSampler(*leader, HumanPlacementOptions{}.group_spread) : PointSampler();
  for (int t = 0; t < kMaxTries; ++t) {
    Vec2 p;
    if (near && t < kMaxTries / 2) {
      p = near(rng);
    } else {
      const double angle = rng.Uniform() * 2.0 * std::numbers::pi;
      const double px_noise = (rng.Uniform() - 0.5) * v_pref;
      const double py_noise = (rng.Uniform() - 0.5) * v_pref;
      p = Vec2(radius * std::cos(angle) + px_noise, radius * std::sin(angle) + py_noise);
    }
    bool collide = false;
    for (const Placed& a : placed) {
      const double min_dist = r_h + a.radius + request.sim.discomfort_dist;
      if (NormBelow(p - a.position, min_dist) || NormBelow(p - a.goal, min_dist)) {
        collide = true;
        break;
      }
    }
    if (!collide) {
      *start = p;
      *goal = -p;
      return;
    }
  }
  Fail(index, request, true, radius);
}

// generate_square_crossing_human: side sign first, then the start (tested against placed
// positions only), then the goal on the other side (tested against placed goals only).
void SquareHuman(double width, const ScenarioRequest& request, int index,
                 const std::vector<Placed>& placed, const Placed* leader, Rng& rng, Vec2* start,
                 Vec2* goal) {
  const double r_h = HumanAttributesOf(request, index).radius;
  const double spread = HumanPlacementOptions{}.group_spread;
  const double sign = rng.Uniform() > 0.5 ? -1.0 : 1.0;
  auto clear = [&](const Vec2& p, bool against_goals) {
    for (const Placed& a : placed) {
      const double min_dist = r_h + a.radius + request.sim.discomfort_dist;
      if (NormBelow(p - (against_goals ? a.goal : a.position), min_dist)) return false;
    }
    return true;
  };
  bool ok = false;
  // A group member tries near its leader's start and goal for the first half of the tries.
  const PointSampler near_start = leader ? DiscSampler(leader->position, spread) : PointSampler();
  const PointSampler near_goal = leader ? DiscSampler(leader->goal, spread) : PointSampler();
  for (int t = 0; t < kMaxTries && !ok; ++t) {
    if (near_start && t < kMaxTries / 2) {
      *start = near_start(rng);
    } else {
      const double px = rng.Uniform() * width * 0.5 * sign;
      const double py = (rng.Uniform() - 0.5) * width;
      *start = Vec2(px, py);
    }
    ok = clear(*start, false);
  }
  if (!ok) Fail(index, request, false, width);
  ok = false;
  for (int t = 0; t < kMaxTries && !ok; ++t) {
    if (near_goal && t < kMaxTries / 2) {
      *goal = near_goal(rng);
    } else {
      const double gx = rng.Uniform() * width * 0.5 * -sign;
      const double gy = (rng.Uniform() - 0.5) * width;
      *goal = Vec2(gx, gy);
    }
    ok = clear(*goal, true);
  }
  if (!ok) Fail(index, request, false, width);
}

}  // namespace

ParamSchema Schema() {
  // One parameter per entry reads as a table.
  // clang-format off
  return {
      {"scenario", ParamType::kString, std::string("circle_crossing"), 0, 0,
       {"circle_crossing", "square_crossing"}, "CrowdNav's human generation rule"},
      {"circle_radius", ParamType::kDouble, kDefaultCircleRadius, 0.5, 100.0, {},
       "m; circle of the humans' starts, and the robot's start/goal distance from the centre"},
      {"square_width", ParamType::kDouble, kDefaultSquareWidth, 0.5, 200.0, {},
       "m; side of the square_crossing square"},
      {"new_goal_count", ParamType::kInt, std::int64_t{kDefaultNewGoalCount}, 1, 1000, {},
       "goals per human when the suite gives humans new goals (they cross back and forth)"},
  };
  // clang-format on
}

CrowdNavWorld::CrowdNavWorld(const Params& params)
    : crossing_(params.GetString("scenario") == "square_crossing" ? Crossing::kSquare
                                                                  : Crossing::kCircle),
      circle_radius_(params.GetDouble("circle_radius")),
      square_width_(params.GetDouble("square_width")),
      new_goal_count_(static_cast<int>(params.GetInt("new_goal_count"))) {
  identity_ = std::string("crowdnav:scenario=") +
              (crossing_ == Crossing::kCircle ? "circle_crossing" : "square_crossing");
  if (circle_radius_ != kDefaultCircleRadius)
    identity_ += ":circle_radius=" + Number(circle_radius_);
  if (crossing_ == Crossing::kSquare && square_width_ != kDefaultSquareWidth) {
    identity_ += ":square_width=" + Number(square_width_);
  }
  if (new_goal_count_ != kDefaultNewGoalCount) {
    identity_ += ":new_goal_count=" + std::to_string(new_goal_count_);
  }
  // No obstacles; bounds only need to hold everybody with room to swerve.
  const double half = 2.0 * std::max(circle_radius_, 0.5 * square_width_) + 5.0;
  auto map = std::make_shared<StaticMap>();
  map->name = "crowdnav_open";
  map->bounds = Rect::FromCorners(-half, -half, half, half);
  map_ = std::move(map);
}

Scenario CrowdNavWorld::Make(const ScenarioRequest& request) const {
  Scenario s;
  s.map = map_;
  s.seed = request.seed;
  s.layout = crossing_ == Crossing::kCircle ? "circle_crossing" : "square_crossing";
  s.robot_start = Vec2(0.0, -circle_radius_);
  s.robot_goal = Vec2(0.0, circle_radius_);

  Rng rng(request.seed);
  // Sized once: growing them human by human was most of the allocations of an episode.
  const auto num_humans = static_cast<std::size_t>(std::max(0, request.num_humans));
  std::vector<Placed> placed;
  placed.reserve(num_humans + 1);
  placed.push_back({s.robot_start, s.robot_goal, request.sim.robot_radius});
  s.humans.reserve(num_humans);
  const int goals = request.goal_mode == HumanGoalMode::kNewGoal ? new_goal_count_ : 1;
  for (int i = 0; i < request.num_humans; ++i) {
    Vec2 start, goal;
    // placed[0] is the robot: human k is placed[k + 1].
    const int leader = GroupLeaderOf(request, i);
    const Placed* lead = leader >= 0 ? &placed[static_cast<size_t>(leader) + 1] : nullptr;
    if (crossing_ == Crossing::kCircle) {
      CircleHuman(circle_radius_, request, i, placed, lead ? &lead->position : nullptr, rng, &start,
                  &goal);
    } else {
      SquareHuman(square_width_, request, i, placed, lead, rng, &start, &goal);
    }
    HumanSpec h;
    h.start = start;
    ApplyHumanAttributes(request, i, &h);
    placed.push_back({start, goal, h.radius});
    // New goals alternate between the far side and the start, drawing nothing more, so the
    // first goal (and everything CrowdNav does) stays identical in both goal modes.
    h.goals.reserve(static_cast<std::size_t>(goals));
    for (int k = 0; k < goals; ++k) h.goals.push_back(k % 2 == 0 ? goal : start);
    s.humans.push_back(std::move(h));
  }
  return s;
}

}  // namespace crowdsim::crowdnav
