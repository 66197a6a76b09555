// The small linear programs of ORCA: find the velocity closest to the preferred one inside
// the max-speed disc and on the feasible side of every ORCA line (RVO2's LP1/LP2/LP3).
#pragma once

#include <cstddef>
#include <span>

#include "crowdsim/geometry.h"

namespace crowdsim::orca {

/// A directed line in velocity space; its feasible half-plane is on its left.
struct OrcaLine {
  Vec2 point = Vec2::Zero();       ///< m/s, a point on the line
  Vec2 direction = Vec2::UnitX();  ///< unit direction
};

/// Optimises over the disc of `radius` (m/s) subject to every line, in order: the point
/// closest to `opt`, or, with `direction_opt`, the point farthest along the unit vector `opt`.
/// Returns the number of lines before the first one that made it infeasible (lines.size() on
/// success); `result` then holds the optimum over the lines before it.
std::size_t SolveLinearProgram2(std::span<const OrcaLine> lines, double radius, const Vec2& opt,
                                bool direction_opt, Vec2* result);

/// Called when line `begin` made the program infeasible: keeps the first `num_hard` lines
/// (obstacles) hard and minimises the largest violation of the others. `result` is the
/// output of SolveLinearProgram2 on entry and the new velocity on return.
void SolveLinearProgram3(std::span<const OrcaLine> lines, std::size_t num_hard, std::size_t begin,
                         double radius, Vec2* result);

}  // namespace crowdsim::orca
