#include "morphology.h"

#include <algorithm>
#include <limits>

namespace crowdsim::floorplan {
namespace {

// Separable square filter: a cell becomes `hit` when any cell within `radius` (Chebyshev) has
// value `hit`. Running counts make it O(cells) whatever the radius. Outside the image is
// `outside`.
Grid SquareAny(const Grid& g, int radius, std::uint8_t hit, std::uint8_t outside) {
  if (radius <= 0) return g;
  const std::uint8_t miss = hit ? 0 : 1;
  Grid tmp(g.width, g.height, miss);
  for (int r = 0; r < g.height; ++r) {
    int count = 0;  // hits in the window [c - radius, c + radius]
    auto value = [&](int c) { return c < 0 || c >= g.width ? outside : g.cells[g.Index(r, c)]; };
    for (int c = -radius; c <= radius; ++c) count += value(c) == hit;
    for (int c = 0; c < g.width; ++c) {
      tmp(r, c) = count > 0 ? hit : miss;
      count += (value(c + radius + 1) == hit) - (value(c - radius) == hit);
    }
  }
  Grid out(g.width, g.height, miss);
  for (int c = 0; c < g.width; ++c) {
    int count = 0;
    auto value = [&](int r) {
      return r < 0 || r >= g.height ? outside : tmp.cells[tmp.Index(r, c)];
    };
    for (int r = -radius; r <= radius; ++r) count += value(r) == hit;
    for (int r = 0; r < g.height; ++r) {
      out(r, c) = count > 0 ? hit : miss;
      count += (value(r + radius + 1) == hit) - (value(r - radius) == hit);
    }
  }
  return out;
}

// 1D squared distance transform of f (Felzenszwalb and Huttenlocher, lower envelope of
// parabolas); huge values mark "no site".
void Edt1d(const std::vector<double>& f, std::vector<double>& d, std::vector<int>& v,
           std::vector<double>& z) {
  const int n = static_cast<int>(f.size());
  int k = 0;
  v[0] = 0;
  z[0] = -std::numeric_limits<double>::infinity();
  z[1] = std::numeric_limits<double>::infinity();
  auto intersection = [&](int q, int p) {
    return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * q - 2.0 * p);
  };
  for (int q = 1; q < n; ++q) {
    double s = intersection(q, v[k]);
    while (s <= z[k]) {  // z[0] is -inf, so this stops at k == 0
      --k;
      s = intersection(q, v[k]);
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q) ++k;
    d[q] = double(q - v[k]) * (q - v[k]) + f[v[k]];
  }
}

}  // namespace

Grid DilateNavigable(const Grid& g, int radius) { return SquareAny(g, radius, 1, 0); }
Grid ErodeNavigable(const Grid& g, int radius, bool outside_blocked) {
  return SquareAny(g, radius, 0, outside_blocked ? 0 : 1);
}
Grid CloseNavigable(const Grid& g, int radius) {
  // The image border is no obstacle to the closing: growing then shrinking must give back the
  // navigable cells at the edge, so the erosion treats outside as navigable.
  return SquareAny(DilateNavigable(g, radius), radius, 0, 1);
}
Grid CloseNavigableKeepingStrokes(const Grid& g, int radius, long min_kept) {
  Grid out = CloseNavigable(g, radius);
  std::vector<int> seen(g.cells.size(), 0);
  std::vector<size_t> queue;
  for (size_t seed = 0; seed < g.cells.size(); ++seed) {
    if (g.cells[seed] || seen[seed]) continue;
    queue.assign(1, seed);
    seen[seed] = 1;
    for (size_t head = 0; head < queue.size(); ++head) {
      const int r = static_cast<int>(queue[head] / g.width);
      const int c = static_cast<int>(queue[head] % g.width);
      for (int k = 0; k < 9; ++k) {
        const int nr = r + k / 3 - 1, nc = c + k % 3 - 1;
        if (!g.Inside(nr, nc)) continue;
        const size_t j = g.Index(nr, nc);
        if (!g.cells[j] && !seen[j]) {
          seen[j] = 1;
          queue.push_back(j);
        }
      }
    }
    if (static_cast<long>(queue.size()) > min_kept) {
      for (size_t i : queue) out.cells[i] = 0;
    }
  }
  return out;
}

Grid CloseBlocked(const Grid& g, int radius) {
  // Blocked grows (navigable erodes, outside navigable so the border is not thickened), then
  // shrinks back with outside blocked.
  return SquareAny(SquareAny(g, radius, 0, 1), radius, 1, 0);
}

Grid FloodFill(const Grid& g, const std::vector<std::pair<int, int>>& seeds, std::uint8_t value) {
  Grid reached(g.width, g.height, 0);
  std::vector<std::pair<int, int>> stack;
  for (const auto& s : seeds) {
    if (g.Inside(s.first, s.second) && g.cells[g.Index(s.first, s.second)] == value &&
        !reached.cells[g.Index(s.first, s.second)]) {
      reached(s.first, s.second) = 1;
      stack.push_back(s);
    }
  }
  static const int kDr[4] = {1, -1, 0, 0};
  static const int kDc[4] = {0, 0, 1, -1};
  while (!stack.empty()) {
    const auto [r, c] = stack.back();
    stack.pop_back();
    for (int k = 0; k < 4; ++k) {
      const int nr = r + kDr[k], nc = c + kDc[k];
      if (!g.Inside(nr, nc)) continue;
      const size_t i = g.Index(nr, nc);
      if (g.cells[i] != value || reached.cells[i]) continue;
      reached.cells[i] = 1;
      stack.emplace_back(nr, nc);
    }
  }
  return reached;
}

std::vector<double> SquaredDistanceToZero(const Grid& g, bool outside_is_zero) {
  // Pad by one cell, of zeros when the outside counts as blocked.
  const int w = g.width + 2, h = g.height + 2;
  // Larger than any squared distance in the image, small enough to keep the arithmetic exact.
  const double kBig = 4.0 * (double(w) + h) * (double(w) + h);
  std::vector<double> grid(static_cast<size_t>(w) * h, outside_is_zero ? 0.0 : kBig);
  for (int r = 0; r < g.height; ++r) {
    for (int c = 0; c < g.width; ++c) {
      grid[static_cast<size_t>(r + 1) * w + c + 1] = g.cells[g.Index(r, c)] ? kBig : 0.0;
    }
  }
  const int n = std::max(w, h);
  std::vector<double> f(n), d(n), z(n + 1);
  std::vector<int> v(n);
  for (int c = 0; c < w; ++c) {
    f.resize(h), d.resize(h);
    for (int r = 0; r < h; ++r) f[r] = grid[static_cast<size_t>(r) * w + c];
    Edt1d(f, d, v, z);
    for (int r = 0; r < h; ++r) grid[static_cast<size_t>(r) * w + c] = d[r];
  }
  for (int r = 0; r < h; ++r) {
    f.resize(w), d.resize(w);
    for (int c = 0; c < w; ++c) f[c] = grid[static_cast<size_t>(r) * w + c];
    Edt1d(f, d, v, z);
    for (int c = 0; c < w; ++c) grid[static_cast<size_t>(r) * w + c] = d[c];
  }
  std::vector<double> out(g.cells.size());
  for (int r = 0; r < g.height; ++r) {
    for (int c = 0; c < g.width; ++c)
      out[g.Index(r, c)] = grid[static_cast<size_t>(r + 1) * w + c + 1];
  }
  return out;
}

}  // namespace crowdsim::floorplan
