// Random rectangle rooms: the generator's rules and the navigability checks.
#include "rect_layout.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "free_raster.h"

namespace crowdsim::random_rect {
namespace {

constexpr double kEps = 1e-9;

// Gap between two rectangles along the axis that separates them (negative if they overlap).
double AxisGap(const Rect& a, const Rect& b) {
  const double gx = std::max(a.min.x() - b.max.x(), b.min.x() - a.max.x());
  const double gy = std::max(a.min.y() - b.max.y(), b.min.y() - a.max.y());
  return std::max(gx, gy);
}

void ExpectLayoutRules(const WorldFile& w, const RectLayoutConfig& c) {
  ASSERT_EQ(static_cast<int>(w.rectangles.size()), kWallCount + c.obstacles) << w.name;
  const WorldFile empty = EmptyRoom(c, w.name);
  EXPECT_EQ(w.bounds, empty.bounds);
  for (int i = 0; i < kWallCount; ++i) EXPECT_EQ(w.rectangles[i], empty.rectangles[i]);
  const double h = 0.5 * c.room_size;
  for (int i = kWallCount; i < static_cast<int>(w.rectangles.size()); ++i) {
    const Rect& r = w.rectangles[i];
    for (double side : {r.Size().x(), r.Size().y()}) {
      EXPECT_GE(side, c.min_side - kEps) << w.name;
      EXPECT_LE(side, c.max_side + kEps) << w.name;
    }
    EXPECT_GE(r.min.x(), -h + c.wall_margin - kEps) << w.name;
    EXPECT_GE(r.min.y(), -h + c.wall_margin - kEps) << w.name;
    EXPECT_LE(r.max.x(), h - c.wall_margin + kEps) << w.name;
    EXPECT_LE(r.max.y(), h - c.wall_margin + kEps) << w.name;
    for (int j = kWallCount; j < i; ++j) {
      EXPECT_GE(AxisGap(r, w.rectangles[j]), c.obstacle_margin - kEps) << w.name;
    }
  }
  const FreeRaster raster(w.ToStaticMap(), RoomRegion(c), c.agent_radius, c.raster_resolution);
  EXPECT_EQ(raster.ComponentCount(), 1) << w.name;
  EXPECT_TRUE(raster.HasPairAtLeast(c.min_start_goal_dist, 4)) << w.name;
}

TEST(RectLayout, EmptyRoomIsTenByTenInsideItsWalls) {
  const RectLayoutConfig c;
  const WorldFile w = EmptyRoom(c, "rect0");
  EXPECT_EQ(w.bounds, Rect::FromCorners(-5.5, -5.5, 5.5, 5.5));
  ASSERT_EQ(w.rectangles.size(), 4u);
  double wall_area = 0.0;
  for (const Rect& r : w.rectangles) {
    wall_area += r.Area();
    EXPECT_FALSE(r.Overlaps(RoomRegion(c))) << "walls lie outside the room";
  }
  EXPECT_NEAR(wall_area, 11.0 * 11.0 - 100.0, 1e-9);  // the walls cover exactly the rim
}

TEST(RectLayout, GeneratedLayoutsFollowTheRules) {
  for (int obstacles : {0, 1, 2, 3}) {
    RectLayoutConfig c;
    c.obstacles = obstacles;
    const int count = obstacles == 3 ? 10 : 25;
    RectLayoutStats stats;
    for (int k = 0; k < count; ++k) {
      Rng rng(1000 * obstacles + k);
      ExpectLayoutRules(GenerateLayout(c, "t", rng, &stats), c);
    }
    EXPECT_EQ(stats.layouts, count);
    EXPECT_EQ(stats.side_count, 2 * obstacles * count);
  }
}

TEST(RectLayout, SidesCoverTheirRangeWithOneObstacle) {
  // One obstacle always fits, so its sides are plain uniform draws in [3, 6].
  RectLayoutConfig c;
  RectLayoutStats stats;
  double lo = 10.0, hi = 0.0;
  for (int k = 0; k < 400; ++k) {
    Rng rng(k);
    const WorldFile w = GenerateLayout(c, "t", rng, &stats);
    const Vec2 s = w.rectangles[kWallCount].Size();
    lo = std::min({lo, s.x(), s.y()});
    hi = std::max({hi, s.x(), s.y()});
  }
  EXPECT_EQ(stats.attempts, 400);
  EXPECT_LT(lo, 3.1);
  EXPECT_GT(hi, 5.9);
  EXPECT_NEAR(stats.MeanSide(), 4.5, 0.15);
}

TEST(RectLayout, MarginsAndSizesAreParameters) {
  RectLayoutConfig c;
  c.obstacles = 2;
  c.min_side = 1.0;
  c.max_side = 2.0;
  c.wall_margin = 0.7;
  c.obstacle_margin = 1.5;
  for (int k = 0; k < 20; ++k) {
    Rng rng(k);
    ExpectLayoutRules(GenerateLayout(c, "t", rng), c);
  }
}

TEST(RectLayout, SameSeedSameLayout) {
  RectLayoutConfig c;
  c.obstacles = 3;
  Rng a(99), b(99), d(100);
  const WorldFile wa = GenerateLayout(c, "t", a);
  const WorldFile wb = GenerateLayout(c, "t", b);
  const WorldFile wd = GenerateLayout(c, "t", d);
  EXPECT_EQ(wa.rectangles, wb.rectangles);
  EXPECT_NE(wa.rectangles, wd.rectangles);
}

TEST(RectLayout, DisconnectedFreeSpaceIsRejected) {
  const RectLayoutConfig c;
  WorldFile w = EmptyRoom(c, "split");
  w.rectangles.push_back(Rect::FromCorners(-0.5, -5.0, 0.5, 5.0));  // wall to wall
  RectLayoutStats stats;
  EXPECT_FALSE(LayoutIsNavigable(w, c, &stats));
  EXPECT_EQ(stats.rejected_disconnected, 1);

  // A gap narrower than the disc's diameter splits the room too.
  WorldFile narrow = EmptyRoom(c, "narrow");
  narrow.rectangles.push_back(Rect::FromCorners(-0.5, -4.5, 0.5, 5.0));
  EXPECT_FALSE(LayoutIsNavigable(narrow, c));
  // ...and one wider than it does not.
  WorldFile wide = EmptyRoom(c, "wide");
  wide.rectangles.push_back(Rect::FromCorners(-0.5, -4.2, 0.5, 5.0));
  EXPECT_TRUE(LayoutIsNavigable(wide, c));

  // A closed pocket is a second component.
  WorldFile pocket = EmptyRoom(c, "pocket");
  pocket.rectangles.push_back(Rect::FromCorners(-3, -3, 3, -2.5));
  pocket.rectangles.push_back(Rect::FromCorners(-3, 2.5, 3, 3));
  pocket.rectangles.push_back(Rect::FromCorners(-3, -2.5, -2.5, 2.5));
  pocket.rectangles.push_back(Rect::FromCorners(2.5, -2.5, 3, 2.5));
  EXPECT_FALSE(LayoutIsNavigable(pocket, c));
}

TEST(RectLayout, RoomWithoutALongTripIsRejected) {
  const RectLayoutConfig c;
  WorldFile w = EmptyRoom(c, "small");
  // Free: [-5, 1] x [1, 5], whose disc-free part has a diagonal under 7 m.
  w.rectangles.push_back(Rect::FromCorners(-5, -5, 5, 1));
  w.rectangles.push_back(Rect::FromCorners(1, 1, 5, 5));
  RectLayoutStats stats;
  EXPECT_FALSE(LayoutIsNavigable(w, c, &stats));
  EXPECT_EQ(stats.rejected_no_pair, 1);
  EXPECT_EQ(stats.rejected_disconnected, 0);
}

TEST(RectLayout, ImpossibleRulesAreClearErrors) {
  RectLayoutConfig c;
  c.max_side = 9.0;
  EXPECT_THROW(c.Validate(), std::invalid_argument);
  c = RectLayoutConfig{};
  c.obstacles = 6;
  c.max_layout_tries = 200;
  Rng rng(1);
  try {
    GenerateLayout(c, "crowded", rng);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("crowded"), std::string::npos);
  }
}

TEST(FreeRaster, CountsFreeAreaOfAnEmptyRoom) {
  const RectLayoutConfig c;
  const WorldFile w = EmptyRoom(c, "rect0");
  const FreeRaster raster(w.ToStaticMap(), RoomRegion(c), 0.3, 0.05);
  EXPECT_EQ(raster.rows(), 200);
  EXPECT_EQ(raster.cols(), 200);
  EXPECT_NEAR(raster.FreeArea(), 9.4 * 9.4, 0.5);
  EXPECT_EQ(raster.ComponentCount(), 1);
  EXPECT_TRUE(raster.HasPairAtLeast(12.5, 4));
  EXPECT_FALSE(raster.HasPairAtLeast(13.5, 3));
}

}  // namespace
}  // namespace crowdsim::random_rect
