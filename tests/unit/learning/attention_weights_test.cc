// SARL's attention weights: CrowdNav's masked softmax where it is finite, a max-shifted one
// where exp under- or overflows (the NaN that stopped the realistic-sensor training).
#include <gtest/gtest.h>

#include <cmath>

#include "value_rl/value_network.h"

namespace crowdsim::value_rl {
namespace {

torch::Tensor CrowdNavWeights(const torch::Tensor& s, const torch::Tensor& mask) {
  const torch::Tensor w = torch::exp(s) * s.ne(0).to(torch::kFloat) * mask;
  return w / w.sum(1, true);
}

TEST(AttentionWeightsTest, OrdinaryScoresKeepCrowdNavsValuesExactly) {
  torch::manual_seed(5);
  const torch::Tensor s = torch::randn({6, 5}) * 4;
  torch::Tensor mask = torch::ones({6, 5});
  mask.index_put_({2, torch::indexing::Slice(3)}, 0.0f);  // a state with 3 people, 2 padded
  EXPECT_TRUE(torch::equal(AttentionWeights(s, mask), CrowdNavWeights(s, mask)));
}

TEST(AttentionWeightsTest, UnderAndOverflowingRowsTakeTheShiftedSoftmax) {
  // Row 0 ordinary; row 1 one person at -200 (exp is 0: 0/0); row 2 two people at -200, -201;
  // row 3 one person at +200 (exp is inf: inf/inf) beside a padded row.
  const torch::Tensor s =
      torch::tensor({{0.5f, -1.0f}, {-200.0f, 0.0f}, {-200.0f, -201.0f}, {200.0f, 3.0f}});
  const torch::Tensor mask =
      torch::tensor({{1.0f, 1.0f}, {1.0f, 0.0f}, {1.0f, 1.0f}, {1.0f, 0.0f}});
  ASSERT_FALSE(torch::isfinite(CrowdNavWeights(s, mask)).all().item<bool>());
  const torch::Tensor w = AttentionWeights(s, mask);
  ASSERT_TRUE(torch::isfinite(w).all().item<bool>());
  EXPECT_TRUE(torch::equal(w[0], CrowdNavWeights(s, mask)[0]));
  EXPECT_FLOAT_EQ(w[1][0].item<float>(), 1.0f);
  EXPECT_FLOAT_EQ(w[1][1].item<float>(), 0.0f);
  const float e = std::exp(-1.0f);
  EXPECT_NEAR(w[2][0].item<float>(), 1.0f / (1.0f + e), 1e-6);
  EXPECT_NEAR(w[2][1].item<float>(), e / (1.0f + e), 1e-6);
  EXPECT_FLOAT_EQ(w[3][0].item<float>(), 1.0f);
  EXPECT_FLOAT_EQ(w[3][1].item<float>(), 0.0f);
}

TEST(AttentionWeightsTest, GradientsStayFiniteThroughTheShiftedRows) {
  torch::Tensor s =
      torch::tensor({{0.5f, -1.0f}, {-200.0f, -201.0f}, {150.0f, 0.0f}}).requires_grad_(true);
  const torch::Tensor mask = torch::ones({3, 2});
  const torch::Tensor h = torch::tensor({1.0f, 2.0f});
  (AttentionWeights(s, mask) * h).sum().backward();
  EXPECT_TRUE(torch::isfinite(s.grad()).all().item<bool>());
  // The ordinary row's gradient is CrowdNav's: w0 w1 (h0 - h1) on the first score.
  torch::Tensor s0 = torch::tensor({{0.5f, -1.0f}}).requires_grad_(true);
  (CrowdNavWeights(s0, torch::ones({1, 2})) * h).sum().backward();
  EXPECT_TRUE(torch::allclose(s.grad()[0], s0.grad()[0]));
}

TEST(AttentionWeightsTest, NoScoredRowGivesZeroWeights) {
  const torch::Tensor w = AttentionWeights(torch::zeros({1, 3}), torch::ones({1, 3}));
  EXPECT_TRUE(torch::equal(w, torch::zeros({1, 3})));
}

}  // namespace
}  // namespace crowdsim::value_rl
