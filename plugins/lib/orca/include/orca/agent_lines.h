// The ORCA lines an agent takes from its neighbours (half of each avoidance), computed one
// neighbour at a time or four at a time in AVX2 lanes. Both compute every line with the same
// IEEE operations in the same order (no fused multiply-add), so they agree to the last bit
// and a table made on a machine without AVX2 equals one made with it.
#pragma once

#include <span>

#include "orca/linear_program.h"
#include "orca/solver.h"

namespace crowdsim::orca {

/// One line per neighbour into out[0 .. neighbours.size()), nearest first as given; the
/// fastest of the two below that this processor runs, or the scalar one when SimdDisabled()
/// (both give the same bits; the switch exists to show it on whole suites).
void AddAgentLines(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                   const OrcaParams& params, double time_step, OrcaLine* out);

/// One neighbour at a time: the reference, and what runs without AVX2.
void AddAgentLinesScalar(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                         const OrcaParams& params, double time_step, OrcaLine* out);

/// True when this processor and its operating system run AVX2 code.
bool HaveAvx2();

/// True when the environment variable CROWDSIM_SIMD is "off": AddAgentLines then takes the
/// scalar path on any processor (read at its first call).
bool SimdDisabled();

/// Four neighbours at a time in AVX2 lanes, one or two left over one at a time (three fill a
/// group, padded with a copy of the last). Call only when HaveAvx2().
void AddAgentLinesAvx2(const OrcaAgent& self, std::span<const OrcaAgent> neighbours,
                       const OrcaParams& params, double time_step, OrcaLine* out);

}  // namespace crowdsim::orca
