#include "crowdsim/rng.h"

#include <cmath>
#include <numbers>

namespace crowdsim {

std::uint64_t DeriveSeed(std::uint64_t suite_seed, std::string_view world_identity,
                         std::uint64_t episode_index) {
  // FNV-1a of the identity, then mixed with the seed and the index.
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : world_identity) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  return SplitMix64(SplitMix64(suite_seed ^ SplitMix64(h)) ^ SplitMix64(episode_index + 1));
}

std::uint64_t Rng::Below(std::uint64_t n) {
  if (n == 0) return 0;
  // Rejection sampling: unbiased and portable.
  const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % n);
  std::uint64_t x;
  do {
    x = NextU64();
  } while (x >= limit);
  return x % n;
}

double Rng::Normal() {
  double u1 = Uniform();
  while (u1 <= 0.0) u1 = Uniform();
  const double u2 = Uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

Rng Rng::Fork(std::uint64_t salt) { return Rng(SplitMix64(NextU64() ^ SplitMix64(salt))); }

}  // namespace crowdsim
