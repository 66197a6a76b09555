// The ORCA lines an agent takes from its neighbours (half of each avoidance), computed one
// neighbour at a time or four at a time in AVX2 lanes. Both compute every line with the same
// IEEE operations in the same order (no fused multiply-add), so they agree to the last bit
// and a table made on a machine without AVX2 equals one made with it.
#pragma once

#include <span>

#include "crowdsim/vector_units.h"
#include "orca/linear_program.h"
#include "orca/solver.h"

namespace crowdsim::orca {

/// One line per neighbour into out[0 .. neighbours.size()), nearest first as given; the
/// fastest of the two below that this processor runs, or the scalar one when SimdDisabled()
/// (crowdsim/vector_units.h: both give the same bits; the switch exists to show it on whole
/// suites).
void AddAgentLines(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                   const OrcaParams& params, double time_step, OrcaLine* out);

/// One neighbour at a time: the reference, and what runs without AVX2.
void AddAgentLinesScalar(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                         const OrcaParams& params, double time_step, OrcaLine* out);

/// Four neighbours at a time in AVX2 lanes, one or two left over one at a time (three fill a
/// group, padded with a copy of the last). Call only when HaveAvx2().
void AddAgentLinesAvx2(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                       const OrcaParams& params, double time_step, OrcaLine* out);

}  // namespace crowdsim::orca
