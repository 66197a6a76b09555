#include "crowdsim/agent_index.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace crowdsim {

namespace {

struct Hit {
  double d2;
  int i;
};

// Nearest first, ties by index: a strict total order, so the k best are one exact set.
inline bool Less(const Hit& a, const Hit& b) { return a.d2 < b.d2 || (a.d2 == b.d2 && a.i < b.i); }

// The k best hits so far, nearest first in caller slots (k is small: a sorted array beats a heap).
class KBest {
 public:
  KBest(Hit* slots, int k) : slots_(slots), k_(k) {}
  /// True when no hit at `lower_d2` or farther can enter (the k best are all nearer).
  bool Excludes(double lower_d2) const { return lower_d2 > bound_; }
  void Offer(const Hit& h) {
    if (n_ == k_) {
      if (!Less(h, slots_[n_ - 1])) return;
      --n_;
    }
    int j = n_++;
    for (; j > 0 && Less(h, slots_[j - 1]); --j) slots_[j] = slots_[j - 1];
    slots_[j] = h;
    if (n_ == k_) bound_ = slots_[n_ - 1].d2;
  }
  void Write(std::vector<int>* out) const {
    for (int k = 0; k < n_; ++k) out->push_back(slots_[k].i);
  }
  /// The k-th best distance squared, or -1 while fewer than k hits have come.
  double KthD2() const { return n_ == k_ ? slots_[n_ - 1].d2 : -1.0; }

 private:
  Hit* slots_;
  int k_;
  int n_ = 0;
  double bound_ = kInfinity;  // the k-th best distance once there are k hits
};

// Crowds up to this size are searched by offering every agent (no grid walk).
constexpr size_t kScanAllUpTo = 16;

// Distance from x to the interval [lo, hi] (0 inside), less `margin`, never negative.
inline double GapTo(double x, double lo, double hi, double margin) {
  return std::max(0.0, std::max(lo - x, x - hi) - margin);
}

// First and last cell along an axis holding lo..hi (in cells from the origin); first > last when
// none. Truncation serves as floor.
inline void CellRange(double lo, double hi, int cells, int* first, int* last) {
  const double top = static_cast<double>(cells - 1);
  *first = static_cast<int>(std::clamp(lo, 0.0, top + 1.0));
  *last = hi < 0.0 ? -1 : static_cast<int>(std::min(hi, top));
}

// Nearest without a grid, for small crowds: index order makes ties match the grid search. The k
// best stay sorted in `out`, distances after a sentinel (no bound test).
void NearestOfFew(std::span<const Vec2> positions, const Vec2& p, double range_sq, int max_count,
                  int exclude, std::vector<int>* out) {
  const int count = static_cast<int>(positions.size());
  // At most the crowd less the agent left out: when all are in range, `out` is sized once.
  const int k = std::min(max_count, count - static_cast<int>(exclude >= 0 && exclude < count));
  // Sized, not cleared first: a policy's vector mostly keeps its size from query to query.
  out->resize(static_cast<size_t>(k));
  int* ids = out->data();
  double sentinel_and_d2s[kScanAllUpTo + 1];
  sentinel_and_d2s[0] = -kInfinity;
  double* d2s = sentinel_and_d2s + 1;
  int n = 0;
  const auto offer = [&](int i) {
    const double d2 = (positions[i] - p).squaredNorm();
    if (d2 >= range_sq) return;
    if (n == k) {
      if (!(d2 < d2s[n - 1])) return;
      --n;
    }
    int j = n++;
    for (; d2 < d2s[j - 1]; --j) {
      d2s[j] = d2s[j - 1];
      ids[j] = ids[j - 1];
    }
    d2s[j] = d2;
    ids[j] = i;
  };
  // The agents before and after the one left out: no test for it in the loops.
  const int skipped = exclude >= 0 && exclude < count ? exclude : count;
  for (int i = 0; i < skipped; ++i) offer(i);
  for (int i = skipped + 1; i < count; ++i) offer(i);
  out->resize(static_cast<size_t>(n));
}

}  // namespace

