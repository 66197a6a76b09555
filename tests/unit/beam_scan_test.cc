// The lidar's beam kernel: four beams at a time in AVX2 lanes gives the very bits of one beam at
// a time, on random scenes and on the cases a slab or root test gets wrong first (beams along
// an axis, an origin on an edge or inside a shape, grazing beams, groups of fewer than four).
#include "beam_scan.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "crowdsim/vector_units.h"

namespace crowdsim {
namespace {

struct Scene {
  std::vector<Vec2> directions;
  std::vector<RelRect> rects;
  std::vector<RelDisc> discs;
};

RelDisc Disc(double cx, double cy, double radius) {
  return {cx, cy, cx * cx + cy * cy - radius * radius};
}

// Both kernels on the scene; every range equal to the bit (a -0 is not a +0 here).
void ExpectSameBits(const Scene& s, double max_range, const std::string& what) {
  std::vector<double> scalar(s.directions.size(), -1.0);
  std::vector<double> lanes(s.directions.size(), -1.0);
  ScanBeamsScalar(s.directions, max_range, s.rects, s.discs, scalar.data());
  ScanBeamsAvx2(s.directions, max_range, s.rects, s.discs, lanes.data());
  for (std::size_t k = 0; k < scalar.size(); ++k) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(scalar[k]), std::bit_cast<std::uint64_t>(lanes[k]))
        << what << ", beam " << k << " of " << scalar.size() << ": scalar " << scalar[k]
        << ", AVX2 " << lanes[k];
  }
}

std::vector<Vec2> Fan(int beams, double first, double last) {
  std::vector<Vec2> out;
  for (int k = 0; k < beams; ++k) {
    const double a = beams == 1 ? first : first + (last - first) * k / (beams - 1);
    out.emplace_back(std::cos(a), std::sin(a));
  }
  return out;
}

class BeamScanTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!HaveAvx2()) GTEST_SKIP() << "this processor runs no AVX2: the scalar path is the only one";
  }
};

// The scalar kernel on any processor; the comparison with the AVX2 one where it runs.
TEST(BeamScanScalar, MeasuresWhatTheGeometrySays) {
  // A wall 2 m ahead (x in [2, 3]), a disc of radius 0.5 at (0, 4), beams +x, +y, -x.
  Scene s{{Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0)}, {{2, -1, 3, 1}}, {Disc(0, 4, 0.5)}};
  std::vector<double> r(3);
  ScanBeamsScalar(s.directions, 5.0, s.rects, s.discs, r.data());
  EXPECT_DOUBLE_EQ(r[0], 2.0);
  EXPECT_DOUBLE_EQ(r[1], 3.5);
  EXPECT_DOUBLE_EQ(r[2], 5.0);
  if (HaveAvx2()) ExpectSameBits(s, 5.0, "wall, disc, nothing");
}

TEST_F(BeamScanTest, RandomScenesGiveTheSameBits) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pos(-6.0, 6.0);
  std::uniform_real_distribution<double> size(0.05, 2.0);
  std::uniform_int_distribution<int> count(0, 12);
  for (int trial = 0; trial < 300; ++trial) {
    Scene s;
    const int beams = 1 + trial % 47;  // every group size, 45 as the lidar's default
    s.directions = Fan(beams, -0.5 * std::numbers::pi, 0.5 * std::numbers::pi + 0.01 * trial);
    for (int i = count(rng); i > 0; --i) {
      const double x = pos(rng), y = pos(rng);
      s.rects.push_back({x, y, x + size(rng), y + size(rng)});
    }
    for (int i = count(rng); i > 0; --i) s.discs.push_back(Disc(pos(rng), pos(rng), size(rng)));
    ExpectSameBits(s, 5.0, "random scene " + std::to_string(trial));
  }
}

// Values no sensor makes but a kernel must not part on: infinities, NaNs, signed zeros,
// subnormals and huge numbers in every field of the rectangles, discs and beams, drawn at
// random (each operand order of a min or max, each miss condition, shows here).
TEST_F(BeamScanTest, SpecialValuesGiveTheSameBits) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double sub = std::numeric_limits<double>::denorm_min();
  const std::vector<double> special = {0.0, -0.0, 1.0,  -1.0,  0.5,    -2.0, inf,   -inf,
                                       nan, sub,  -sub, 1e308, -1e308, 3.0,  -0.25, 2.0};
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<std::size_t> pick(0, special.size() - 1);
  std::uniform_int_distribution<int> count(0, 4);
  const auto any = [&] { return special[pick(rng)]; };
  for (int trial = 0; trial < 4000; ++trial) {
    Scene s;
    for (int k = 1 + trial % 9; k > 0; --k) s.directions.emplace_back(any(), any());
    for (int i = count(rng); i > 0; --i) s.rects.push_back({any(), any(), any(), any()});
    for (int i = count(rng); i > 0; --i) s.discs.push_back({any(), any(), any()});
    ExpectSameBits(s, trial % 2 == 0 ? 5.0 : any(), "special scene " + std::to_string(trial));
    if (HasFailure()) break;  // one scene's report is enough
  }
}

