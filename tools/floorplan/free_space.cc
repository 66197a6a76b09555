#include "free_space.h"

#include <cmath>
#include <functional>
#include <queue>
#include <set>
#include <tuple>

namespace crowdsim::floorplan {
namespace {

// A pair rounded to the world file's 4 decimals, for the disjointness check.
std::tuple<long, long, long, long> Key(const StartGoal& p) {
  auto q = [](double x) { return std::lround(x * 1e4); };
  return {q(p.start.x()), q(p.start.y()), q(p.goal.x()), q(p.goal.y())};
}

}  // namespace

FreeSpace::FreeSpace(const Grid& mask, const Grid& centres, const RasterFrame& frame,
                     std::vector<Rect> rectangles, double clearance)
    : mask_(mask),
      centres_(centres),
      frame_(frame),
      rectangles_(std::move(rectangles)),
      clearance_(clearance) {
  for (size_t i = 0; i < centres_.cells.size(); ++i) {
    if (centres_.cells[i]) candidates_.push_back(static_cast<int>(i));
  }
}

bool FreeSpace::CellOf(const Vec2& p, int* row, int* col) const {
  const Vec2 local = (p - frame_.origin) / frame_.cell_size;
  *col = static_cast<int>(std::floor(local.x()));
  *row = frame_.height - 1 - static_cast<int>(std::floor(local.y()));
  return mask_.Inside(*row, *col);
}

bool FreeSpace::IsFree(const Vec2& p) const {
  int row, col;
  CellOf(p, &row, &col);
  const int reach = static_cast<int>(std::ceil(clearance_ / frame_.cell_size)) + 1;
  for (int r = row - reach; r <= row + reach; ++r) {
    for (int c = col - reach; c <= col + reach; ++c) {
      if (mask_.At(r, c)) continue;
      if (PointToRectDistance(p, frame_.CellsToRect(r, c, r, c)) < clearance_) return false;
    }
  }
  for (const Rect& rect : rectangles_) {
    if (PointToRectDistance(p, rect) < clearance_) return false;
  }
  return true;
}

std::optional<Vec2> FreeSpace::Sample(Rng& rng, int max_tries) const {
  if (candidates_.empty()) return std::nullopt;
  for (int t = 0; t < max_tries; ++t) {
    const int i = candidates_[rng.Below(candidates_.size())];
    const int row = i / mask_.width, col = i % mask_.width;
    // x before y: the draw order is part of the reproducibility contract.
    const double dx = rng.Uniform(-0.5, 0.5);
    const double dy = rng.Uniform(-0.5, 0.5);
    // Snapped to the world file's 4 decimals, so the checked point is the stored one.
    const Vec2 q = frame_.CellCentre(row, col) + frame_.cell_size * Vec2(dx, dy);
    const Vec2 p(std::round(q.x() * 1e4) / 1e4, std::round(q.y() * 1e4) / 1e4);
    if (IsFree(p)) return p;
  }
  return std::nullopt;
}

std::vector<StartGoal> FreeSpace::SamplePairs(int count, double min_distance, Rng& rng,
                                              const std::vector<StartGoal>& exclude) const {
  std::set<std::tuple<long, long, long, long>> taken;
  for (const auto& p : exclude) taken.insert(Key(p));
  std::vector<StartGoal> out;
  // Generous but bounded: a plan where pairs this far apart are rare fails instead of looping.
  const long max_draws = 200L * count + 10000;
  for (long draw = 0; draw < max_draws && static_cast<int>(out.size()) < count; ++draw) {
    const auto start = Sample(rng);
    const auto goal = Sample(rng);
    if (!start || !goal) return {};
    if ((*goal - *start).norm() < min_distance) continue;
    const StartGoal pair{*start, *goal};
    if (!taken.insert(Key(pair)).second) continue;
    out.push_back(pair);
  }
  if (static_cast<int>(out.size()) < count) return {};
  return out;
}

double FreeSpace::GeodesicDistance(const Vec2& a, const Vec2& b) const {
  int ar, ac, br, bc;
  CellOf(a, &ar, &ac);
  CellOf(b, &br, &bc);
  const int w = centres_.width;
  // A jittered sample can sit on the edge of its centre cell: snap to a neighbouring centre.
  auto snap = [&](int* r, int* c) {
    for (int k = 0; k < 9; ++k) {
      const int nr = *r + k / 3 - 1, nc = *c + k % 3 - 1;
      if (centres_.At(nr, nc)) {
        *r = nr, *c = nc;
        return true;
      }
    }
    return false;
  };
  if (!centres_.At(ar, ac) && !snap(&ar, &ac)) return kInfinity;
  if (!centres_.At(br, bc) && !snap(&br, &bc)) return kInfinity;
  const size_t src = centres_.Index(ar, ac), dst = centres_.Index(br, bc);
  std::vector<double> dist(centres_.cells.size(), kInfinity);
  using Item = std::pair<double, size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> open;
  dist[src] = 0.0;
  open.push({0.0, src});
  static const int kDr[8] = {1, -1, 0, 0, 1, 1, -1, -1};
  static const int kDc[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > dist[i]) continue;
    if (i == dst) return d * frame_.cell_size;
    const int r = static_cast<int>(i / w), c = static_cast<int>(i % w);
    for (int k = 0; k < 8; ++k) {
      const int nr = r + kDr[k], nc = c + kDc[k];
      if (!centres_.At(nr, nc)) continue;
      if (k >= 4 && (!centres_.At(r, nc) || !centres_.At(nr, c))) continue;
      const double nd = d + (k >= 4 ? M_SQRT2 : 1.0);
      const size_t j = centres_.Index(nr, nc);
      if (nd < dist[j]) {
        dist[j] = nd;
        open.push({nd, j});
      }
    }
  }
  return kInfinity;
}

}  // namespace crowdsim::floorplan