void AgentIndex::Rebuild(std::span<const AgentState> agents, double cell_size) {
  // A new crowd size is taken for new agents: their radii start unknown (0).
  if (hint_.size() != agents.size()) hint_.assign(agents.size(), 0.0f);
  agents_ = agents;
  cell_ = cell_size;
  if (agents.empty()) {
    nx_ = ny_ = 0;
    cell_start_.assign(1, 0);
    order_.clear();
    position_.clear();
    return;
  }
  if (agents.size() <= kScanAllUpTo) {
    // Nearest offers every agent of a crowd this small: no grid, the agents in their order.
    order_.resize(agents.size());
    position_.resize(agents.size());
    for (size_t i = 0; i < agents.size(); ++i) {
      order_[i] = static_cast<int>(i);
      position_[i] = agents[i].position;
    }
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
  // A position's cell comes from a rounded division; the pruning bounds' margin far exceeds it.
  margin_ =
      1e-9 *
      (1.0 + std::max({std::abs(lo.x()), std::abs(lo.y()), std::abs(hi.x()), std::abs(hi.y())}));
  nx_ = static_cast<int>((hi.x() - lo.x()) / cell_) + 1;
  ny_ = static_cast<int>((hi.y() - lo.y()) / cell_) + 1;
  const int cells = nx_ * ny_;
  cell_start_.assign(cells + 1, 0);
  cell_of_.resize(agents.size());
  for (size_t i = 0; i < agents.size(); ++i) {
    const int cx = static_cast<int>((agents[i].position.x() - lo.x()) / cell_);
    const int cy = static_cast<int>((agents[i].position.y() - lo.y()) / cell_);
    cell_of_[i] = cy * nx_ + cx;
    ++cell_start_[cell_of_[i] + 1];
  }
  for (int c = 0; c < cells; ++c) cell_start_[c + 1] += cell_start_[c];
  order_.resize(agents.size());
  position_.resize(agents.size());
  // Counting sort: each agent takes the next free slot of its cell, then starts move back one cell.
  for (size_t i = 0; i < agents.size(); ++i) {
    const int k = cell_start_[cell_of_[i]]++;
    order_[k] = static_cast<int>(i);
    position_[k] = agents[i].position;
  }
  for (int c = cells; c > 0; --c) cell_start_[c] = cell_start_[c - 1];
  cell_start_[0] = 0;
}

void AgentIndex::Nearest(const Vec2& p, double range, int max_count, int exclude,
                         std::vector<int>* out) const {
  if (agents_.empty() || max_count <= 0) {
    out->clear();
    return;
  }
  const double range_sq = range * range;
  if (position_.size() <= kScanAllUpTo) {
    NearestOfFew(position_, p, range_sq, max_count, exclude, out);
    return;
  }
  out->clear();
  // Start from the agent's last query radius: a disc that held its k nearest likely still does.
  const bool hinted =
      exclude >= 0 && exclude < static_cast<int>(hint_.size()) && max_count <= kMaxHintedCount;
  double kth_d2 = -1.0;
  if (!hinted) {
    RingSearch(p, range, max_count, exclude, out, &kth_d2);
    return;
  }
  std::atomic_ref<float> hint(hint_[exclude]);
  const double radius = hint.load(std::memory_order_relaxed);
  if (!(radius > 0.0 &&
        DiscSearch(p, range, std::min(range, radius), max_count, exclude, out, &kth_d2))) {
    RingSearch(p, range, max_count, exclude, out, &kth_d2);
  }
  hint.store(kth_d2 < 0.0 ? static_cast<float>(range)
                          : static_cast<float>(kHintScale * std::sqrt(kth_d2) + kHintSlack),
             std::memory_order_relaxed);
}

bool AgentIndex::DiscSearch(const Vec2& p, double range, double radius, int max_count, int exclude,
                            std::vector<int>* out, double* kth_d2) const {
  // Gather every agent within `radius` of p, row by row of cells cut to the disc's chord;
  // branch-free.
  const double range_sq = range * range;
  const double radius_sq = radius * radius;
  const double reach = radius + margin_;
  const double inv_cell = 1.0 / cell_;
  int y0, y1;
  CellRange((p.y() - reach - origin_.y()) * inv_cell, (p.y() + reach - origin_.y()) * inv_cell, ny_,
            &y0, &y1);
  // First each row's run of agents (the square roots of all rows at once), then the agents.
  constexpr int kMaxRows = 64;
  if (y1 - y0 + 1 > kMaxRows) return false;  // a disc of very many cells: the ring walk
  int run_begin[kMaxRows], run_end[kMaxRows];
  int runs = 0, total = 0;
  for (int cy = y0; cy <= y1; ++cy) {
    const double gy =
        GapTo(p.y(), origin_.y() + cy * cell_, origin_.y() + (cy + 1) * cell_, margin_);
    const double half_chord = std::sqrt(std::max(0.0, radius_sq - gy * gy)) + margin_;
    int xa, xb;
    CellRange((p.x() - half_chord - origin_.x()) * inv_cell,
              (p.x() + half_chord - origin_.x()) * inv_cell, nx_, &xa, &xb);
    if (gy > radius || xa > xb) continue;
    run_begin[runs] = cell_start_[cy * nx_ + xa];
    run_end[runs] = cell_start_[cy * nx_ + xb + 1];
    total += run_end[runs] - run_begin[runs];
    ++runs;
  }
  if (total > kDiscCapacity) return false;  // a crowd too dense for the slots
  Hit found[kDiscCapacity];
  int n = 0;
  for (int r = 0; r < runs; ++r) {
    for (int k = run_begin[r]; k < run_end[r]; ++k) {
      const double d2 = (position_[k] - p).squaredNorm();
      const int i = order_[k];
      found[n] = {d2, i};
      n += static_cast<int>((d2 <= radius_sq) & (d2 < range_sq) & (i != exclude));
    }
  }
  // k agents in the disc are the k nearest overall; fewer answer only if the disc covers the range.
  if (n < max_count && radius < range) return false;
  Hit slots[kMaxHintedCount];
  KBest best(slots, max_count);
  for (int j = 0; j < n; ++j) best.Offer(found[j]);
  best.Write(out);
  *kth_d2 = best.KthD2();
  return true;
}

void AgentIndex::RingSearch(const Vec2& p, double range, int max_count, int exclude,
                            std::vector<int>* out, double* kth_d2) const {
  const double range_sq = range * range;
  constexpr int kOnStack = 32;
  Hit stack_slots[kOnStack];
  std::vector<Hit> heap_slots(max_count > kOnStack ? max_count : 0);
  KBest best(max_count > kOnStack ? heap_slots.data() : stack_slots, max_count);

  // Offers the agent in slot k of the cell-sorted arrays if it is in range.
  const auto offer = [&](int k) {
    const double d2 = (position_[k] - p).squaredNorm();
    if (d2 >= range_sq) return;
    const int i = order_[k];
    if (i != exclude) best.Offer({d2, i});
  };
  const int x0 = std::max(0, static_cast<int>(std::floor((p.x() - range - origin_.x()) / cell_)));
  const int x1 =
      std::min(nx_ - 1, static_cast<int>(std::floor((p.x() + range - origin_.x()) / cell_)));
  const int y0 = std::max(0, static_cast<int>(std::floor((p.y() - range - origin_.y()) / cell_)));
  const int y1 =
      std::min(ny_ - 1, static_cast<int>(std::floor((p.y() + range - origin_.y()) / cell_)));
  if (x0 > x1 || y0 > y1) return;  // kth_d2 stays -1: none in range

  // Cells [xa, xb] of row cy: one run of the sorted arrays, skipped when too far.
  const auto visit_span = [&](int xa, int xb, int cy) {
    const double gx =
        GapTo(p.x(), origin_.x() + xa * cell_, origin_.x() + (xb + 1) * cell_, margin_);
    const double gy =
        GapTo(p.y(), origin_.y() + cy * cell_, origin_.y() + (cy + 1) * cell_, margin_);
    const double lower_d2 = gx * gx + gy * gy;
    if ((lower_d2 >= range_sq) | best.Excludes(lower_d2)) return;
    const int end = cell_start_[cy * nx_ + xb + 1];
    for (int k = cell_start_[cy * nx_ + xa]; k < end; ++k) offer(k);
  };
  // The cell of p, then rings outward until the k best beat the next ring (as RVO2's kd-tree); a
  // ring is two row runs plus side cells.
  const int pcx = static_cast<int>(std::floor((p.x() - origin_.x()) / cell_));
  const int pcy = static_cast<int>(std::floor((p.y() - origin_.y()) / cell_));
  const int last_ring = std::max({pcx - x0, x1 - pcx, pcy - y0, y1 - pcy});
  for (int r = std::max(0, std::max({x0 - pcx, pcx - x1, y0 - pcy, pcy - y1})); r <= last_ring;
       ++r) {
    if (r >= 1) {
      const double inner_x0 = origin_.x() + (pcx - r + 1) * cell_,
                   inner_x1 = origin_.x() + (pcx + r) * cell_;
      const double inner_y0 = origin_.y() + (pcy - r + 1) * cell_,
                   inner_y1 = origin_.y() + (pcy + r) * cell_;
      const double gap =
          std::min({p.x() - inner_x0, inner_x1 - p.x(), p.y() - inner_y0, inner_y1 - p.y()}) -
          margin_;
      if (gap > 0.0 && (gap * gap >= range_sq || best.Excludes(gap * gap))) break;
    }
    const int ya = std::max(y0, pcy - r), yb = std::min(y1, pcy + r);
    const int xa = std::max(x0, pcx - r), xb = std::min(x1, pcx + r);
    if (xa > xb) continue;
    for (int cy = ya; cy <= yb; ++cy) {
      if (cy == pcy - r || cy == pcy + r) {
        visit_span(xa, xb, cy);  // the ring's top and bottom rows
      } else {
        if (pcx - r >= x0) visit_span(pcx - r, pcx - r, cy);  // its left and right columns
        if (r > 0 && pcx + r <= x1) visit_span(pcx + r, pcx + r, cy);
      }
    }
  }
  best.Write(out);
  *kth_d2 = best.KthD2();
}

}  // namespace crowdsim
