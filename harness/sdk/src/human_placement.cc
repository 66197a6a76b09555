#include "crowdsim/human_placement.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <utility>

namespace crowdsim {

// Margin (m) beyond a rectangle's grown box that stays clear in the exact test despite rounding.
constexpr double kReachSlack = 1e-9;

DiscFreeSpace::DiscFreeSpace(std::shared_ptr<const StaticMap> map, double clearance)
    : map_(std::move(map)), clearance_(clearance) {
  if (!map_) throw std::invalid_argument("DiscFreeSpace: map is null");
  if (!(clearance_ >= 0.0)) throw std::invalid_argument("DiscFreeSpace: clearance must be >= 0");
  inner_ = map_->bounds.Inflated(-clearance_);
  reach_.reserve(map_->rectangles.size());
  for (const Rect& r : map_->rectangles) reach_.push_back(r.Inflated(clearance_ + kReachSlack));
}

bool DiscFreeSpace::Contains(const Vec2& p) const {
  if (inner_.min.x() > inner_.max.x() || inner_.min.y() > inner_.max.y() || !inner_.Contains(p)) {
    return false;
  }
  // Four comparisons rule out the far rectangles; only near ones take the exact disc test.
  const std::vector<Rect>& rects = map_->rectangles;
  for (size_t i = 0; i < rects.size(); ++i) {
    if (reach_[i].Contains(p) && DiscOverlapsRect(p, clearance_, rects[i])) return false;
  }
  return true;
}

PointSampler UniformSampler(const Rect& region) {
  return [region](Rng& rng) {
    // x before y: the draw order is part of the reproducibility contract.
    const double x = rng.Uniform(region.min.x(), region.max.x());
    const double y = rng.Uniform(region.min.y(), region.max.y());
    return Vec2(x, y);
  };
}

PointSampler DiscSampler(const Vec2& centre, double radius) {
  return [centre, radius](Rng& rng) {
    // Rejection from the square: 79% of the draws land in the disc.
    for (;;) {
      const double x = rng.Uniform(-radius, radius);
      const double y = rng.Uniform(-radius, radius);
      if (x * x + y * y <= radius * radius) return Vec2(centre.x() + x, centre.y() + y);
    }
  };
}

PointSampler ListSampler(std::vector<Vec2> points) {
  if (points.empty()) throw std::invalid_argument("ListSampler: the list of points is empty");
  // Shared so that copies of the sampler do not copy a long list.
  auto shared = std::make_shared<const std::vector<Vec2>>(std::move(points));
  return [shared](Rng& rng) { return (*shared)[static_cast<size_t>(rng.Below(shared->size()))]; };
}

HumanPlacementOptions HumanPlacementOptions::FromRequest(const ScenarioRequest& request) {
  HumanPlacementOptions o;
  o.human_radius = request.sim.human_radius;
  o.human_v_pref = request.sim.human_v_pref;
  o.robot_radius = request.sim.robot_radius;
  o.discomfort_dist = request.sim.discomfort_dist;
  return o;
}

double PassableGoalClearance(double human_radius, double padding) {
  return (human_radius + padding) + 2.0 * (human_radius + padding);
}

namespace {

// A placed human's point and radius: gaps between people add both radii.
struct Disc {
  Vec2 centre;
  double radius = 0.0;
};

// One point to place: the discs it must keep clear of and the point its distance counts from.
struct PointRule {
  const std::vector<Disc>* others = nullptr;  // same-kind points of humans placed before
  double radius = 0.0;                        // the placed human's own radius
  double discomfort = 0.0;                    // centre gap to other k: radius + r_k + this
  Vec2 robot_point = Vec2::Zero();
  double robot_gap = 0.0;
  const Vec2* previous = nullptr;  // goal rule: the point walked from; null for starts
  double previous_min = 0.0;
  const std::function<bool(const Vec2&)>* stricter = nullptr;  // goals: room to pass
};

bool FarFromAll(const Vec2& p, const PointRule& rule) {
  // |p - q| >= gap, on squares where clearly apart; the square root only near the boundary.
  return std::all_of(rule.others->begin(), rule.others->end(), [&](const Disc& q) {
    const double gap = (rule.radius + q.radius) + rule.discomfort;
    const double gap_sq = gap * gap;
    const double d_sq = (p - q.centre).squaredNorm();
    if (d_sq > gap_sq * (1.0 + 1e-9)) return true;
    if (d_sq < gap_sq * (1.0 - 1e-9)) return false;
    return std::sqrt(d_sq) >= gap;
  });
}

// Required distance from the previous point at try t: full for half the tries, then linearly to 0
// for small rooms.
double RelaxedDistance(double full, int t, int max_tries) {
  const int half = max_tries / 2;
  if (t < half) return full;
  const double f = static_cast<double>(t - half) / static_cast<double>(max_tries - half);
  return full * (1.0 - f);
}

bool Draw(const PlacementArea& area, const PointSampler& sample, const PointRule& rule,
          int max_tries, Rng& rng, Vec2* out) {
  for (int t = 0; t < max_tries; ++t) {
    const Vec2 p = sample(rng);
    // The tests are pure, so order only sets cost: distances first (most rejections), free-space
    // predicates (every rectangle) last.
    if ((p - rule.robot_point).norm() < rule.robot_gap) continue;
    if (!FarFromAll(p, rule)) continue;
    if (rule.previous != nullptr &&
        (p - *rule.previous).norm() < RelaxedDistance(rule.previous_min, t, max_tries)) {
      continue;
    }
    if (!area.is_free(p)) continue;
    if (rule.stricter != nullptr && *rule.stricter && t < max_tries / 2 && !(*rule.stricter)(p)) {
      continue;
    }
    *out = p;
    return true;
  }
  return false;
}

// Free area (m^2) in `area.region`, from a 256 x 256 grid of centres; computed only on failure.
double FreeArea(const PlacementArea& area) {
  constexpr int kGrid = 256;
  const Rect& r = area.region;
  const Vec2 cell((r.max.x() - r.min.x()) / kGrid, (r.max.y() - r.min.y()) / kGrid);
  int free = 0;
  for (int i = 0; i < kGrid; ++i) {
    for (int j = 0; j < kGrid; ++j) {
      free += area.is_free(r.min + Vec2((i + 0.5) * cell.x(), (j + 0.5) * cell.y())) ? 1 : 0;
    }
  }
  return r.Area() * free / (kGrid * kGrid);
}

std::string Format(const char* format, double value) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), format, value);
  return buf;
}

