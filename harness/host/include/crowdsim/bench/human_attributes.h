// The per-person attributes of one episode, drawn from a row's `humans:` keys.
#pragma once

#include <cstdint>
#include <vector>

#include "crowdsim/bench/suite.h"
#include "crowdsim/sim_config.h"
#include "crowdsim/world_source.h"

namespace crowdsim {

/// The people's attributes of the episode with `episode_seed`; empty when `humans` sets none
/// (worlds then use the sim's radius and v_pref). Person i's draws depend on the seed and i alone,
/// so every row, count and thread count meets the same people. Radii are rounded to the
/// centimetre, so people of one size share one planning roadmap.
std::vector<HumanAttributes> DrawHumanAttributes(const HumansSpec& humans, const SimConfig& sim,
                                                 std::uint64_t episode_seed, int count);

}  // namespace crowdsim
