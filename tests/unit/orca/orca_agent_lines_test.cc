// The agent lines of ORCA four neighbours at a time (AVX2) against one at a time: the same
// bits on every kind of neighbour, so that tables do not depend on the processor.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "orca/agent_lines.h"
#include "orca/geometry.h"

namespace crowdsim::orca {
namespace {

constexpr double kDt = 0.25;
const OrcaParams kParams{5.0, 5.0, 1.0};

// Which formula the scalar code takes for `other` (for coverage counts).
enum class Case { kOverlap, kCutoff, kLeftLeg, kRightLeg };

Case Classify(const OrcaAgent& self, const OrcaAgent& other, const OrcaParams& params) {
  const Vec2 p = other.position - self.position;
  const double combined = self.radius + other.radius;
  if (!(p.squaredNorm() > combined * combined)) return Case::kOverlap;
  const Vec2 w = self.velocity - other.velocity - (1.0 / params.time_horizon) * p;
  const double dot = w.dot(p);
  if (dot < 0.0 && dot * dot > combined * combined * w.squaredNorm()) return Case::kCutoff;
  return Det(p, w) > 0.0 ? Case::kLeftLeg : Case::kRightLeg;
}

std::string Bits(double x) {
  return std::to_string(std::bit_cast<std::uint64_t>(x)) + " (" + std::to_string(x) + ")";
}

// Every coordinate of every line, bit for bit (NaN payloads and the sign of zero included).
void ExpectSameLines(const std::vector<OrcaLine>& want, const std::vector<OrcaLine>& got,
                     const std::string& where) {
  ASSERT_EQ(want.size(), got.size()) << where;
  for (std::size_t k = 0; k < want.size(); ++k) {
    const std::array<double, 4> a{want[k].point.x(), want[k].point.y(), want[k].direction.x(),
                                  want[k].direction.y()};
    const std::array<double, 4> b{got[k].point.x(), got[k].point.y(), got[k].direction.x(),
                                  got[k].direction.y()};
    for (int c = 0; c < 4; ++c) {
      EXPECT_EQ(std::bit_cast<std::uint64_t>(a[c]), std::bit_cast<std::uint64_t>(b[c]))
          << where << ", line " << k << ", coordinate " << c << ": scalar " << Bits(a[c])
          << ", vector " << Bits(b[c]);
    }
  }
}

// Both paths on the same neighbours; also that nothing past the last line is written.
void CompareOn(const OrcaAgent& self, const std::vector<OrcaAgent>& neighbours,
               const std::string& where) {
  const OrcaLine sentinel{Vec2(-7.0, -7.0), Vec2(-7.0, -7.0)};
  std::vector<OrcaLine> scalar(neighbours.size() + 4, sentinel);
  std::vector<OrcaLine> vector(neighbours.size() + 4, sentinel);
  AddAgentLinesScalar(self, neighbours, kParams, kDt, scalar.data());
  AddAgentLinesAvx2(self, neighbours, kParams, kDt, vector.data());
  ExpectSameLines(scalar, vector, where);
  for (std::size_t k = neighbours.size(); k < vector.size(); ++k) {
    EXPECT_EQ(vector[k].point, sentinel.point) << where << ": line " << k << " written";
  }
  std::vector<OrcaLine> chosen(neighbours.size() + 4, sentinel);
  AddAgentLines(self, neighbours, kParams, kDt, chosen.data());
  ExpectSameLines(scalar, chosen, where + " (AddAgentLines)");
}

class AgentLinesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!HaveAvx2()) GTEST_SKIP() << "this processor runs no AVX2: the scalar path is the only one";
  }
};

TEST_F(AgentLinesTest, RandomCrowdsGiveTheScalarBitsInEveryCase) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> where(-3.0, 3.0), speed(-1.5, 1.5), radius(0.1, 0.6);
  std::uniform_int_distribution<int> count(0, 11);
  std::array<int, 4> seen{};
  for (int trial = 0; trial < 4000; ++trial) {
    const OrcaAgent self{Vec2(where(rng), where(rng)), Vec2(speed(rng), speed(rng)), radius(rng)};
    std::vector<OrcaAgent> neighbours(static_cast<std::size_t>(count(rng)));
    for (OrcaAgent& other : neighbours) {
      other = {Vec2(where(rng), where(rng)), Vec2(speed(rng), speed(rng)), radius(rng)};
      ++seen[static_cast<int>(Classify(self, other, kParams))];
    }
    CompareOn(self, neighbours, "trial " + std::to_string(trial));
    if (HasFailure()) return;
  }
  // Every formula ran in many lanes (else the comparison proves little).
  for (int c = 0; c < 4; ++c) EXPECT_GT(seen[c], 500) << "case " << c;
}