[[noreturn]] void Fail(const std::string& what, int human, int num_humans,
                       const HumanPlacementOptions& o, const PlacementArea& area) {
  const double gap = 2.0 * o.human_radius + o.discomfort_dist;
  std::string message = "cannot place the " + what + " of human " + std::to_string(human + 1) +
                        " of " + std::to_string(num_humans) + " after " +
                        std::to_string(o.max_tries) + " tries";
  if (area.region.Area() > 0.0) {
    // Random discs jam at 54.7% coverage (random sequential adsorption); here discs have diameter
    // `gap`, and narrow spaces hold a little more.
    const double free_area = FreeArea(area);
    const double jammed = 0.547 / (std::numbers::pi * 0.25 * gap * gap);
    message +=
        " (and as many over the whole free space): " + std::to_string(num_humans) +
        " humans in about " + Format("%.0f", free_area) + " m^2 of free space is " +
        Format("%.2f", num_humans / std::max(free_area, 1e-9)) + " per m^2, and humans kept " +
        Format("%g", gap) + " m apart (starts from starts, goals from goals) jam at about " +
        Format("%.2f", jammed) +
        " per m^2 when placed at random on open floor. Fix: fewer humans (the row's humans.count), "
        "a smaller human_radius or discomfort_dist, or a larger world.";
  } else {
    message += ": the free space is too small or too crowded for discs of radius " +
               Format("%g", o.human_radius) + " m kept " + Format("%g", o.discomfort_dist) +
               " m apart. Fix: use fewer humans (the row's humans.count), smaller radii, or a "
               "larger world.";
  }
  throw PlacementError(message);
}

}  // namespace

