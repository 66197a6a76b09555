#include "scene_layout.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace crowdsim::crowds {

namespace {

// The chord of `box` through `p` along `d` (unit): [lo, hi] in units of d, p inside the box.
std::pair<double, double> Chord(const Rect& box, const Vec2& p, const Vec2& d) {
  double lo = -kInfinity;
  double hi = kInfinity;
  for (int i = 0; i < 2; ++i) {
    if (std::abs(d[i]) < 1e-12) continue;
    const double a = (box.min[i] - p[i]) / d[i];
    const double b = (box.max[i] - p[i]) / d[i];
    lo = std::max(lo, std::min(a, b));
    hi = std::min(hi, std::max(a, b));
  }
  return {lo, hi};
}

}  // namespace

Rect TracksBox(const crowd_tracks::Tracks& tracks) {
  Rect box{Vec2::Constant(kInfinity), Vec2::Constant(-kInfinity)};
  for (const crowd_tracks::RecordedPerson& p : tracks.people) {
    for (const Vec2& x : p.positions) {
      box.min = box.min.cwiseMin(x);
      box.max = box.max.cwiseMax(x);
    }
  }
  return box;
}

std::shared_ptr<const StaticMap> SceneMap(const crowd_tracks::Tracks& tracks,
                                          const std::string& name) {
  const Rect box = TracksBox(tracks);
  const Vec2 lo = box.min - Vec2::Constant(kMargin);
  const Vec2 hi = box.max + Vec2::Constant(kMargin);
  const double w = kWallThickness;
  auto map = std::make_shared<StaticMap>();
  map->name = name;
  map->bounds = Rect{lo - Vec2::Constant(w), hi + Vec2::Constant(w)};
  // Bottom, top, left, right: the floor inside is the box plus the margin.
  map->rectangles = {Rect::FromCorners(lo.x() - w, lo.y() - w, hi.x() + w, lo.y()),
                     Rect::FromCorners(lo.x() - w, hi.y(), hi.x() + w, hi.y() + w),
                     Rect::FromCorners(lo.x() - w, lo.y(), lo.x(), hi.y()),
                     Rect::FromCorners(hi.x(), lo.y(), hi.x() + w, hi.y())};
  map->attribution = tracks.source + "; " + tracks.cite;
  return map;
}

Vec2 MainFlowAxis(const crowd_tracks::Tracks& tracks) {
  double c = 0.0;
  double s = 0.0;
  for (const crowd_tracks::RecordedPerson& p : tracks.people) {
    const Vec2 d = p.positions.back() - p.positions.front();
    const double length = d.norm();
    if (length <= 0.0) continue;
    const double angle = 2.0 * std::atan2(d.y(), d.x());
    c += length * std::cos(angle);
    s += length * std::sin(angle);
  }
  const double axis = 0.5 * std::atan2(s, c);
  return Vec2(std::cos(axis), std::sin(axis));
}

std::vector<double> SplitWindows(const crowd_tracks::Tracks& tracks, const std::string& split) {
  const int count = static_cast<int>(std::floor(tracks.duration() / kWindowSeconds));
  if (count < 2) {
    throw std::invalid_argument("the recording lasts " + std::to_string(tracks.duration()) +
                                " s: a train and a test window need at least " +
                                std::to_string(2 * kWindowSeconds) + " s");
  }
  const int test = std::clamp(static_cast<int>(std::lround(kTestShare * count)), 1, count - 1);
  const int first = split == "test" ? count - test : 0;
  const int end = split == "test" ? count : count - test;
  std::vector<double> starts;
  for (int k = first; k < end; ++k) starts.push_back(k * kWindowSeconds);
  return starts;
}

StartGoal CrossingPair(const Rect& box, const Vec2& axis, Rng& rng) {
  const Rect inner{box.min + Vec2::Constant(kRobotInset), box.max - Vec2::Constant(kRobotInset)};
  const Vec2 centre = inner.Center();
  const auto [along_lo, along_hi] = Chord(inner, centre, axis);
  const double spread = 0.5 * kCrossingSpread * (along_hi - along_lo);
  const Vec2 through = centre + rng.Uniform(-spread, spread) * axis;
  const Vec2 normal(-axis.y(), axis.x());
  const auto [lo, hi] = Chord(inner, through, normal);
  StartGoal pair{through + lo * normal, through + hi * normal};
  if (rng.Uniform() < 0.5) std::swap(pair.start, pair.goal);
  return pair;
}

}  // namespace crowdsim::crowds
