// Neighbour queries over the agents of one step (a uniform grid, rebuilt each step), so
// policies of large crowds never scan all pairs.
#pragma once

#include <span>
#include <vector>

#include "crowdsim/agent_state.h"

namespace crowdsim {

/// The agents one policy may see this step, with a fast k-nearest query.
class AgentIndex {
 public:
  /// Rebuilds the grid over `agents` (kept by reference until the next Rebuild).
  void Rebuild(std::span<const AgentState> agents, double cell_size = 2.0);

  std::span<const AgentState> agents() const { return agents_; }

  /// Indices of up to `max_count` agents whose centre is within `range` of `p`, nearest
  /// first, `exclude` (an index, or -1) left out. Ties keep lower indices first.
  void Nearest(const Vec2& p, double range, int max_count, int exclude,
               std::vector<int>* out) const;

 private:
  /// Nearest for a crowd small enough to have no grid (`range_sq`: range squared).
  void NearestOfFew(const Vec2& p, double range_sq, int max_count, int exclude,
                    std::vector<int>* out) const;

  std::span<const AgentState> agents_;
  double cell_ = 2.0;
  double margin_ = 0.0;  // slack on cell bounds for rounding in the cell of a position
  Vec2 origin_ = Vec2::Zero();
  int nx_ = 0, ny_ = 0;
  std::vector<int> cell_start_;  // CSR layout: agents of cell c are order_[start[c]..start[c+1])
  std::vector<int> order_;
  std::vector<Vec2> position_;  // position_[k] = agents_[order_[k]].position: cells contiguous
  std::vector<int> cell_of_;    // Rebuild's scratch
};

}  // namespace crowdsim
