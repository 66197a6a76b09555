// Portable deterministic random numbers: one seed gives the same numbers on every compiler and
// standard library.
#pragma once

#include <cstdint>
#include <string_view>

#include "crowdsim/export.h"

namespace crowdsim {

/// SplitMix64 step: mixes a 64-bit value into a well-distributed one. Inline: the person
/// sensor derives a stream per person and step.
constexpr std::uint64_t SplitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// Episode seed from suite seed, world identity and episode index: all rows share episode k's
/// scenario.
CROWDSIM_SDK_API std::uint64_t DeriveSeed(std::uint64_t suite_seed, std::string_view world_identity,
                                          std::uint64_t episode_index);

/// xoshiro256** generator with portable uniform and normal draws.
class CROWDSIM_SDK_API Rng {
 public:
  explicit Rng(std::uint64_t seed) {
    std::uint64_t x = seed;
    for (auto& s : s_) {
      x = SplitMix64(x);
      s = x;
    }
  }
  /// The next 64 random bits; inline, as scenario set-up draws thousands of points.
  std::uint64_t NextU64() {
    const std::uint64_t result = Rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = Rotl(s_[3], 45);
    return result;
  }
  /// Uniform in [0, 1): the top 53 bits as a double.
  double Uniform() { return static_cast<double>(NextU64() >> 11) * 0x1.0p-53; }
  /// Uniform in [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  /// Uniform integer in [0, n).
  std::uint64_t Below(std::uint64_t n);
  /// Standard normal (Box-Muller, no cached second value).
  double Normal();
  /// An independent stream derived from this generator's next output and `salt`.
  Rng Fork(std::uint64_t salt);

 private:
  static constexpr std::uint64_t Rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

  std::uint64_t s_[4];
};

}  // namespace crowdsim
