// The grid over boxes that the roadmap uses for the clearance of points: exactly the boxes a
// plain scan keeps, and with it the same roadmap answers as without it.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
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

}  // namespace
}  // namespace crowdsim::orca
