// Value targets of one recorded episode: Monte-Carlo returns for demonstrations, TD(0) from the
// target network for RL.
#pragma once

#include <span>
#include <vector>

namespace crowdsim::training {

/// v_i = sum_{t >= i} discount^(t - i) r_t (imitation: the teacher's episode as it ended).
std::vector<float> MonteCarloReturns(std::span<const float> rewards, double discount);

/// TD(0): y_i = r_i + discount * next_values[i], the target network's value after step i.
/// `next_values` is one shorter than `rewards` after a terminal state (last target: reward), equal
/// after a truncation.
std::vector<float> TdTargets(std::span<const float> rewards, std::span<const float> next_values,
                             double discount);

}  // namespace crowdsim::training
