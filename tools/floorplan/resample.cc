#include "resample.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace crowdsim::floorplan {
namespace {

// Overlap of each target cell with the source pixels along one axis: for target index t the
// list of (source index, length in source pixels). Separable because both grids are regular.
struct Span {
  int src;
  double length;
};

std::vector<std::vector<Span>> AxisSpans(int src_n, int dst_n, double ratio) {
  std::vector<std::vector<Span>> spans(dst_n);
  for (int t = 0; t < dst_n; ++t) {
    const double a = t * ratio;
    const double b = (t + 1) * ratio;
    for (int s = static_cast<int>(std::floor(a)); s < b && s < src_n; ++s) {
      const double len = std::min<double>(b, s + 1) - std::max<double>(a, s);
      if (len > 1e-12) spans[t].push_back({s, len});
    }
  }
  return spans;
}

}  // namespace

Grid Resample(const Grid& src, double src_res, double dst_res, double blocked_share) {
  if (std::abs(src_res - dst_res) <= 1e-9 * dst_res) return src;
  const double ratio = dst_res / src_res;  // source pixels per target cell
  const int w = static_cast<int>(std::ceil(src.width / ratio - 1e-9));
  const int h = static_cast<int>(std::ceil(src.height / ratio - 1e-9));
  const auto xs = AxisSpans(src.width, w, ratio);
  const auto ys = AxisSpans(src.height, h, ratio);
  const double cell_area = ratio * ratio;
  Grid out(w, h);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) {
      double free_area = 0.0;
      for (const Span& y : ys[r]) {
        for (const Span& x : xs[c]) {
          if (src.cells[src.Index(y.src, x.src)]) free_area += y.length * x.length;
        }
      }
      const double blocked = 1.0 - free_area / cell_area;  // beyond the image counts as blocked
      out(r, c) = blocked >= blocked_share - 1e-12 ? 0 : 1;
    }
  }
  return out;
}

}  // namespace crowdsim::floorplan
