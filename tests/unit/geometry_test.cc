#include "crowdsim/geometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace crowdsim {
namespace {

constexpr double kEps = 1e-12;
// Swept contact is defined 1e-9 m inside the disc (touching is not contact), so contact
// times sit within 1e-9 m of travel of the exact touch.
constexpr double kContactEps = 1e-9;
const Rect kBox = Rect::FromCorners(1.0, -1.0, 3.0, 1.0);

TEST(PointToSegmentDistance, ProjectsInsideTheSegment) {
  EXPECT_NEAR(PointToSegmentDistance(Vec2(0, 0), Vec2(4, 0), Vec2(2, 3)), 3.0, kEps);
}

TEST(PointToSegmentDistance, ClampsToTheEndpoints) {
  // u < 0 and u > 1 use the nearest endpoint (CrowdNav's point_to_segment_dist).
  EXPECT_NEAR(PointToSegmentDistance(Vec2(0, 0), Vec2(4, 0), Vec2(-3, 4)), 5.0, kEps);
  EXPECT_NEAR(PointToSegmentDistance(Vec2(0, 0), Vec2(4, 0), Vec2(7, -4)), 5.0, kEps);
}

TEST(PointToSegmentDistance, DegenerateSegmentIsAPoint) {
  EXPECT_NEAR(PointToSegmentDistance(Vec2(1, 1), Vec2(1, 1), Vec2(4, 5)), 5.0, kEps);
}

// The definition the function shortens: u = clamp((p - a).ab / |ab|^2, 0, 1), the distance to
// a + u ab. Bit for bit, not within a tolerance: the shortcut divides only strictly between the
// ends and must give the same double everywhere.
double SegmentDistanceByDefinition(const Vec2& a, const Vec2& b, const Vec2& p) {
  const Vec2 ab = b - a;
  const double len2 = ab.squaredNorm();
  if (len2 == 0.0) return (p - a).norm();
  const double u = std::clamp((p - a).dot(ab) / len2, 0.0, 1.0);
  return (a + u * ab - p).norm();
}

TEST(PointToSegmentDistance, EqualsItsDefinitionBitForBit) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> coord(-6.0, 6.0);
  std::uniform_real_distribution<double> small(-0.5, 0.5);
  int interior = 0, ends = 0;
  for (int k = 0; k < 200000; ++k) {
    // Short segments near the point, as the swept robot-human test makes them, and long ones.
    const Vec2 a(coord(rng), coord(rng));
    const Vec2 b =
        k % 2 == 0 ? Vec2(a + Vec2(small(rng), small(rng))) : Vec2(coord(rng), coord(rng));
    const Vec2 p = k % 3 == 0 ? Vec2::Zero() : Vec2(coord(rng), coord(rng));
    const double along = (p - a).dot(b - a);
    (along > 0.0 && along < (b - a).squaredNorm() ? interior : ends) += 1;
    ASSERT_EQ(PointToSegmentDistance(a, b, p), SegmentDistanceByDefinition(a, b, p))
        << "a " << a.transpose() << " b " << b.transpose() << " p " << p.transpose();
  }
  EXPECT_GT(interior, 10000);  // both branches were exercised
  EXPECT_GT(ends, 10000);
  // Exactly at the ends, on the segment's line, and with signed zeros.
  const std::vector<std::array<Vec2, 3>> cases = {{Vec2(0, 0), Vec2(4, 0), Vec2(0, 3)},
                                                  {Vec2(0, 0), Vec2(4, 0), Vec2(4, 3)},
                                                  {Vec2(0, 0), Vec2(4, 0), Vec2(2, 0)},
                                                  {Vec2(1, 1), Vec2(3, 3), Vec2(3, 3)},
                                                  {Vec2(-0.0, 0), Vec2(0, -2), Vec2(0, 0)},
                                                  {Vec2(0.1, 0.2), Vec2(0.3, 0.7), Vec2(0.3, 0.7)},
                                                  {Vec2(1e-300, 0), Vec2(2e-300, 0), Vec2(0, 0)},
                                                  // Squares that overflow: the definition's NaN.
                                                  {Vec2(0, 0), Vec2(1e200, 0), Vec2(1e200, 0)},
                                                  {Vec2(0, 0), Vec2(2e154, 0), Vec2(3e154, 0)},
                                                  {Vec2(0, 0), Vec2(1e154, 0), Vec2(-1e300, 0)},
                                                  {Vec2(0, 0), Vec2(1, 0), Vec2(kInfinity, 0)},
                                                  {Vec2(0, 0), Vec2(1, 0), Vec2(-kInfinity, 0)}};
  for (const auto& [a, b, p] : cases) {
    const double got = PointToSegmentDistance(a, b, p);
    const double want = SegmentDistanceByDefinition(a, b, p);
    EXPECT_TRUE(got == want || (std::isnan(got) && std::isnan(want)))
        << got << " against " << want << " for a " << a.transpose() << " b " << b.transpose()
        << " p " << p.transpose();
  }
}

