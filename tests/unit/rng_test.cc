#include "crowdsim/rng.h"

#include <gtest/gtest.h>

#include <set>

namespace crowdsim {
namespace {

TEST(Rng, SameSeedSameStreamAndPortableValues) {
  Rng a(42), b(42), c(43);
  for (int i = 0; i < 100; ++i) {
    const auto x = a.NextU64();
    EXPECT_EQ(x, b.NextU64());
    EXPECT_NE(x, c.NextU64());
  }
  // Pinned: the stream must not change across compilers, or frozen results would drift.
  Rng p(1);
  EXPECT_EQ(p.NextU64(), Rng(1).NextU64());
  EXPECT_EQ(SplitMix64(0), 0xe220a8397b1dcdafULL);
}

TEST(Rng, UniformStaysInRangeAndBelowIsUnbiasedEnough) {
  Rng r(7);
  int counts[5] = {0};
  for (int i = 0; i < 50000; ++i) {
    const double u = r.Uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    ++counts[r.Below(5)];
  }
  for (int c : counts) EXPECT_NEAR(c, 10000, 400);
}

TEST(Rng, DeriveSeedSeparatesWorldsAndEpisodes) {
  std::set<std::uint64_t> seeds;
  for (int e = 0; e < 100; ++e) {
    seeds.insert(DeriveSeed(1, "random_rect:obstacles=1:split=test", e));
    seeds.insert(DeriveSeed(1, "random_rect:obstacles=3:split=test", e));
    seeds.insert(DeriveSeed(2, "random_rect:obstacles=1:split=test", e));
  }
  EXPECT_EQ(seeds.size(), 300u);
  EXPECT_EQ(DeriveSeed(1, "w", 5), DeriveSeed(1, "w", 5));
}

}  // namespace
}  // namespace crowdsim
