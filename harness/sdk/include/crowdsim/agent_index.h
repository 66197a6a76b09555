// Neighbour queries over one step's agents (a uniform grid, rebuilt each step): no all-pairs scan.
#pragma once

#include <span>
#include <vector>

#include "crowdsim/agent_state.h"
#include "crowdsim/export.h"

namespace crowdsim {

/// The agents a policy may see this step, with a thread-safe k-nearest query seeded by each agent's
/// last query (the answer never depends on it).
class CROWDSIM_SDK_API AgentIndex {
 public:
  /// Rebuilds the grid over `agents` (kept by reference until the next Rebuild).
  void Rebuild(std::span<const AgentState> agents, double cell_size = 2.0);

  std::span<const AgentState> agents() const { return agents_; }

  /// Up to `max_count` agents within `range` of `p`, nearest first, ties by index; `exclude` (or
  /// -1) left out.
  void Nearest(const Vec2& p, double range, int max_count, int exclude,
               std::vector<int>* out) const;

 private:
  /// Nearest from the agents within `radius` (<= range) of p alone; false, `out` undefined, when
  /// that disc cannot decide.
  bool DiscSearch(const Vec2& p, double range, double radius, int max_count, int exclude,
                  std::vector<int>* out, double* kth_d2) const;
  /// Nearest by walking rings of cells outward. `kth_d2`: the k-th best distance squared, or -1.
  void RingSearch(const Vec2& p, double range, int max_count, int exclude, std::vector<int>* out,
                  double* kth_d2) const;

  // Agent i's query starts at radius hint_[i]: kHintScale times its last k-th distance plus
  // kHintSlack (m) for a step's motion.
  static constexpr int kMaxHintedCount = 32;
  static constexpr int kDiscCapacity = 256;
  static constexpr double kHintScale = 1.0;
  static constexpr double kHintSlack = 0.25;

  std::span<const AgentState> agents_;
  double cell_ = 2.0;
  double margin_ = 0.0;  // slack on cell bounds for rounding in the cell of a position
  Vec2 origin_ = Vec2::Zero();
  int nx_ = 0, ny_ = 0;
  std::vector<int> cell_start_;  // CSR layout: agents of cell c are order_[start[c]..start[c+1])
  std::vector<int> order_;
  std::vector<Vec2> position_;  // position_[k] = agents_[order_[k]].position: cells contiguous
  std::vector<int> cell_of_;    // Rebuild's scratch
  // Per agent, its next query's start radius (m; 0: none). Const queries write it through relaxed
  // atomics: staleness costs only time.
  mutable std::vector<float> hint_;
};

}  // namespace crowdsim
