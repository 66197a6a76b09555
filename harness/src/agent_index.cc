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
  thread_local std::vector<Hit> hits;
  hits.clear();
  const int x0 = std::max(0, static_cast<int>(std::floor((p.x() - range - origin_.x()) / cell_)));
  const int x1 = std::min(nx_ - 1, static_cast<int>(std::floor((p.x() + range - origin_.x()) / cell_)));
  const int y0 = std::max(0, static_cast<int>(std::floor((p.y() - range - origin_.y()) / cell_)));
  const int y1 = std::min(ny_ - 1, static_cast<int>(std::floor((p.y() + range - origin_.y()) / cell_)));
  for (int cy = y0; cy <= y1; ++cy) {
    for (int cx = x0; cx <= x1; ++cx) {
      const int c = cy * nx_ + cx;
      for (int k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
        const int i = order_[k];
        if (i == exclude) continue;
        const double d2 = (agents_[i].position - p).squaredNorm();
        if (d2 < range_sq) hits.push_back({d2, i});
      }
    }
  }
  const auto less = [](const Hit& a, const Hit& b) { return a.d2 < b.d2 || (a.d2 == b.d2 && a.i < b.i); };
  if (static_cast<int>(hits.size()) > max_count) {
    std::partial_sort(hits.begin(), hits.begin() + max_count, hits.end(), less);
    hits.resize(max_count);
  } else {
    std::sort(hits.begin(), hits.end(), less);
  }
  for (const auto& h : hits) out->push_back(h.i);
}

}  // namespace crowdsim
