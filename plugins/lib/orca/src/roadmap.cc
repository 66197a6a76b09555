#include "orca/roadmap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <list>
#include <mutex>
#include <queue>

#include "orca/geometry.h"

namespace crowdsim::orca {
namespace {

// Slack on clearance tests, so that nodes exactly at `clearance` from a wall stay usable.
constexpr double kClearanceSlack = 1e-9;

}  // namespace

Roadmap::Roadmap(std::span<const Rect> rects, const Rect& bounds, double clearance, double margin)
    : rects_(rects.begin(), rects.end()),
      index_(rects_),
      bounds_(bounds),
      clearance_(clearance),
      margin_(margin) {
  const bool bounded = bounds.Area() > 0.0;
  for (const Rect& r : rects_) {
    const Rect grown = r.Inflated(clearance + margin);
    const std::array<Vec2, 4> corners = {grown.min, Vec2(grown.max.x(), grown.min.y()), grown.max,
                                         Vec2(grown.min.x(), grown.max.y())};
    for (const Vec2& c : corners) {
      if (bounded && !bounds.Contains(c)) continue;
      // Corners that fall next to another rectangle (touching or close rectangles) are
      // not places a disc can stand on.
      if (CappedClearance(c) < clearance - kClearanceSlack) continue;
      nodes_.push_back(c);
    }
  }

  const int n = static_cast<int>(nodes_.size());
  std::vector<std::vector<Edge>> adjacency(n);
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (!SegmentClear(rects_, nodes_[i], nodes_[j], clearance - kClearanceSlack)) continue;
      const double length = (nodes_[j] - nodes_[i]).norm();
      adjacency[i].push_back({j, length});
      adjacency[j].push_back({i, length});
    }
  }
  edge_start_.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) {
    edge_start_[i + 1] = edge_start_[i] + static_cast<int>(adjacency[i].size());
  }
  edges_.reserve(edge_start_[n]);
  for (const auto& list : adjacency) edges_.insert(edges_.end(), list.begin(), list.end());
}

double Roadmap::CappedClearance(const Vec2& p) const {
  thread_local std::vector<int> near;
  // Padded well beyond rounding: a rectangle outside the box is farther than clearance_.
  const double pad = 1e-9 * (1.0 + std::abs(p.x()) + std::abs(p.y()) + clearance_);
  index_.Query(Rect{p, p}.Inflated(clearance_ + pad), &near);
  double best_sq = kInfinity;
  for (int i : near) best_sq = std::min(best_sq, RectDistanceSq(rects_[i], p));
  return std::min(clearance_, std::sqrt(best_sq));
}

bool Roadmap::Visible(const Vec2& a, const Vec2& b) const {
  return Visible(a, CappedClearance(a), b, CappedClearance(b));
}

bool Roadmap::Visible(const Vec2& a, double a_clearance, const Vec2& b, double b_clearance) const {
  int no_hint = -1;
  return Visible(a, a_clearance, b, b_clearance, &no_hint);
}

bool Roadmap::Visible(const Vec2& a, double a_clearance, const Vec2& b, double b_clearance,
                      int* blocker) const {
  const double c = std::min({clearance_, a_clearance, b_clearance});
  return SegmentClear(rects_, a, b, std::max(0.0, c - kClearanceSlack), blocker);
}

std::vector<Vec2> Roadmap::ShortestPath(const Vec2& start, const Vec2& goal) const {
  if (Visible(start, goal)) return {goal};
  const int n = static_cast<int>(nodes_.size());
  const int kStart = n;
  const int kGoal = n + 1;
  // The start and goal join the graph through the nodes they see; the clearance asked of
  // those segments is capped by their own (an agent may stand closer to a wall than a node).
  const double c_start = std::max(0.0, CappedClearance(start) - kClearanceSlack);
  const double c_goal = std::max(0.0, CappedClearance(goal) - kClearanceSlack);
  std::vector<char> seen_from_start(n, 0);
  int blocker = -1;
  for (int i = 0; i < n; ++i) {
    seen_from_start[i] = SegmentClear(rects_, start, nodes_[i], c_start, &blocker);
  }
  // Whether node i sees the goal matters only once the search expands node i: asked then (the
  // search stops at the goal, long before it has expanded every node). -1: not asked yet.
  std::vector<signed char> sees_goal(n, -1);
  auto node_sees_goal = [&](int i) {
    if (sees_goal[i] < 0) sees_goal[i] = SegmentClear(rects_, nodes_[i], goal, c_goal) ? 1 : 0;
    return sees_goal[i] == 1;
  };

  // A* with the straight-line heuristic.
  std::vector<double> cost(n + 2, kInfinity);
  std::vector<int> parent(n + 2, -1);
  using Item = std::pair<double, int>;  // (cost + heuristic, node)
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  auto point = [&](int i) -> const Vec2& {
    return i == kStart ? start : (i == kGoal ? goal : nodes_[i]);
  };
  auto relax = [&](int from, int to, double length) {
    const double c = cost[from] + length;
    if (c < cost[to]) {
      cost[to] = c;
      parent[to] = from;
      open.push({c + (goal - point(to)).norm(), to});
    }
  };
  cost[kStart] = 0.0;
  open.push({(goal - start).norm(), kStart});
  while (!open.empty()) {
    const auto [f, i] = open.top();
    open.pop();
    if (i == kGoal) break;
    if (f > cost[i] + (goal - point(i)).norm() + 1e-12) continue;  // stale entry
    if (i == kStart) {
      for (int j = 0; j < n; ++j) {
        if (seen_from_start[j]) relax(i, j, (nodes_[j] - start).norm());
      }
      continue;
    }
    for (int e = edge_start_[i]; e < edge_start_[i + 1]; ++e)
      relax(i, edges_[e].to, edges_[e].length);
    if (node_sees_goal(i)) relax(i, kGoal, (goal - nodes_[i]).norm());
  }
  if (parent[kGoal] < 0) return {};

  std::vector<Vec2> path;
  for (int i = kGoal; i != kStart; i = parent[i]) path.push_back(point(i));
  std::reverse(path.begin(), path.end());
  return path;
}

std::shared_ptr<const Roadmap> SharedRoadmap(const StaticMap& map, double clearance,
                                             double margin) {
  // A few recent roadmaps, most recent first: a suite replays a handful of maps (or one new
  // map per episode, which every agent of the episode then shares).
  constexpr std::size_t kCapacity = 16;
  static std::mutex mutex;
  static std::list<std::shared_ptr<const Roadmap>> cache;
  auto matches = [&](const Roadmap& r) {
    return r.clearance() == clearance && r.margin() == margin && r.bounds() == map.bounds &&
           r.rects() == map.rectangles;
  };
  {
    std::lock_guard<std::mutex> lock(mutex);
    for (auto it = cache.begin(); it != cache.end(); ++it) {
      if (matches(**it)) {
        cache.splice(cache.begin(), cache, it);
        return cache.front();
      }
    }
  }
  // Built outside the lock: other threads keep working on their own maps meanwhile.
  auto built = std::make_shared<const Roadmap>(map.rectangles, map.bounds, clearance, margin);
  std::lock_guard<std::mutex> lock(mutex);
  cache.push_front(built);
  if (cache.size() > kCapacity) cache.pop_back();
  return built;
}

}  // namespace crowdsim::orca
