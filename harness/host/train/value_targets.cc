#include "train/value_targets.h"

#include <stdexcept>

namespace crowdsim::training {

std::vector<float> MonteCarloReturns(std::span<const float> rewards, double discount) {
  std::vector<float> values(rewards.size());
  double v = 0.0;
  for (std::size_t i = rewards.size(); i-- > 0;) {
    v = rewards[i] + discount * v;
    values[i] = static_cast<float>(v);
  }
  return values;
}

std::vector<float> TdTargets(std::span<const float> rewards, std::span<const float> next_values,
                             double discount) {
  const std::size_t n = rewards.size();
  if (n == 0) return {};
  if (next_values.size() + 1 != n && next_values.size() != n) {
    throw std::invalid_argument("TdTargets: " + std::to_string(next_values.size()) +
                                " next values for " + std::to_string(n) + " rewards");
  }
  std::vector<float> y(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double bootstrap = i < next_values.size() ? discount * next_values[i] : 0.0;
    y[i] = static_cast<float>(rewards[i] + bootstrap);
  }
  return y;
}

}  // namespace crowdsim::training
