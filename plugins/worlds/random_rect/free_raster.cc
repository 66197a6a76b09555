#include "free_raster.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace crowdsim::random_rect {

FreeRaster::FreeRaster(const StaticMap& map, const Rect& region, double clearance,
                       double resolution)
    : region_(region), resolution_(resolution) {
  if (!(resolution > 0.0)) throw std::invalid_argument("FreeRaster: resolution must be > 0");
  const Vec2 size = region.Size();
  cols_ = std::max(0, static_cast<int>(std::floor(size.x() / resolution + 1e-9)));
  rows_ = std::max(0, static_cast<int>(std::floor(size.y() / resolution + 1e-9)));
  free_.assign(static_cast<size_t>(rows_) * cols_, 0);
  const Rect inner = map.bounds.Inflated(-clearance);
  for (int r = 0; r < rows_; ++r) {
    for (int c = 0; c < cols_; ++c) free_[Index(r, c)] = inner.Contains(CellCentre(r, c)) ? 1 : 0;
  }
  // Each rectangle clears only the cells near it: far cheaper than testing every cell
  // against every rectangle, and the raster is built for every candidate layout.
  for (const Rect& rect : map.rectangles) {
    const Rect reach = rect.Inflated(clearance);
    // Cell index ranges covering `reach`, one cell wider on each side against rounding.
    auto lower = [&](double v, double origin) {
      return static_cast<int>(std::floor((v - origin) / resolution)) - 1;
    };
    auto upper = [&](double v, double origin) {
      return static_cast<int>(std::ceil((v - origin) / resolution));
    };
    const int c0 = std::max(0, lower(reach.min.x(), region.min.x()));
    const int c1 = std::min(cols_ - 1, upper(reach.max.x(), region.min.x()));
    const int r0 = std::max(0, lower(reach.min.y(), region.min.y()));
    const int r1 = std::min(rows_ - 1, upper(reach.max.y(), region.min.y()));
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) {
        if (free_[Index(r, c)] && DiscOverlapsRect(CellCentre(r, c), clearance, rect)) {
          free_[Index(r, c)] = 0;
        }
      }
    }
  }
  for (unsigned char f : free_) free_count_ += f;
}

Vec2 FreeRaster::CellCentre(int row, int col) const {
  return region_.min + Vec2((col + 0.5) * resolution_, (row + 0.5) * resolution_);
}

int FreeRaster::ComponentCount() const {
  std::vector<unsigned char> seen(free_.size(), 0);
  std::vector<std::pair<int, int>> stack;
  int components = 0;
  for (int r0 = 0; r0 < rows_; ++r0) {
    for (int c0 = 0; c0 < cols_; ++c0) {
      if (!Free(r0, c0) || seen[Index(r0, c0)]) continue;
      ++components;
      seen[Index(r0, c0)] = 1;
      stack.emplace_back(r0, c0);
      while (!stack.empty()) {
        const auto [r, c] = stack.back();
        stack.pop_back();
        const int nr[4] = {r - 1, r + 1, r, r};
        const int nc[4] = {c, c, c - 1, c + 1};
        for (int k = 0; k < 4; ++k) {
          if (nr[k] < 0 || nr[k] >= rows_ || nc[k] < 0 || nc[k] >= cols_) continue;
          if (!Free(nr[k], nc[k]) || seen[Index(nr[k], nc[k])]) continue;
          seen[Index(nr[k], nc[k])] = 1;
          stack.emplace_back(nr[k], nc[k]);
        }
      }
    }
  }
  return components;
}

bool FreeRaster::HasPairAtLeast(double distance, int stride) const {
  if (stride < 1) stride = 1;
  std::vector<Vec2> points;
  for (int r = 0; r < rows_; r += stride) {
    for (int c = 0; c < cols_; c += stride) {
      if (Free(r, c)) points.push_back(CellCentre(r, c));
    }
  }
  const double d2 = distance * distance;
  for (size_t i = 0; i < points.size(); ++i) {
    for (size_t j = i + 1; j < points.size(); ++j) {
      if ((points[i] - points[j]).squaredNorm() >= d2) return true;
    }
  }
  return false;
}

}  // namespace crowdsim::random_rect
