#include "rect_decomposition.h"

#include <vector>

namespace crowdsim::floorplan {
namespace {

struct RowBest {
  long area = 0;
  int col0 = 0;
  int col1 = 0;
  int height = 0;
};

// Largest rectangle under the histogram `h` (first one on ties), with a monotone stack.
RowBest BestInHistogram(const int* h, int n, std::vector<int>& stack) {
  RowBest best;
  stack.clear();
  for (int c = 0; c <= n; ++c) {
    const int cur = c < n ? h[c] : 0;
    while (!stack.empty() && h[stack.back()] >= cur) {
      const int top = stack.back();
      stack.pop_back();
      const int left = stack.empty() ? 0 : stack.back() + 1;
      const long area = long(h[top]) * (c - left);
      // Strictly larger keeps the earliest rectangle; among equal areas prefer the leftmost.
      if (area > best.area || (area == best.area && area > 0 && left < best.col0)) {
        best = {area, left, c - 1, h[top]};
      }
    }
    if (c < n) stack.push_back(c);
  }
  return best;
}

}  // namespace

std::vector<CellRect> DecomposeBlocked(const Grid& g, long max_rectangles) {
  const int w = g.width, h = g.height;
  std::vector<CellRect> out;
  if (w == 0 || h == 0) return out;
  // open[i] = 1 for blocked cells not covered yet; heights[i] = run of open cells ending at i.
  std::vector<unsigned char> open(g.cells.size());
  for (size_t i = 0; i < open.size(); ++i) open[i] = g.cells[i] ? 0 : 1;
  std::vector<int> heights(g.cells.size(), 0);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      const size_t i = g.Index(r, c);
      heights[i] = open[i] ? (r > 0 ? heights[i - w] : 0) + 1 : 0;
    }
  }
  std::vector<int> stack;
  stack.reserve(w + 1);
  std::vector<RowBest> best(h);
  for (int r = 0; r < h; ++r) best[r] = BestInHistogram(&heights[g.Index(r, 0)], w, stack);

  while (max_rectangles < 0 || static_cast<long>(out.size()) < max_rectangles) {
    int row = -1;
    for (int r = 0; r < h; ++r) {
      if (best[r].area > 0 && (row < 0 || best[r].area > best[row].area)) row = r;
    }
    if (row < 0) break;
    const RowBest b = best[row];
    const CellRect rect{row - b.height + 1, b.col0, row, b.col1};
    out.push_back(rect);
    for (int r = rect.row0; r <= rect.row1; ++r) {
      for (int c = rect.col0; c <= rect.col1; ++c) open[g.Index(r, c)] = 0;
    }
    // Heights change from row0 down to where each column's run of open cells ends.
    int last_changed = rect.row1;
    for (int c = rect.col0; c <= rect.col1; ++c) {
      for (int r = rect.row0; r < h; ++r) {
        const size_t i = g.Index(r, c);
        const int nh = open[i] ? (r > 0 ? heights[i - w] : 0) + 1 : 0;
        if (nh == heights[i] && r > rect.row1) break;
        heights[i] = nh;
        if (r > last_changed) last_changed = r;
      }
    }
    for (int r = rect.row0; r <= last_changed; ++r) {
      best[r] = BestInHistogram(&heights[g.Index(r, 0)], w, stack);
    }
  }
  return out;
}

int RectanglesForCoverage(const std::vector<CellRect>& rects, long total, double share) {
  if (total <= 0) return 0;
  long covered = 0;
  for (size_t k = 0; k < rects.size(); ++k) {
    covered += rects[k].Area();
    if (static_cast<double>(covered) >= share * static_cast<double>(total) - 1e-9) {
      return static_cast<int>(k + 1);
    }
  }
  return static_cast<int>(rects.size());
}

}  // namespace crowdsim::floorplan
