// Per-person attributes: drawn in range, rounded radii, the configured share of distracted people,
// one person's draws independent of the others, and the sim's people when nothing is set.
#include "crowdsim/bench/human_attributes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace crowdsim {
namespace {

HumansSpec CrowdNavPeople(double distracted = 0.0) {
  HumansSpec h;
  h.radius = AttributeRange{0.3, 0.5};  // CrowdNav's randomize_attributes
  h.v_pref = AttributeRange{0.5, 1.5};
  h.distracted = distracted;
  return h;
}

TEST(HumanAttributes, NoneAreDrawnForTheSimsPeople) {
  EXPECT_TRUE(DrawHumanAttributes(HumansSpec{}, SimConfig{}, 42, 5).empty());
}

TEST(HumanAttributes, DrawsStayInRangeWithCentimetreRadii) {
  const HumansSpec spec = CrowdNavPeople();
  double radius_sum = 0.0, v_sum = 0.0;
  int n = 0;
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    for (const HumanAttributes& a : DrawHumanAttributes(spec, SimConfig{}, seed, 5)) {
      EXPECT_GE(a.radius, 0.3);
      EXPECT_LE(a.radius, 0.5);
      EXPECT_NEAR(a.radius * 100.0, std::round(a.radius * 100.0), 1e-9);
      EXPECT_GE(a.v_pref, 0.5);
      EXPECT_LT(a.v_pref, 1.5);
      EXPECT_FALSE(a.ignores_robot);
      radius_sum += a.radius;
      v_sum += a.v_pref;
      ++n;
    }
  }
  // Uniform means 0.4 and 1.0; standard errors 0.058 / sqrt(10,000) and 0.29 / sqrt(10,000).
  EXPECT_NEAR(radius_sum / n, 0.4, 4 * 0.058 / 100.0);
  EXPECT_NEAR(v_sum / n, 1.0, 4 * 0.29 / 100.0);
}

TEST(HumanAttributes, TheDistractedShareIsTheConfiguredProbability) {
  const HumansSpec spec = CrowdNavPeople(0.25);
  int distracted = 0, n = 0;
  for (std::uint64_t seed = 1; seed <= 2000; ++seed) {
    for (const HumanAttributes& a : DrawHumanAttributes(spec, SimConfig{}, seed, 5)) {
      distracted += a.ignores_robot ? 1 : 0;
      ++n;
    }
  }
  const double se = std::sqrt(0.25 * 0.75 / n);
  EXPECT_NEAR(static_cast<double>(distracted) / n, 0.25, 4 * se);
}

TEST(HumanAttributes, APersonsDrawsDependOnTheSeedAndItsIndexAlone) {
  const HumansSpec spec = CrowdNavPeople(0.5);
  const auto three = DrawHumanAttributes(spec, SimConfig{}, 7, 3);
  const auto six = DrawHumanAttributes(spec, SimConfig{}, 7, 6);
  const auto again = DrawHumanAttributes(spec, SimConfig{}, 7, 3);
  const auto other = DrawHumanAttributes(spec, SimConfig{}, 8, 3);
  for (size_t i = 0; i < three.size(); ++i) {
    EXPECT_EQ(three[i].radius, six[i].radius);
    EXPECT_EQ(three[i].v_pref, six[i].v_pref);
    EXPECT_EQ(three[i].ignores_robot, six[i].ignores_robot);
    EXPECT_EQ(three[i].v_pref, again[i].v_pref);
  }
  EXPECT_NE(three[0].v_pref, other[0].v_pref);
}

TEST(HumanAttributes, OneKeySetLeavesTheOthersAtTheSimsValues) {
  HumansSpec spec;
  spec.distracted = 1.0;
  SimConfig sim;
  sim.human_radius = 0.35;
  sim.human_v_pref = 1.2;
  for (const HumanAttributes& a : DrawHumanAttributes(spec, sim, 3, 4)) {
    EXPECT_EQ(a.radius, 0.35);
    EXPECT_EQ(a.v_pref, 1.2);
    EXPECT_TRUE(a.ignores_robot);
  }
  // A fixed value (lo == hi) is that value for everybody.
  HumansSpec fixed;
  fixed.v_pref = AttributeRange{0.8, 0.8};
  for (const HumanAttributes& a : DrawHumanAttributes(fixed, sim, 3, 4)) {
    EXPECT_EQ(a.v_pref, 0.8);
    EXPECT_EQ(a.radius, 0.35);
  }
}

// share 0.6 of 10 people: the first 6 walk in groups of 2-3 (consecutive ids from 0), the rest
// alone; each group at the pace of its slowest member.
TEST(HumanAttributes, GroupsTakeTheFirstShareOfThePeopleAtOnePace) {
  HumansSpec spec = CrowdNavPeople();
  spec.groups = GroupsSpec{0.6, 2, 3};
  for (std::uint64_t seed = 1; seed <= 500; ++seed) {
    const auto people = DrawHumanAttributes(spec, SimConfig{}, seed, 10);
    int grouped = 0;
    for (size_t i = 0; i < people.size();) {
      size_t end = i + 1;
      while (end < people.size() && people[i].group >= 0 && people[end].group == people[i].group)
        ++end;
      if (people[i].group >= 0) {
        EXPECT_GE(end - i, 2u);
        EXPECT_LE(end - i, 3u);
        for (size_t k = i; k < end; ++k) EXPECT_EQ(people[k].v_pref, people[i].v_pref);
        grouped += static_cast<int>(end - i);
      }
      i = end;
    }
    // round(0.6 * 10) = 6 grouped, or 5 when a 2 and a 3 leave one person over, who walks alone.
    EXPECT_LE(grouped, 6);
    EXPECT_GE(grouped, 5);
    for (size_t i = 6; i < people.size(); ++i) EXPECT_EQ(people[i].group, -1);
  }
}

}  // namespace
}  // namespace crowdsim