TEST_F(BeamScanTest, AxisBeamsEdgesInsidesAndGrazesGiveTheSameBits) {
  // Beams exactly along the axes (a zero component, of either sign) and between them.
  const std::vector<Vec2> axes = {Vec2(1, 0),     Vec2(0, 1),      Vec2(-1, 0),
                                  Vec2(0, -1),    Vec2(1, -0.0),   Vec2(-0.0, 1),
                                  Vec2(0.6, 0.8), Vec2(-0.8, 0.6), Vec2(0.6, -0.8)};
  const std::vector<RelRect> rects = {
      {0, -1, 1, 1},           // the origin on its left edge
      {-1, 0, 1, 1},           // on its bottom edge
      {-1, -1, 0, 0},          // on its corner
      {-0.5, -0.5, 0.5, 0.5},  // around the origin
      {1, 0, 2, 1},            // a beam along +x grazes its bottom edge
      {-3, -2, -2, 2},         // behind a +x beam
      {2, 2, 2, 3},            // no width
      {0.5, 4.9, 0.6, 5.1},    // at the end of the range
      {-0.0, -1, 1, 1},        // edges at a negative zero: hits at -0, which
      {-1, -1, -0.0, -0.0},    // min and max keep only in the scalar operand order
      {0.0, -1, -0.0, 1},      // no width, its two edges at zeros of both signs
      {0.0, -0.0, 1, 1}};      // corner at the origin: slabs entered at +0 and -0
  const std::vector<RelDisc> discs = {Disc(0, 0, 0.3), Disc(2, 0.5, 0.5), Disc(0, -2, 1),
                                      Disc(3, 3, 0.1), Disc(-1, 0, 1),    Disc(0.6, 0.8, 0)};
  for (std::size_t i = 0; i < rects.size(); ++i) {
    ExpectSameBits({axes, {rects[i]}, {}}, 5.0, "rectangle " + std::to_string(i));
  }
  for (std::size_t i = 0; i < discs.size(); ++i) {
    ExpectSameBits({axes, {}, {discs[i]}}, 5.0, "disc " + std::to_string(i));
  }
  ExpectSameBits({axes, rects, discs}, 5.0, "all together");
  ExpectSameBits({axes, {rects[8]}, {discs[0]}}, 5.0, "a hit at -0, then a disc around the origin");
  ExpectSameBits({axes, {rects[9], rects[8]}, {}}, 5.0, "two hits at -0");
  ExpectSameBits({axes, {rects[10]}, {}}, 5.0, "edges at +0 and -0");
  ExpectSameBits({axes, {rects[11]}, {}}, 5.0, "slabs entered at +0 and -0");
  // A disc of undefined centre (not a finite input): the scalar kernel passes over it.
  const RelDisc undefined{std::nan(""), 1.0, 1.0};
  ExpectSameBits({axes, {rects[0]}, {undefined, discs[1]}}, 5.0, "a NaN disc");
  ExpectSameBits({axes, {}, {}}, 5.0, "nothing to meet");
  ExpectSameBits({{}, rects, discs}, 5.0, "no beams");
}

