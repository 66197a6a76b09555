// Portable deterministic random numbers: the same seed gives the same numbers on every
// compiler and standard library (std:: distributions do not promise that).
#pragma once

#include <cstdint>
#include <string_view>

namespace crowdsim {

/// SplitMix64 step: mixes a 64-bit value into a well-distributed one.
std::uint64_t SplitMix64(std::uint64_t x);

/// Seed of one episode, from the suite seed, the world's identity and the episode index.
/// Every row of a suite sees the same scenario for episode k.
std::uint64_t DeriveSeed(std::uint64_t suite_seed, std::string_view world_identity,
                         std::uint64_t episode_index);

/// xoshiro256** generator with portable uniform and normal draws.
class Rng {
 public:
  explicit Rng(std::uint64_t seed);
  std::uint64_t NextU64();
  /// Uniform in [0, 1).
  double Uniform();
  /// Uniform in [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  /// Uniform integer in [0, n).
  std::uint64_t Below(std::uint64_t n);
  /// Standard normal (Box-Muller, no cached second value).
  double Normal();
  /// An independent stream derived from this generator's next output and `salt`.
  Rng Fork(std::uint64_t salt);

 private:
  std::uint64_t s_[4];
};

}  // namespace crowdsim
