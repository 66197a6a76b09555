// The grid over boxes that the roadmap uses for the clearance of points: exactly the boxes a
// plain scan keeps, and with it the same roadmap answers as without it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "crowdsim/rng.h"
#include "orca/geometry.h"
#include "orca/rect_index.h"
#include "orca/roadmap.h"

namespace crowdsim::orca {
namespace {

bool Touches(const Rect& a, const Rect& b) {
  return a.min.x() <= b.max.x() && b.min.x() <= a.max.x() && a.min.y() <= b.max.y() &&
         b.min.y() <= a.max.y();
}

// Boxes on a 0.5 m lattice (shared sides and corners), thin and zero-size ones, long walls and
// a few with their corners swapped.
std::vector<Rect> RandomBoxes(Rng& rng, int n) {
  std::vector<Rect> boxes;
  for (int i = 0; i < n; ++i) {
    const double x = 0.5 * static_cast<double>(rng.Below(40)) - 10.0;
    const double y = 0.5 * static_cast<double>(rng.Below(40)) - 10.0;
    const double w = i % 7 == 0 ? 0.0 : (i % 11 == 0 ? 15.0 : rng.Uniform(0.0, 2.0));
    const double h = i % 5 == 0 ? 0.0 : rng.Uniform(0.0, 2.0);
    boxes.push_back(i % 13 == 0 ? Rect::FromCorners(x + w, y + h, x, y)
                                : Rect::FromCorners(x, y, x + w, y + h));
  }
  return boxes;
}

TEST(RectIndex, QueryKeepsWhatAScanKeeps) {
  Rng rng(21);
  for (int trial = 0; trial < 30; ++trial) {
    const auto boxes = RandomBoxes(rng, 1 + static_cast<int>(rng.Below(150)));
    const RectIndex index(boxes);
    std::vector<int> got;
    for (int q = 0; q < 60; ++q) {
      const double x =
          q % 3 == 0 ? 0.5 * static_cast<double>(rng.Below(50)) - 12.0 : rng.Uniform(-15, 15);
      const double y = rng.Uniform(-15, 15);
      const double w = q % 4 == 0 ? 0.0 : rng.Uniform(0, 8), h = rng.Uniform(0, 8);
      const Rect query = Rect::FromCorners(x, y, x + w, y + h);
      std::vector<int> expected;
      for (int i = 0; i < static_cast<int>(boxes.size()); ++i) {
        if (Touches(boxes[i], query)) expected.push_back(i);
      }
      index.Query(query, &got);
      SCOPED_TRACE("trial " + std::to_string(trial) + " query " + std::to_string(q));
      EXPECT_EQ(got, expected);
    }
  }
  RectIndex empty;
  std::vector<int> got{3};
  empty.Query(Rect::FromCorners(0, 0, 1, 1), &got);
  EXPECT_TRUE(got.empty());
}

// The roadmap's visibility through the index equals SegmentClear over every rectangle.
TEST(RectIndex, RoadmapVisibilityMatchesAScanOfEveryRectangle) {
  Rng rng(8);
  const auto boxes = RandomBoxes(rng, 80);
  const double clearance = 0.4;
  const Roadmap roadmap(boxes, Rect{}, clearance, 0.1);
  for (int q = 0; q < 400; ++q) {
    const Vec2 a(rng.Uniform(-12, 12), rng.Uniform(-12, 12));
    const Vec2 b = q % 2 == 0 ? Vec2(rng.Uniform(-12, 12), rng.Uniform(-12, 12))
                              : Vec2(a + Vec2(rng.Uniform(-2, 2), rng.Uniform(-2, 2)));
    const double c = std::min({clearance, DistanceToRects(boxes, a), DistanceToRects(boxes, b)});
    EXPECT_EQ(roadmap.Visible(a, b), SegmentClear(boxes, a, b, std::max(0.0, c - 1e-9)))
        << "query " << q;
  }
}

// SegmentClear against its definition, every rectangle's exact distance (its bounding-box cull
// may only skip work): random segments, and segments along a side or past a corner of one box
// at the clearance give or take 1e-12 m, 1e-9 m and 1e-6 m, where any cull of the segment's
// surroundings with too thin a margin answers wrongly (a cull of boxes beyond the segment's line
// by clearance - 1e-9 fails here).
TEST(RectIndex, SegmentClearMatchesTheDistanceToEveryRectangle) {
  Rng rng(12);
  // Rectangles as maps hold them (min <= max; the generator's swapped corners left out: the
  // bounding-box cull has never seen those as boxes).
  std::vector<Rect> boxes;
  for (const Rect& r : RandomBoxes(rng, 70)) {
    if (r.min.x() <= r.max.x() && r.min.y() <= r.max.y()) boxes.push_back(r);
  }
  auto by_definition = [](std::span<const Rect> rects, const Vec2& a, const Vec2& b, double c) {
    return std::all_of(rects.begin(), rects.end(), [&](const Rect& r) {
      const double d = SegmentRectDistance(a, b, r);
      return !(d < c || d == 0.0);
    });
  };
  int checked = 0, clear = 0;
  auto check = [&](std::span<const Rect> rects, const Vec2& a, const Vec2& b, double c) {
    const bool expected = by_definition(rects, a, b, c);
    EXPECT_EQ(SegmentClear(rects, a, b, c), expected)
        << "a (" << a.x() << ", " << a.y() << ") b (" << b.x() << ", " << b.y() << ") c " << c;
    ++checked;
    clear += expected ? 1 : 0;
    return expected;
  };
  for (int q = 0; q < 1000; ++q) {
    const Vec2 a(rng.Uniform(-12, 12), rng.Uniform(-12, 12));
    const Vec2 b = q % 2 == 0 ? Vec2(rng.Uniform(-12, 12), rng.Uniform(-12, 12))
                              : Vec2(a + Vec2(rng.Uniform(-3, 3), rng.Uniform(-3, 3)));
    check(boxes, a, b, q % 7 == 0 ? 0.0 : rng.Uniform(0.0, 0.6));
  }
  // One box alone, passed at the clearance give or take: blocked below it, clear above.
  const Rect box = Rect::FromCorners(2.25, -1.5, 3.5, 0.75);
  const std::span<const Rect> one(&box, 1);
  const double c = 0.37;
  for (double off : {-1e-6, -1e-9, -1e-12, 1e-12, 1e-9, 1e-6}) {
    SCOPED_TRACE("off " + std::to_string(off));
    // Along the top side, at c + off above it, longer than the box on both ends.
    const double y = box.max.y() + c + off;
    EXPECT_EQ(check(one, Vec2(box.min.x() - 4.0, y), Vec2(box.max.x() + 4.0, y), c), off > 0.0);
    // Slanted past the top-right corner, at c + off from it.
    const Vec2 n = Vec2(1.0, 1.0).normalized();
    const Vec2 touch = box.max + (c + off) * n;
    const Vec2 along(-n.y(), n.x());
    EXPECT_EQ(check(one, touch - 5.0 * along, touch + 5.0 * along, c), off > 0.0);
  }
  EXPECT_GT(clear, 100);
  EXPECT_LT(clear, checked - 100);
}

// A blocker hint only changes which rectangle is tested first: the answers are SegmentClear's
// without a hint, whatever the hint (none, stale, out of range, kept from call to call), and a
// rectangle reported as the blocker does block the segment.
TEST(RectIndex, SegmentClearAnswersTheSameWhateverTheBlockerHint) {
  Rng rng(5);
  const auto boxes = RandomBoxes(rng, 60);
  const int n = static_cast<int>(boxes.size());
  int kept = -1;
  int blocked = 0;
  for (int q = 0; q < 600; ++q) {
    const Vec2 a(rng.Uniform(-12, 12), rng.Uniform(-12, 12));
    const Vec2 b = q % 2 == 0 ? Vec2(rng.Uniform(-12, 12), rng.Uniform(-12, 12))
                              : Vec2(a + Vec2(rng.Uniform(-2, 2), rng.Uniform(-2, 2)));
    const double c = q % 5 == 0 ? 0.0 : rng.Uniform(0.0, 0.6);
    const bool expected = SegmentClear(boxes, a, b, c);
    blocked += expected ? 0 : 1;
    for (int hint : {-1, static_cast<int>(rng.Below(static_cast<std::uint64_t>(n))), n + 3, kept}) {
      int blocker = hint;
      SCOPED_TRACE("query " + std::to_string(q) + " hint " + std::to_string(hint));
      EXPECT_EQ(SegmentClear(boxes, a, b, c, &blocker), expected);
      if (!expected) {
        ASSERT_GE(blocker, 0);
        ASSERT_LT(blocker, n);
        EXPECT_FALSE(SegmentClear(std::span<const Rect>(&boxes[blocker], 1), a, b, c));
      } else {
        EXPECT_EQ(blocker, hint);  // a clear segment leaves the hint alone
      }
    }
    SegmentClear(boxes, a, b, c, &kept);
  }
  EXPECT_GT(blocked, 100);  // both answers are exercised
  EXPECT_LT(blocked, 500);
}

// The roadmap's visibility with a hint kept between calls, as an agent's guidance keeps it.
TEST(RectIndex, RoadmapVisibilityIgnoresTheBlockerHint) {
  Rng rng(9);
  const auto boxes = RandomBoxes(rng, 80);
  const Roadmap roadmap(boxes, Rect{}, 0.4, 0.1);
  int blocker = -1;
  const Vec2 from(0.3, -0.2);
  for (int q = 0; q < 400; ++q) {
    const Vec2 a = q % 3 == 0 ? from : Vec2(rng.Uniform(-12, 12), rng.Uniform(-12, 12));
    const Vec2 b(rng.Uniform(-12, 12), rng.Uniform(-12, 12));
    const double ca = roadmap.CappedClearance(a), cb = roadmap.CappedClearance(b);
    EXPECT_EQ(roadmap.Visible(a, ca, b, cb, &blocker), roadmap.Visible(a, ca, b, cb))
        << "query " << q;
  }
}

}  // namespace
}  // namespace crowdsim::orca
