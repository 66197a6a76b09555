#include "crowdsim/agent_index.h"

#include <algorithm>
#include <cmath>

namespace crowdsim {

void AgentIndex::Rebuild(std::span<const AgentState> agents, double cell_size) {
  agents_ = agents;
  cell_ = cell_size;
  if (agents.empty()) {
    nx_ = ny_ = 0;
    cell_start_.assign(1, 0);
    order_.clear();
    return;
  }
  Vec2 lo = agents[0].position, hi = agents[0].position;
  for (const auto& a : agents) {
    lo = lo.cwiseMin(a.position);
    hi = hi.cwiseMax(a.position);
  }
  origin_ = lo;
  // Keep the grid small: at most ~4 cells per agent in each direction.
  const double extent = std::max(hi.x() - lo.x(), hi.y() - lo.y());
  const double max_cells = std::max(1.0, 2.0 * std::sqrt(static_cast<double>(agents.size())));
  cell_ = std::max(cell_size, extent / max_cells);
  nx_ = static_cast<int>((hi.x() - lo.x()) / cell_) + 1;
  ny_ = static_cast<int>((hi.y() - lo.y()) / cell_) + 1;
  const int cells = nx_ * ny_;
  cell_start_.assign(cells + 1, 0);
  std::vector<int> cell_of(agents.size());
  for (size_t i = 0; i < agents.size(); ++i) {
    const int cx = static_cast<int>((agents[i].position.x() - lo.x()) / cell_);
    const int cy = static_cast<int>((agents[i].position.y() - lo.y()) / cell_);
    cell_of[i] = cy * nx_ + cx;
    ++cell_start_[cell_of[i] + 1];
  }
  for (int c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  order_.assign(agents.size(), 0);
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (size_t i = 0; i < agents.size(); ++i) order_[fill[cell_of[i]]++] = static_cast<int>(i);
}

void AgentIndex::Nearest(const Vec2& p, double range, int max_count, int exclude,
                         std::vector<int>* out) const {
  out->clear();
  if (agents_.empty() || max_count <= 0) return;
  const double range_sq = range * range;
  struct Hit {
    double d2;
    int i;
  };
  // Nearest first, ties by index: a strict total order, so the k best are one exact set.
  const auto less = [](const Hit& a, const Hit& b) { return a.d2 < b.d2 || (a.d2 == b.d2 && a.i < b.i); };
  thread_local std::vector<Hit> best;  // the ring search keeps it a max-heap (worst on top)
  best.clear();
  const int x0 = std::max(0, static_cast<int>(std::floor((p.x() - range - origin_.x()) / cell_)));
  const int x1 = std::min(nx_ - 1, static_cast<int>(std::floor((p.x() + range - origin_.x()) / cell_)));
  const int y0 = std::max(0, static_cast<int>(std::floor((p.y() - range - origin_.y()) / cell_)));
  const int y1 = std::min(ny_ - 1, static_cast<int>(std::floor((p.y() + range - origin_.y()) / cell_)));
  if (x0 > x1 || y0 > y1) return;
  if (static_cast<int>(agents_.size()) <= max_count + 1 || (x1 - x0 + 1) * (y1 - y0 + 1) <= 9) {
    // Few agents or few cells (the paper's 5-human rooms): scan the box, sort what is in range.
    for (int cy = y0; cy <= y1; ++cy) {
      for (int c = cy * nx_ + x0; c <= cy * nx_ + x1; ++c) {
        for (int k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
          const int i = order_[k];
          const double d2 = (agents_[i].position - p).squaredNorm();
          if (i != exclude && d2 < range_sq) best.push_back({d2, i});
        }
      }
    }
    const std::size_t keep = std::min(best.size(), static_cast<std::size_t>(max_count));
    std::partial_sort(best.begin(), best.begin() + keep, best.end(), less);
    for (std::size_t k = 0; k < keep; ++k) out->push_back(best[k].i);
    return;
  }
  // The cell holding p (it may lie outside the grid), then rings of cells around it: ring r is
  // at least (r - 1) cells from p, so once the heap is full and its worst hit is nearer than
  // that, no farther ring can change the answer (RVO2's kd-tree stops the same way).
  const int pcx = static_cast<int>(std::floor((p.x() - origin_.x()) / cell_));
  const int pcy = static_cast<int>(std::floor((p.y() - origin_.y()) / cell_));
  const int last_ring = std::max({pcx - x0, x1 - pcx, pcy - y0, y1 - pcy});
  auto visit_cell = [&](int cx, int cy) {
    const int c = cy * nx_ + cx;
    for (int k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
      const int i = order_[k];
      if (i == exclude) continue;
      const double d2 = (agents_[i].position - p).squaredNorm();
      if (d2 >= range_sq) continue;
      const Hit h{d2, i};
      if (static_cast<int>(best.size()) < max_count) {
        best.push_back(h);
        std::push_heap(best.begin(), best.end(), less);
      } else if (less(h, best.front())) {
        std::pop_heap(best.begin(), best.end(), less);
        best.back() = h;
        std::push_heap(best.begin(), best.end(), less);
      }
    }
  };
  for (int r = std::max(0, std::max({x0 - pcx, pcx - x1, y0 - pcy, pcy - y1})); r <= last_ring; ++r) {
    if (r >= 1 && static_cast<int>(best.size()) == max_count) {
      const double gap = (r - 1) * cell_;
      if (gap * gap > best.front().d2) break;
    }
    const int ya = std::max(y0, pcy - r), yb = std::min(y1, pcy + r);
    const int xa = std::max(x0, pcx - r), xb = std::min(x1, pcx + r);
    for (int cy = ya; cy <= yb; ++cy) {
      if (cy == pcy - r || cy == pcy + r) {
        for (int cx = xa; cx <= xb; ++cx) visit_cell(cx, cy);  // the ring's top and bottom rows
      } else {
        if (pcx - r >= x0) visit_cell(pcx - r, cy);  // its left and right columns
        if (r > 0 && pcx + r <= x1) visit_cell(pcx + r, cy);
      }
    }
  }
  std::sort_heap(best.begin(), best.end(), less);
  for (const auto& h : best) out->push_back(h.i);
}

}  // namespace crowdsim
