#include "crowdsim/route_field.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace crowdsim {
// The 16 moves of the grid: 4 straight, 4 diagonal, 8 knight's moves (16 directions keep a
// grid path within 2.7% of the straight length; 8 directions: 8.2%). A move needs only its
// end cell free, not the cells its segment crosses: the distance to a convex obstacle along a
// segment between two points farther than the clearance c from it is at least
// sqrt(c^2 - L^2 / 4) (L the segment's length), so a knight's move of 0.1 m cells keeps
// 0.332 m of the default 0.35 and stays clear of a 0.3 m robot. Demanding the crossed cells
// free too closed diagonal passages a robot fits through (a third of the medium floor plan's
// test trips started in pockets such a rule sealed off).
struct RouteField::Move {
  int dr, dc;
  double length;  // in cells
};

namespace {

const double kDiagonal = std::sqrt(2.0), kKnight = std::sqrt(5.0);
const RouteField::Move kMoves[16] = {
    {0, 1, 1.0},       {1, 0, 1.0},        {0, -1, 1.0},        {-1, 0, 1.0},
    {1, 1, kDiagonal}, {1, -1, kDiagonal}, {-1, -1, kDiagonal}, {-1, 1, kDiagonal},
    {1, 2, kKnight},   {2, 1, kKnight},    {-1, 2, kKnight},    {-2, 1, kKnight},
    {1, -2, kKnight},  {2, -1, kKnight},   {-1, -2, kKnight},   {-2, -1, kKnight},
};

double RectDistanceSquared(const Rect& r, const Vec2& p) {
  const double dx = std::max({r.min.x() - p.x(), 0.0, p.x() - r.max.x()});
  const double dy = std::max({r.min.y() - p.y(), 0.0, p.y() - r.max.y()});
  return dx * dx + dy * dy;
}

}  // namespace

RouteField::RouteField(const StaticMap& map, const Vec2& goal, double clearance, double resolution)
    : origin_(map.bounds.min),
      goal_(goal),
      resolution_(resolution),
      band_(clearance + resolution),
      search_cells_(static_cast<int>(std::ceil(clearance / resolution)) + 1) {
  const Vec2 size = map.bounds.Size();
  cols_ = std::max(1, static_cast<int>(std::ceil(size.x() / resolution)));
  rows_ = std::max(1, static_cast<int>(std::ceil(size.y() / resolution)));
  free_.assign(static_cast<size_t>(rows_) * cols_, 1);
  value_.assign(free_.size(), kInfinity);

  // Cells whose centre lies closer than `clearance` to a rectangle are blocked.
  const double c2 = clearance * clearance;
  for (const Rect& r : map.rectangles) {
    const int c0 = std::max(
        0, static_cast<int>(std::ceil((r.min.x() - clearance - origin_.x()) / resolution - 0.5)));
    const int c1 = std::min(
        cols_ - 1,
        static_cast<int>(std::floor((r.max.x() + clearance - origin_.x()) / resolution - 0.5)));
    const int r0 = std::max(
        0, static_cast<int>(std::ceil((r.min.y() - clearance - origin_.y()) / resolution - 0.5)));
    const int r1 = std::min(
        rows_ - 1,
        static_cast<int>(std::floor((r.max.y() + clearance - origin_.y()) / resolution - 0.5)));
    for (int row = r0; row <= r1; ++row) {
      for (int col = c0; col <= c1; ++col) {
        if (RectDistanceSquared(r, Centre(row, col)) < c2) free_[Index(row, col)] = 0;
      }
    }
  }

  // Seeds: the free cells next to the goal (or, for a goal closer to a wall than the
  // clearance, those within the clearance band), at their straight distance.
  // Dijkstra over buckets of half a cell: a move is at least a cell long, so a cell's
  // expansion only reaches buckets two or more ahead, and a bucket's cells are final when it
  // is reached. Every order of expansion that sees final values gives these same values:
  // each cell's is the least over its neighbours of (neighbour + move), in the same sums.
  const double bucket_width = 0.5 * resolution;
  std::vector<std::vector<std::pair<double, int>>> buckets;
  const auto push = [&](double d, int i) {
    const size_t b = static_cast<size_t>(d / bucket_width);
    if (b >= buckets.size()) buckets.resize(b + 1);
    buckets[b].emplace_back(d, i);
  };
  for (const double reach : {1.5 * resolution, clearance + 1.5 * resolution}) {
    const int k = static_cast<int>(std::ceil(reach / resolution)) + 1;
    const int gr = static_cast<int>(std::floor((goal.y() - origin_.y()) / resolution));
    const int gc = static_cast<int>(std::floor((goal.x() - origin_.x()) / resolution));
    bool seeded = false;
    for (int row = std::max(0, gr - k); row <= std::min(rows_ - 1, gr + k); ++row) {
      for (int col = std::max(0, gc - k); col <= std::min(cols_ - 1, gc + k); ++col) {
        const double d = (Centre(row, col) - goal).norm();
        if (!Free(row, col) || d > reach) continue;
        value_[Index(row, col)] = d;
        push(d, Index(row, col));
        seeded = true;
      }
    }
    if (seeded) break;
  }

  // Each move's length (m) and index offset; cells two or more from the edge reach all 16.
  double step[16];
  int offset[16];
  for (int m = 0; m < 16; ++m) {
    step[m] = kMoves[m].length * resolution;
    offset[m] = kMoves[m].dr * cols_ + kMoves[m].dc;
  }
  for (size_t b = 0; b < buckets.size(); ++b) {
    // By index: pushes (to later buckets) may move the bucket vectors.
    for (size_t k = 0; k < buckets[b].size(); ++k) {
      const auto [d, i] = buckets[b][k];
      if (d > value_[i]) continue;  // lowered since, and expanded then
      const int row = i / cols_, col = i % cols_;
      const bool inside = row >= 2 && row < rows_ - 2 && col >= 2 && col < cols_ - 2;
      for (int m = 0; m < 16; ++m) {
        if (inside ? free_[i + offset[m]] == 0 : !CanMove(row, col, kMoves[m])) continue;
        const double nd = d + step[m];
        const int j = i + offset[m];
        if (nd < value_[j]) {
          value_[j] = nd;
          push(nd, j);
        }
      }
    }
    std::vector<std::pair<double, int>>().swap(buckets[b]);
  }
}

