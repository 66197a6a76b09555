#include "orca/rect_index.h"

#include <algorithm>
#include <cmath>

namespace crowdsim::orca {
namespace {

// Closed boxes touch when they overlap or share a side or a corner.
bool Touches(const Rect& a, const Rect& b) {
  return a.min.x() <= b.max.x() && b.min.x() <= a.max.x() && a.min.y() <= b.max.y() &&
         b.min.y() <= a.max.y();
}

}  // namespace

RectIndex::RectIndex(std::span<const Rect> boxes) : boxes_(boxes.begin(), boxes.end()) {
  if (boxes_.empty()) return;
  Vec2 lo = boxes_[0].min, hi = boxes_[0].max;
  for (const Rect& b : boxes_) {
    lo = lo.cwiseMin(b.min.cwiseMin(b.max));
    hi = hi.cwiseMax(b.min.cwiseMax(b.max));
  }
  origin_ = lo;
  // About one cell per box, square cells.
  const double extent = std::max({hi.x() - lo.x(), hi.y() - lo.y(), 1e-9});
  const double per_side = std::ceil(std::sqrt(static_cast<double>(boxes_.size())));
  cell_ = extent / per_side;
  nx_ = std::max(1, static_cast<int>((hi.x() - lo.x()) / cell_) + 1);
  ny_ = std::max(1, static_cast<int>((hi.y() - lo.y()) / cell_) + 1);
  cell_start_.assign(static_cast<std::size_t>(nx_) * ny_ + 1, 0);
  // The cells of a box's extent (corners in either order: the scan's test also keeps an
  // inverted box that straddles the query).
  const auto for_cells = [&](const Rect& b, auto&& f) {
    const Vec2 b_lo = b.min.cwiseMin(b.max), b_hi = b.min.cwiseMax(b.max);
    for (int cy = CellY(b_lo.y()); cy <= CellY(b_hi.y()); ++cy) {
      for (int cx = CellX(b_lo.x()); cx <= CellX(b_hi.x()); ++cx) f(cy * nx_ + cx);
    }
  };
  first_cell_.reserve(boxes_.size());
  for (const Rect& b : boxes_) {
    first_cell_.push_back(
        {CellX(std::min(b.min.x(), b.max.x())), CellY(std::min(b.min.y(), b.max.y()))});
  }
  for (const Rect& b : boxes_) for_cells(b, [&](int c) { ++cell_start_[c + 1]; });
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  items_.resize(cell_start_.back());
  std::vector<int> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (int i = 0; i < static_cast<int>(boxes_.size()); ++i) {
    for_cells(boxes_[i], [&](int c) { items_[fill[c]++] = i; });
  }
}

// floor((x - origin) / cell) clamped to the grid: monotonic in x, so a box and a query that
// touch always share a cell, whatever the rounding.
int RectIndex::CellX(double x) const {
  const double c = std::floor((x - origin_.x()) / cell_);
  return c >= 0.0 ? static_cast<int>(std::min(c, static_cast<double>(nx_ - 1))) : 0;
}
int RectIndex::CellY(double y) const {
  const double c = std::floor((y - origin_.y()) / cell_);
  return c >= 0.0 ? static_cast<int>(std::min(c, static_cast<double>(ny_ - 1))) : 0;
}

void RectIndex::Query(const Rect& query, std::vector<int>* out) const {
  out->clear();
  if (boxes_.empty() || !(query.min.x() <= query.max.x() && query.min.y() <= query.max.y())) {
    return;
  }
  const int qx0 = CellX(query.min.x()), qx1 = CellX(query.max.x());
  const int qy0 = CellY(query.min.y()), qy1 = CellY(query.max.y());
  for (int cy = qy0; cy <= qy1; ++cy) {
    for (int cx = qx0; cx <= qx1; ++cx) {
      const int c = cy * nx_ + cx;
      for (int k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
        const int i = items_[k];
        // A box spanning several cells is reported from one of them only: the first cell of
        // its overlap with the query.
        const auto [bx, by] = first_cell_[i];
        if (cx != std::max(qx0, bx) || cy != std::max(qy0, by)) continue;
        if (Touches(boxes_[i], query)) out->push_back(i);
      }
    }
  }
  std::sort(out->begin(), out->end());
}

}  // namespace crowdsim::orca