TEST_F(AgentLinesTest, EdgeCasesGiveTheScalarBits) {
  const OrcaAgent self{Vec2(1.0, 2.0), Vec2(0.5, -0.25), 0.31};
  const double touching = 0.62;  // the two radii
  const double tiny = std::numeric_limits<double>::denorm_min();
  const std::vector<std::vector<OrcaAgent>> crowds = {
      // Same spot, same velocity: w vanishes, the direction is +x (UnitOr).
      {{self.position, self.velocity, 0.31}},
      // Exactly touching, then a hair apart and a hair overlapping.
      {{self.position + Vec2(touching, 0.0), Vec2::Zero(), 0.31},
       {self.position + Vec2(0.0, std::nextafter(touching, 1.0)), Vec2::Zero(), 0.31},
       {self.position + Vec2(std::nextafter(touching, 0.0), 0.0), Vec2::Zero(), 0.31}},
      // Far away, head on, behind; a zero radius; negative zeros; the smallest offsets.
      {{self.position + Vec2(80.0, 0.0), Vec2(-1.0, 0.0), 0.31},
       {self.position + Vec2(2.0, 0.0), Vec2(-0.5, 0.25), 0.31},
       {self.position + Vec2(-2.0, 0.0), self.velocity, 0.0},
       {Vec2(-0.0, -0.0), Vec2(-0.0, 0.0), 0.31},
       {self.position + Vec2(tiny, -tiny), self.velocity, 0.31}},
      // v_rel exactly at the cut-off centre (w = 0 while apart).
      {{self.position + Vec2(2.0, 1.0), self.velocity - Vec2(2.0, 1.0) / kParams.time_horizon,
        0.31}},
  };
  for (std::size_t c = 0; c < crowds.size(); ++c) {
    CompareOn(self, crowds[c], "crowd " + std::to_string(c));
  }
}

TEST(AgentLinesDispatch, AddAgentLinesGivesTheScalarLinesOnEveryProcessor) {
  // Whichever path this processor takes, the lines are the scalar ones (the test above covers
  // the vector path in depth; this one runs on every machine).
  const OrcaAgent self{Vec2::Zero(), Vec2(0.8, 0.2), 0.31};
  const std::vector<OrcaAgent> neighbours = {{Vec2(1.0, 1.2), Vec2(-0.6, 0.1), 0.31},
                                             {Vec2(-1.2, -0.8), Vec2(0.5, 0.5), 0.31},
                                             {Vec2(0.2, 0.5), Vec2(0.0, 0.9), 0.31},
                                             {Vec2(-2.0, 0.3), Vec2(0.8, -0.2), 0.31},
                                             {Vec2(1.1, 2.6), Vec2(-0.3, -0.9), 0.31}};
  std::vector<OrcaLine> scalar(neighbours.size()), chosen(neighbours.size());
  AddAgentLinesScalar(self, neighbours, kParams, kDt, scalar.data());
  AddAgentLines(self, neighbours, kParams, kDt, chosen.data());
  ExpectSameLines(scalar, chosen, "five neighbours");
}

TEST(AgentLinesDispatch, CrowdsimSimdOffAloneDisablesTheVectorPath) {
  const char* before = std::getenv("CROWDSIM_SIMD");
  const std::string saved = before != nullptr ? before : "";
  unsetenv("CROWDSIM_SIMD");
  EXPECT_FALSE(SimdDisabled());
  setenv("CROWDSIM_SIMD", "on", 1);
  EXPECT_FALSE(SimdDisabled());
  setenv("CROWDSIM_SIMD", "off", 1);
  EXPECT_TRUE(SimdDisabled());
  if (before != nullptr) {
    setenv("CROWDSIM_SIMD", saved.c_str(), 1);
  } else {
    unsetenv("CROWDSIM_SIMD");
  }
}

}  // namespace
}  // namespace crowdsim::orca