TEST(NormBelow, EqualsTheSquareRootTestEverywhere) {
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_real_distribution<double> limit_of(0.0, 2.0);
  for (int k = 0; k < 200000; ++k) {
    const double limit = limit_of(rng);
    // Half the vectors within a few ulps of the limit, where squares alone would misjudge.
    Vec2 d(unit(rng), unit(rng));
    if (k % 2 == 0 && d.norm() > 0.0) {
      d *= limit / d.norm();
      for (int u = k % 7 - 3; u != 0; u += u > 0 ? -1 : 1) {
        d.x() = std::nextafter(d.x(), u > 0 ? kInfinity : -kInfinity);
      }
    }
    ASSERT_EQ(NormBelow(d, limit), d.norm() < limit) << d.transpose() << " limit " << limit;
    ASSERT_EQ(NormAbove(d, limit), d.norm() > limit) << d.transpose() << " limit " << limit;
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Limits whose squares are subnormal or overflow, and a vector at each within an ulp or two.
  for (const double limit : {1e-160, 1.5e154, 1e300}) {
    for (int u = -2; u <= 2; ++u) {
      Vec2 d(limit * 0.6, limit * 0.8);
      d *= limit / d.norm();
      for (int step = u; step != 0; step += step > 0 ? -1 : 1) {
        d.y() = std::nextafter(d.y(), step > 0 ? kInfinity : -kInfinity);
      }
      EXPECT_EQ(NormBelow(d, limit), d.norm() < limit) << d.transpose() << " limit " << limit;
      EXPECT_EQ(NormAbove(d, limit), d.norm() > limit) << d.transpose() << " limit " << limit;
    }
  }
  for (const double limit : {0.0, -1.0, 0.3, kInfinity, nan}) {
    for (const Vec2& d : {Vec2(0, 0), Vec2(0.3, 0), Vec2(0, -0.3), Vec2(nan, 0), Vec2(kInfinity, 0),
                          Vec2(1e200, 1e200), Vec2(1e-200, 0)}) {
      EXPECT_EQ(NormBelow(d, limit), d.norm() < limit) << d.transpose() << " limit " << limit;
      EXPECT_EQ(NormAbove(d, limit), d.norm() > limit) << d.transpose() << " limit " << limit;
    }
  }
}

TEST(PointToRectDistance, InsideEdgeAndCorner) {
  EXPECT_EQ(PointToRectDistance(Vec2(2, 0), kBox), 0.0);
  EXPECT_EQ(PointToRectDistance(Vec2(3, 1), kBox), 0.0);  // on the corner
  EXPECT_NEAR(PointToRectDistance(Vec2(2, 3), kBox), 2.0, kEps);
  EXPECT_NEAR(PointToRectDistance(Vec2(0, 0), kBox), 1.0, kEps);
  EXPECT_NEAR(PointToRectDistance(Vec2(6, 5), kBox), 5.0, kEps);  // 3-4-5 from (3, 1)
}

TEST(DiscOverlapsRect, TouchingIsNotOverlapping) {
  EXPECT_TRUE(DiscOverlapsRect(Vec2(0, 0), 1.01, kBox));
  EXPECT_FALSE(DiscOverlapsRect(Vec2(0, 0), 1.0, kBox));
  EXPECT_TRUE(DiscOverlapsRect(Vec2(2, 0), 0.1, kBox));  // centre inside
  // Near a corner the rounded distance decides, not the bounding box.
  EXPECT_FALSE(DiscOverlapsRect(Vec2(3.5, 1.5), 0.7, kBox));
  EXPECT_TRUE(DiscOverlapsRect(Vec2(3.5, 1.5), 0.71, kBox));
}

TEST(RayRectDistance, HitsTheNearFace) {
  EXPECT_NEAR(RayRectDistance(Vec2(0, 0), Vec2(1, 0), kBox), 1.0, kEps);
  EXPECT_NEAR(RayRectDistance(Vec2(5, 0.5), Vec2(-1, 0), kBox), 2.0, kEps);
  EXPECT_NEAR(RayRectDistance(Vec2(2, 4), Vec2(0, -1), kBox), 3.0, kEps);
  const Vec2 diag = Vec2(1, 1).normalized();
  // From (0, -2) along 45 deg the ray meets the box exactly at its corner (1, -1).
  EXPECT_NEAR(RayRectDistance(Vec2(0, -2), diag, kBox), std::sqrt(2.0), kEps);
}

TEST(RayRectDistance, MissesAndBehind) {
  EXPECT_EQ(RayRectDistance(Vec2(0, 0), Vec2(-1, 0), kBox), kInfinity);
  EXPECT_EQ(RayRectDistance(Vec2(0, 2), Vec2(1, 0), kBox), kInfinity);
  EXPECT_EQ(RayRectDistance(Vec2(0, 0), Vec2(0, 1), kBox), kInfinity);  // parallel, outside
  // Just above the top-left corner (1, 1).
  EXPECT_EQ(RayRectDistance(Vec2(0, 0), Vec2(1, 1.01).normalized(), kBox), kInfinity);
}

TEST(RayRectDistance, GrazingEdgeCounts) {
  // Running along the top edge line touches the rectangle from x = 1.
  EXPECT_NEAR(RayRectDistance(Vec2(0, 1), Vec2(1, 0), kBox), 1.0, kEps);
}

TEST(RayRectDistance, ZeroInside) {
  EXPECT_EQ(RayRectDistance(Vec2(2, 0), Vec2(1, 0), kBox), 0.0);
  EXPECT_EQ(RayRectDistance(Vec2(1, 0), Vec2(-1, 0), kBox), 0.0);  // on the boundary
}

TEST(RayCircleDistance, HitMissInside) {
  EXPECT_NEAR(RayCircleDistance(Vec2(0, 0), Vec2(1, 0), Vec2(5, 0), 1.0), 4.0, kEps);
  // Offset by 0.6 with radius 1: chord half-length 0.8.
  EXPECT_NEAR(RayCircleDistance(Vec2(0, 0.6), Vec2(1, 0), Vec2(5, 0), 1.0), 4.2, kEps);
  EXPECT_NEAR(RayCircleDistance(Vec2(0, 1), Vec2(1, 0), Vec2(5, 0), 1.0), 5.0, kEps);  // tangent
  EXPECT_EQ(RayCircleDistance(Vec2(0, 1.01), Vec2(1, 0), Vec2(5, 0), 1.0), kInfinity);
  EXPECT_EQ(RayCircleDistance(Vec2(0, 0), Vec2(-1, 0), Vec2(5, 0), 1.0), kInfinity);
  EXPECT_EQ(RayCircleDistance(Vec2(5.5, 0), Vec2(1, 0), Vec2(5, 0), 1.0), 0.0);
}

TEST(SweptDiscRectTime, FaceContact) {
  // Centre moves from x = -2 to x = 2 at y = 0 with radius 0.5; contact when x = 0.5.
  EXPECT_NEAR(SweptDiscRectTime(Vec2(-2, 0), Vec2(2, 0), 0.5, kBox), 2.5 / 4.0, kContactEps);
}

TEST(SweptDiscRectTime, CornerContactIsRounded) {
  // Passing above the top-left corner (1, 1) at y = 1.3 with radius 0.5: the disc touches the
  // corner when its centre is 0.5 from it, i.e. at x = 1 - 0.4.
  const double t = SweptDiscRectTime(Vec2(-1.4, 1.3), Vec2(2.6, 1.3), 0.5, kBox);
  EXPECT_NEAR(t, 2.0 / 4.0, kContactEps);
  // At y = 1.6 > 1 + 0.5 it misses although the swept bounding box overlaps.
  EXPECT_EQ(SweptDiscRectTime(Vec2(-1.4, 1.6), Vec2(2.6, 1.6), 0.5, kBox), kInfinity);
}

TEST(SweptDiscRectTime, TouchingIsNotContact) {
  // Resting against the right face (x = 3) at exactly one radius, then leaving or sliding.
  EXPECT_EQ(SweptDiscRectTime(Vec2(3.5, 0), Vec2(4.5, 0), 0.5, kBox), kInfinity);
  EXPECT_EQ(SweptDiscRectTime(Vec2(3.5, -0.5), Vec2(3.5, 0.5), 0.5, kBox), kInfinity);
  EXPECT_EQ(SweptDiscRectTime(Vec2(3.5, 0), Vec2(3.5, 0), 0.5, kBox), kInfinity);
  // Moving in from the touching position is contact at once.
  EXPECT_NEAR(SweptDiscRectTime(Vec2(3.5, 0), Vec2(3.0, 0), 0.5, kBox), 0.0, 1e-8);
}

TEST(SweptDiscRectTime, ThinWallAtHighSpeedDoesNotTunnel) {
  const Rect wall = Rect::FromCorners(10.0, -5.0, 10.001, 5.0);
  const double t = SweptDiscRectTime(Vec2(0, 0), Vec2(1000, 0), 0.1, wall);
  EXPECT_NEAR(t, 9.9 / 1000.0, 2 * kContactEps / 1000.0);
  // Endpoints on both sides, neither overlapping.
  EXPECT_LT(SweptDiscRectTime(Vec2(9.0, 0), Vec2(11.0, 0), 0.1, wall), 1.0);
}

TEST(SweptDiscRectTime, OverlapAtStartIsZeroAndStopsShortIsInfinity) {
  EXPECT_EQ(SweptDiscRectTime(Vec2(0.8, 0), Vec2(-3, 0), 0.5, kBox), 0.0);
  EXPECT_EQ(SweptDiscRectTime(Vec2(-2, 0), Vec2(0.4, 0), 0.5, kBox), kInfinity);
  // Ending exactly touching the face is not contact.
  EXPECT_EQ(SweptDiscRectTime(Vec2(-2, 0), Vec2(0.5, 0), 0.5, kBox), kInfinity);
  EXPECT_NEAR(SweptDiscRectTime(Vec2(-2, 0), Vec2(0.51, 0), 0.5, kBox), 2.5 / 2.51, kContactEps);
  EXPECT_EQ(SweptDiscRectTime(Vec2(0, 0), Vec2(0, 0), 0.5, kBox), kInfinity);
  EXPECT_EQ(SweptDiscRectTime(Vec2(0.9, 0), Vec2(0.9, 0), 0.5, kBox), 0.0);
}

// The swept time agrees with dense sampling of the distance along the motion.
TEST(SweptDiscRectTime, MatchesSampling) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-4.0, 6.0);
  int hits = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const Vec2 a(u(rng), u(rng));
    const Vec2 b(u(rng), u(rng));
    const double radius = 0.3;
    const double t = SweptDiscRectTime(a, b, radius, kBox);
    constexpr int kSamples = 4000;
    double first = kInfinity;
    for (int i = 0; i <= kSamples; ++i) {
      const double s = static_cast<double>(i) / kSamples;
      if (PointToRectDistance(a + s * (b - a), kBox) <= radius) {
        first = s;
        break;
      }
    }
    if (first == kInfinity) {
      // Sampling can miss a graze; the exact time then has to be a near-tangent contact.
      if (t != kInfinity) {
        const Vec2 p = a + t * (b - a);
        EXPECT_NEAR(PointToRectDistance(p, kBox), radius, 1e-9);
      }
      continue;
    }
    ++hits;
    ASSERT_NE(t, kInfinity) << trial;
    EXPECT_LE(t, first + 1e-12) << trial;
    EXPECT_GE(t, first - 1.0 / kSamples - 1e-12) << trial;
  }
  EXPECT_GT(hits, 50);
}

}  // namespace
}  // namespace crowdsim