std::vector<HumanSpec> PlaceHumans(const PlacementArea& area, const Vec2& robot_start,
                                   const Vec2& robot_goal, const ScenarioRequest& request,
                                   const HumanPlacementOptions& options, Rng& rng) {
  if (!area.is_free || !area.sample) {
    throw std::invalid_argument("PlaceHumans: the placement area needs is_free and sample");
  }
  if (request.num_humans < 0) throw std::invalid_argument("PlaceHumans: num_humans < 0");
  if (options.max_tries < 1 || options.new_goal_count < 1) {
    throw std::invalid_argument("PlaceHumans: max_tries and new_goal_count must be >= 1");
  }
  const int n = request.num_humans;
  const int goals_per_human =
      request.goal_mode == HumanGoalMode::kNewGoal ? options.new_goal_count : 1;
  const double d = options.discomfort_dist;

  // Points the sampler cannot place, and later ones of that kind, draw from the whole region.
  const PointSampler more = area.region.Area() > 0.0 ? UniformSampler(area.region) : PointSampler();
  std::vector<char> sampler_spent(static_cast<size_t>(goals_per_human) + 1, 0);  // starts, goals
  auto draw = [&](const PointRule& rule, int kind, const Vec2* near, Vec2* out) {
    // A group member first near its leader's point; where none fits, anywhere.
    if (near != nullptr &&
        Draw(area, DiscSampler(*near, options.group_spread), rule, options.max_tries, rng, out)) {
      return true;
    }
    char& spent = sampler_spent[static_cast<size_t>(kind)];
    if (!spent) {
      if (Draw(area, area.sample, rule, options.max_tries, rng, out)) return true;
      spent = 1;
    }
    return more && Draw(area, more, rule, options.max_tries, rng, out);
  };

  std::vector<Disc> starts;
  // goals_by_index[k]: the k-th goals of the humans placed so far (goal k meets goal k).
  std::vector<std::vector<Disc>> goals_by_index(static_cast<size_t>(goals_per_human));
  std::vector<HumanSpec> humans;
  humans.reserve(static_cast<size_t>(n));

  for (int i = 0; i < n; ++i) {
    HumanSpec h;
    h.radius = options.human_radius;
    h.v_pref = options.human_v_pref;
    if (!request.humans.empty()) ApplyHumanAttributes(request, i, &h);
    const int leader = request.humans.empty() ? -1 : GroupLeaderOf(request, i);
    const HumanSpec* lead = leader >= 0 ? &humans[static_cast<size_t>(leader)] : nullptr;
    const double robot_gap = h.radius + options.robot_radius + d;
    PointRule start_rule{&starts, h.radius, d, robot_start, robot_gap, nullptr, 0.0};
    if (!draw(start_rule, 0, lead ? &lead->start : nullptr, &h.start))
      Fail("start", i, n, options, area);

    Vec2 previous = h.start;
    for (int k = 0; k < goals_per_human; ++k) {
      PointRule goal_rule{&goals_by_index[static_cast<size_t>(k)],
                          h.radius,
                          d,
                          robot_goal,
                          robot_gap,
                          &previous,
                          options.goal_min_dist,
                          &area.is_goal_free};
      Vec2 goal;
      if (!draw(goal_rule, k + 1, lead ? &lead->goals[static_cast<size_t>(k)] : nullptr, &goal))
        Fail("goal " + std::to_string(k + 1), i, n, options, area);
      h.goals.push_back(goal);
      goals_by_index[static_cast<size_t>(k)].push_back({goal, h.radius});
      previous = goal;
    }
    starts.push_back({h.start, h.radius});
    humans.push_back(std::move(h));
  }
  return humans;
}

}  // namespace crowdsim