// The culls keep exactly the rectangles (or their indices) a closed-box test keeps, in order, in
// either kernel: shared edges and corners touch, a gap of one ulp does not.
TEST_F(BeamScanTest, CullKeepsTheTouchingRectanglesInOrder) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> pos(-6.0, 6.0), size(0.0, 3.0);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<RelRect> rects;
    const double bx = pos(rng), by = pos(rng);
    const RelRect box{bx, by, bx + size(rng), by + size(rng)};
    for (int i = 0; i < 1 + trial % 40; ++i) {
      const double x = pos(rng), y = pos(rng);
      RelRect r{x, y, x + size(rng), y + size(rng)};
      if (i % 6 == 1) r.x1 = box.x0;                             // touching the box's left edge
      if (i % 6 == 2) r.y0 = std::nextafter(box.y1, kInfinity);  // one ulp above it
      if (i % 6 == 3) r = box;
      rects.push_back(r);
    }
    std::vector<RelRect> expected;
    std::vector<int> expected_ids;
    for (std::size_t i = 0; i < rects.size(); ++i) {
      const RelRect& r = rects[i];
      if (r.x0 <= box.x1 && box.x0 <= r.x1 && r.y0 <= box.y1 && box.y0 <= r.y1) {
        expected.push_back(r);
        expected_ids.push_back(static_cast<int>(i));
      }
    }
    for (const auto cull : {&RectsTouchingScalar, &RectsTouchingAvx2, &RectsTouching}) {
      std::vector<RelRect> out(rects.size());
      const std::size_t kept = cull(rects, box, out.data());
      ASSERT_EQ(kept, expected.size()) << "trial " << trial;
      for (std::size_t k = 0; k < kept; ++k) {
        EXPECT_EQ(out[k].x0, expected[k].x0);
        EXPECT_EQ(out[k].y1, expected[k].y1);
      }
    }
    for (const auto cull : {&RectIdsTouchingScalar, &RectIdsTouchingAvx2, &RectIdsTouching}) {
      std::vector<int> ids(rects.size());
      ids.resize(cull(rects, box, ids.data()));
      EXPECT_EQ(ids, expected_ids) << "trial " << trial;
    }
  }
}

// The sight lines' query, culled in fours (many rectangles) or not (few), in either kernel pair
// and dispatched, blocks exactly the lines a one-beam scan along each finds blocked before
// their end; lines along an axis, ending on a corner and of zero length included.
TEST_F(BeamScanTest, SightLinesBlockWhereAOneBeamScanHitsFirst) {
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> pos(-6.0, 6.0), size(0.0, 2.0);
  int blocked_lines = 0, clear_lines = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<RelRect> rects;
    for (int i = 0; i < 1 + trial % 20; ++i) {
      const double x = pos(rng), y = pos(rng);
      rects.push_back({x, y, x + size(rng), y + size(rng)});
    }
    std::vector<Vec2> offsets, directions;
    std::vector<double> lengths;
    for (int k = 0; k < 1 + trial % 23; ++k) {
      Vec2 end(pos(rng), pos(rng));
      if (k % 5 == 1) end.x() = 0.0;  // along the y axis
      if (k % 7 == 2) end = Vec2(rects[0].x0, rects[0].y1);
      if (k % 11 == 3) end = Vec2::Zero();
      offsets.push_back(end);
      lengths.push_back(end.norm());
      directions.push_back(lengths.back() > 0.0 ? Vec2(end / lengths.back()) : Vec2(1.0, 0.0));
    }
    std::vector<std::uint8_t> expected(offsets.size());
    for (std::size_t k = 0; k < offsets.size(); ++k) {
      double range = 0.0;
      ScanBeamsScalar(std::span<const Vec2>(&directions[k], 1), lengths[k] + 1.0, rects, {},
                      &range);
      expected[k] = range < lengths[k] ? 1 : 0;
      (expected[k] ? blocked_lines : clear_lines) += 1;
    }
    for (const auto scan : {&ScanSightLinesScalar, &ScanSightLinesAvx2, &ScanSightLines}) {
      std::vector<RelRect> near(rects.size());
      std::vector<std::uint8_t> blocked(offsets.size(), 2);
      scan(offsets, directions, lengths.data(), rects, near.data(), blocked.data());
      EXPECT_EQ(blocked, expected) << "trial " << trial << ", " << rects.size() << " rectangles";
    }
  }
  EXPECT_GT(blocked_lines, 300);
  EXPECT_GT(clear_lines, 300);
}

TEST(BeamScanDispatch, TheChosenKernelGivesTheScalarBits) {
  Scene s{Fan(45, -0.5 * std::numbers::pi, 0.5 * std::numbers::pi),
          {{1, -2, 1.5, 2}, {-2, 1, 2, 1.2}},
          {Disc(0.5, 0.5, 0.3), Disc(-1, -1, 0.4)}};
  std::vector<double> scalar(45), chosen(45);
  ScanBeamsScalar(s.directions, 5.0, s.rects, s.discs, scalar.data());
  ScanBeams(s.directions, 5.0, s.rects, s.discs, chosen.data());
  for (std::size_t k = 0; k < scalar.size(); ++k) {
    EXPECT_EQ(std::bit_cast<std::uint64_t>(scalar[k]), std::bit_cast<std::uint64_t>(chosen[k]))
        << "beam " << k;
  }
}

}  // namespace
}  // namespace crowdsim
