// The value targets the trainer stores for one recorded episode: Monte-Carlo returns for the
// teacher's demonstrations, TD(0) targets from the target network for RL episodes.
#pragma once

#include <span>
#include <vector>

namespace crowdsim::training {

/// v_i = sum_{t >= i} discount^(t - i) r_t (imitation: the teacher's episode as it ended).
std::vector<float> MonteCarloReturns(std::span<const float> rewards, double discount);

/// TD(0): y_i = r_i + discount * next_values[i], where next_values[i] is the target network's
/// value of the state reached by transition i. `next_values` holds one value fewer than
/// `rewards` when the episode ended in a terminal state (its last target is its reward), and
/// as many when it was cut short (a timeout stored as a truncation bootstraps its last target).
std::vector<float> TdTargets(std::span<const float> rewards, std::span<const float> next_values,
                             double discount);

}  // namespace crowdsim::training