Vec2 RouteField::Centre(int row, int col) const {
  return origin_ + Vec2((col + 0.5) * resolution_, (row + 0.5) * resolution_);
}

bool RouteField::CanMove(int row, int col, const Move& m) const {
  return Free(row + m.dr, col + m.dc);
}

bool RouteField::Free(int row, int col) const {
  return row >= 0 && row < rows_ && col >= 0 && col < cols_ && free_[Index(row, col)] != 0;
}

int RouteField::EntryCell(const Vec2& p, double* through) const {
  const int pr = static_cast<int>(std::floor((p.y() - origin_.y()) / resolution_));
  const int pc = static_cast<int>(std::floor((p.x() - origin_.x()) / resolution_));
  const int k = search_cells_;
  int best = -1;
  *through = kInfinity;
  for (int row = std::max(0, pr - k); row <= std::min(rows_ - 1, pr + k); ++row) {
    for (int col = std::max(0, pc - k); col <= std::min(cols_ - 1, pc + k); ++col) {
      const int i = Index(row, col);
      if (value_[i] == kInfinity) continue;
      const double d = value_[i] + (Centre(row, col) - p).norm();
      if (d < *through) {
        *through = d;
        best = i;
      }
    }
  }
  return best;
}

int RouteField::Downhill(int i, double* length) const {
  const int row = i / cols_, col = i % cols_;
  int next = -1;
  double best = value_[i];
  for (const RouteField::Move& m : kMoves) {
    if (!CanMove(row, col, m)) continue;
    const int j = Index(row + m.dr, col + m.dc);
    if (value_[j] >= best) continue;
    best = value_[j];
    next = j;
    *length = m.length * resolution_;
  }
  return next;
}

bool RouteField::Sees(const Vec2& p, const Vec2& q) const {
  const double length = (q - p).norm();
  const int samples = static_cast<int>(std::ceil(length / (0.5 * resolution_)));
  // Blocked cells may open and close the segment (p or q inside the clearance band, as a robot
  // or a goal near a wall is), but only the band's width: a longer blocked stretch from p is
  // the wall p stands beside, seen through; a blocked stretch between free ones is a wall in
  // between.
  bool seen_free = false;
  double blocked_from = -1.0;  // where the blocked stretch after a free cell began; -1: none
  for (int k = 0; k <= samples; ++k) {
    const double along = samples == 0 ? length : length * k / samples;
    const Vec2 s = samples == 0 ? q : p + (q - p) * (along / length);
    const int row = static_cast<int>(std::floor((s.y() - origin_.y()) / resolution_));
    const int col = static_cast<int>(std::floor((s.x() - origin_.x()) / resolution_));
    if (!Free(row, col)) {
      if (!seen_free && along > band_) return false;
      if (seen_free && blocked_from < 0.0) blocked_from = along;
    } else if (blocked_from >= 0.0) {
      return false;
    } else {
      seen_free = true;
    }
  }
  return seen_free && (blocked_from < 0.0 || length - blocked_from <= band_);
}

RouteField::Reading RouteField::At(const Vec2& p, double lookahead) const {
  double through = kInfinity;
  int cell = EntryCell(p, &through);
  if (cell < 0) return Reading{kInfinity, p};
  // The farthest point of the path that p sees: the goal when it is in sight, else the last
  // path cell in sight within the horizon (the first cell always counts: p is next to it).
  Vec2 seen = Centre(cell / cols_, cell % cols_);
  double seen_value = value_[cell];
  if (Sees(p, goal_)) {
    seen = goal_;
    seen_value = 0.0;
  } else {
    double travelled = 0.0;
    while (travelled < kPullHorizon) {
      double step = 0.0;
      const int next = Downhill(cell, &step);
      if (next < 0) break;  // next to the goal, which p does not see
      travelled += step;
      cell = next;
      const Vec2 c = Centre(cell / cols_, cell % cols_);
      if (!Sees(p, c)) break;
      seen = c;
      seen_value = value_[cell];
    }
  }
  const double gap = (seen - p).norm();
  Reading r;
  r.distance = gap + seen_value;
  r.waypoint = gap <= lookahead ? seen : p + (seen - p) * (lookahead / gap);
  return r;
}

}  // namespace crowdsim
