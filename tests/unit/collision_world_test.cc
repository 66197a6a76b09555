#include "crowdsim/collision_world.h"

#include <gtest/gtest.h>

#include <random>
#include <thread>

namespace crowdsim {
namespace {

std::shared_ptr<const StaticMap> MakeMap(std::vector<Rect> rects) {
  auto map = std::make_shared<StaticMap>();
  map->name = "test";
  map->bounds = Rect::FromCorners(-10, -10, 10, 10);
  map->rectangles = std::move(rects);
  return map;
}

// A 10 x 10 room with 0.1 m thick walls, a box and a 1 mm thin wall.
std::shared_ptr<const StaticMap> Room() {
  return MakeMap({
      Rect::FromCorners(-5.0, -5.0, 5.0, -4.9),    // 0 bottom
      Rect::FromCorners(-5.0, 4.9, 5.0, 5.0),      // 1 top
      Rect::FromCorners(-5.0, -5.0, -4.9, 5.0),    // 2 left
      Rect::FromCorners(4.9, -5.0, 5.0, 5.0),      // 3 right
      Rect::FromCorners(1.0, 1.0, 2.0, 3.0),       // 4 box
      Rect::FromCorners(-2.0, -3.0, -1.999, 3.0),  // 5 thin wall
  });
}

TEST(CollisionWorld, QueryRectsReturnsSortedOverlaps) {
  CollisionWorld world(Room());
  std::vector<int> ids;
  world.QueryRects(Rect::FromCorners(0.0, 0.0, 1.5, 1.5), &ids);
  EXPECT_EQ(ids, (std::vector<int>{4}));
  world.QueryRects(Rect::FromCorners(-6.0, -6.0, 6.0, 6.0), &ids);
  EXPECT_EQ(ids, (std::vector<int>{0, 1, 2, 3, 4, 5}));
  world.QueryRects(Rect::FromCorners(4.0, 4.0, 6.0, 6.0), &ids);
  EXPECT_EQ(ids, (std::vector<int>{1, 3}));
  world.QueryRects(Rect::FromCorners(-1.0, -1.0, 0.5, 0.5), &ids);
  EXPECT_TRUE(ids.empty());
  // Within the broadphase's float padding but outside in exact arithmetic.
  world.QueryRects(Rect::FromCorners(2.0005, 1.5, 3.0, 2.0), &ids);
  EXPECT_TRUE(ids.empty());
  // Touching counts (closed boxes), so that culling keeps grazing contacts.
  world.QueryRects(Rect::FromCorners(2.0, 1.5, 3.0, 2.0), &ids);
  EXPECT_EQ(ids, (std::vector<int>{4}));
}

TEST(CollisionWorld, DiscOverlaps) {
  CollisionWorld world(Room());
  EXPECT_FALSE(world.DiscOverlaps(Vec2(0, 0), 0.3));
  EXPECT_TRUE(world.DiscOverlaps(Vec2(0.8, 2.0), 0.3));   // 0.2 from the box's left face
  EXPECT_FALSE(world.DiscOverlaps(Vec2(0.6, 2.0), 0.3));  // 0.4 from it
  EXPECT_TRUE(world.DiscOverlaps(Vec2(4.7, 0.0), 0.3));   // 0.2 from the right wall
  EXPECT_TRUE(world.DiscOverlaps(Vec2(1.5, 2.0), 0.1));   // centre inside the box
  // Rounded corner: (2.2, 3.2) is sqrt(0.08) = 0.283 from the corner (2, 3).
  EXPECT_FALSE(world.DiscOverlaps(Vec2(2.2, 3.2), 0.28));
  EXPECT_TRUE(world.DiscOverlaps(Vec2(2.2, 3.2), 0.29));
}

TEST(CollisionWorld, SweepThroughThinWallAtHighSpeedDoesNotTunnel) {
  CollisionWorld world(Room());
  // 100 m/s for 0.25 s would jump 25 m; both ends are free of the 1 mm wall.
  const SweepHit hit = world.SweepDisc(Vec2(-3.0, 0.0), Vec2(22.0, 0.0), 0.3);
  EXPECT_EQ(hit.rect, 5);
  // Contact is defined 1e-9 m inside the disc (touching is not contact).
  EXPECT_NEAR(hit.fraction, (-2.0 - 0.3 - -3.0) / 25.0, 2e-9 / 25.0);
  // A short hop across the wall, both ends clear of it.
  EXPECT_FALSE(world.DiscOverlaps(Vec2(-2.4, 0.0), 0.3));
  EXPECT_FALSE(world.DiscOverlaps(Vec2(-1.6, 0.0), 0.3));
  const SweepHit hop = world.SweepDisc(Vec2(-2.4, 0.0), Vec2(-1.6, 0.0), 0.3);
  EXPECT_EQ(hop.rect, 5);
  EXPECT_NEAR(hop.fraction, 0.1 / 0.8, 2e-9 / 0.8);
}

TEST(CollisionWorld, SweepReportsTheFirstOfSeveralContacts) {
  CollisionWorld world(Room());
  // Along y = 2 to the right: the box (x = 1) comes before the right wall (x = 4.9).
  const SweepHit hit = world.SweepDisc(Vec2(0.0, 2.0), Vec2(8.0, 2.0), 0.5);
  EXPECT_EQ(hit.rect, 4);
  EXPECT_NEAR(hit.fraction, 0.5 / 8.0, 2e-9 / 8.0);
}

TEST(CollisionWorld, SweepFreeMotionAndStartOverlap) {
  CollisionWorld world(Room());
  const SweepHit free = world.SweepDisc(Vec2(0, 0), Vec2(0.5, -0.5), 0.3);
  EXPECT_EQ(free.rect, -1);
  EXPECT_EQ(free.fraction, kInfinity);
  const SweepHit start = world.SweepDisc(Vec2(0.9, 2.0), Vec2(-1.0, 2.0), 0.3);
  EXPECT_EQ(start.rect, 4);
  EXPECT_EQ(start.fraction, 0.0);
  const SweepHit still = world.SweepDisc(Vec2(0, 0), Vec2(0, 0), 0.3);
  EXPECT_EQ(still.rect, -1);
}

std::vector<Rect> RandomRects(int count, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> pos(-8.0, 8.0);
  std::uniform_real_distribution<double> size(0.001, 2.0);
  std::vector<Rect> rects;
  for (int i = 0; i < count; ++i) {
    const double x = pos(rng), y = pos(rng);
    rects.push_back(Rect::FromCorners(x, y, x + size(rng), y + size(rng)));
  }
  return rects;
}

// The broadphase cull never drops a contact: compare with a sweep over every rectangle, on maps
// culled by testing every box (40) and by Bullet's tree (300).
TEST(CollisionWorld, SweepMatchesBruteForce) {
  for (const int rect_count : {40, 300}) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> pos(-8.0, 8.0);
    const std::vector<Rect> rects = RandomRects(rect_count, rng);
    CollisionWorld world(MakeMap(rects));
    for (int trial = 0; trial < 2000; ++trial) {
      const Vec2 a(pos(rng), pos(rng));
      const Vec2 b = a + Vec2(pos(rng), pos(rng)) * 0.5;
      double best = kInfinity;
      for (const Rect& r : rects) best = std::min(best, SweptDiscRectTime(a, b, 0.3, r));
      const SweepHit hit = world.SweepDisc(a, b, 0.3);
      EXPECT_EQ(hit.fraction, best) << rect_count << " rectangles, trial " << trial;
      if (best != kInfinity) {
        EXPECT_EQ(SweptDiscRectTime(a, b, 0.3, rects[hit.rect]), best);
      }
    }
  }
}

// Either cull (every box on small maps, Bullet's tree on large ones) finds exactly the touching
// rectangles, on both sides of the size where the cull changes.
TEST(CollisionWorld, QueryRectsMatchesBruteForceOnSmallAndLargeMaps) {
  for (const int rect_count : {1, 64, 65, 300}) {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> pos(-9.0, 9.0);
    std::uniform_real_distribution<double> size(0.0, 3.0);
    const std::vector<Rect> rects = RandomRects(rect_count, rng);
    CollisionWorld world(MakeMap(rects));
    std::vector<int> ids;
    for (int trial = 0; trial < 500; ++trial) {
      const double x = pos(rng), y = pos(rng);
      Rect box = Rect::FromCorners(x, y, x + size(rng), y + size(rng));
      if (trial % 4 == 1) box.min.x() = box.max.x() = rects[trial % rect_count].max.x();  // edge
      std::vector<int> expected;
      for (int i = 0; i < rect_count; ++i) {
        const Rect& r = rects[static_cast<std::size_t>(i)];
        if (r.min.x() <= box.max.x() && box.min.x() <= r.max.x() && r.min.y() <= box.max.y() &&
            box.min.y() <= r.max.y())
          expected.push_back(i);
      }
      world.QueryRects(box, &ids);
      EXPECT_EQ(ids, expected) << rect_count << " rectangles, trial " << trial;
    }
  }
}

// The sight-line query decides as a ray cast along each line would, axis-aligned, grazing and
// zero-length lines included, whatever lines share its groups of four; among few rectangles
// (one scan of every line) and many (culled in fours), with either broadphase.
TEST(CollisionWorld, SightLinesMatchRayCasts) {
  for (const int rect_count : {5, 40, 300}) {
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> pos(-8.0, 8.0);
    std::uniform_real_distribution<double> size(0.001, rect_count < 10    ? 5.0
                                                       : rect_count < 100 ? 2.0
                                                                          : 0.5);
    std::vector<Rect> rects;
    for (int i = 0; i < rect_count; ++i) {
      const double x = pos(rng), y = pos(rng);
      rects.push_back(Rect::FromCorners(x, y, x + size(rng), y + size(rng)));
    }
    CollisionWorld world(MakeMap(rects));
    int blocked_lines = 0, clear_lines = 0;
    for (int trial = 0; trial < 500; ++trial) {
      const Vec2 eye(pos(rng), pos(rng));
      std::vector<Vec2> ends;
      const int n = 1 + trial % 13;
      for (int k = 0; k < n; ++k) {
        const Rect& r = rects[static_cast<std::size_t>(k % rect_count)];
        Vec2 end(pos(rng), pos(rng));
        if (k % 5 == 1) end.x() = eye.x();    // axis-aligned
        if (k % 5 == 2) end.y() = r.max.y();  // along a rectangle's edge
        if (k % 7 == 3) end = r.min;          // ending on a corner
        if (k % 11 == 4) end = eye;           // zero length
        ends.push_back(end);
      }
      std::vector<std::uint8_t> blocked(ends.size(), 2);
      std::vector<double> lengths(ends.size(), -1.0);
      world.SightLines(eye, ends, lengths.data(), blocked.data());
      for (std::size_t k = 0; k < ends.size(); ++k) {
        const double length = (ends[k] - eye).norm();
        const Vec2 dir = length > 0.0 ? Vec2((ends[k] - eye) / length) : Vec2(1.0, 0.0);
        double range = 0.0;
        world.CastRays(eye, std::span<const Vec2>(&dir, 1), 30.0, {}, &range);
        const std::uint8_t expected = range < length ? 1 : 0;
        EXPECT_EQ(lengths[k], length);
        EXPECT_EQ(blocked[k], expected) << rect_count << " rectangles, trial " << trial;
        (expected ? blocked_lines : clear_lines) += 1;
      }
    }
    // Both outcomes occur often enough to test either.
    EXPECT_GT(blocked_lines, 300) << rect_count;
    EXPECT_GT(clear_lines, 300) << rect_count;
  }
}

TEST(CollisionWorld, ClearanceAt) {
  CollisionWorld world(Room());
  EXPECT_NEAR(world.ClearanceAt(Vec2(0.0, 2.0), 2.0), 1.0, 1e-12);  // box face
  EXPECT_NEAR(world.ClearanceAt(Vec2(4.0, 0.0), 2.0), 0.9, 1e-12);  // right wall
  EXPECT_EQ(world.ClearanceAt(Vec2(0.0, 0.0), 0.5), kInfinity);
  EXPECT_EQ(world.ClearanceAt(Vec2(1.5, 2.0), 0.5), 0.0);  // inside the box
  // The corner (2, 3) is sqrt(2) * 0.5 away: outside a 0.7 search, inside a 0.71 one.
  EXPECT_EQ(world.ClearanceAt(Vec2(2.5, 3.5), 0.7), kInfinity);
  EXPECT_NEAR(world.ClearanceAt(Vec2(2.5, 3.5), 0.71), std::sqrt(0.5), 1e-12);
}

TEST(CollisionWorld, EmptyMap) {
  CollisionWorld world(MakeMap({}));
  EXPECT_FALSE(world.DiscOverlaps(Vec2(0, 0), 1.0));
  EXPECT_EQ(world.SweepDisc(Vec2(0, 0), Vec2(5, 5), 1.0).rect, -1);
  std::vector<int> ids{7};
  world.QueryRects(Rect::FromCorners(-1, -1, 1, 1), &ids);
  EXPECT_TRUE(ids.empty());
  const double angles[] = {0.0, 1.0};
  double ranges[2];
  world.CastRays(Vec2(0, 0), angles, 3.0, {}, ranges);
  EXPECT_EQ(ranges[0], 3.0);
  EXPECT_EQ(ranges[1], 3.0);
  // No Bullet world is built for an empty map: every query still answers, discs included.
  EXPECT_EQ(world.ClearanceAt(Vec2(0, 0), 5.0), kInfinity);
  const Circle disc{Vec2(2.0, 0.0), 0.5};
  world.CastRays(Vec2(0, 0), angles, 3.0, std::span<const Circle>(&disc, 1), ranges);
  EXPECT_DOUBLE_EQ(ranges[0], 1.5);
  EXPECT_EQ(ranges[1], 3.0);
  world.CastRaysBullet(Vec2(0, 0), angles, 3.0, ranges);
  EXPECT_EQ(ranges[0], 3.0);
  EXPECT_EQ(ranges[1], 3.0);
}

// Const queries from several threads on one world give the single-threaded answers.
TEST(CollisionWorld, ConcurrentConstQueries) {
  CollisionWorld world(Room());
  std::vector<double> angles;
  for (int k = 0; k < 90; ++k) angles.push_back(k * 0.0698);
  std::vector<double> expected(angles.size()), expected_bullet(angles.size());
  world.CastRays(Vec2(0.1, -0.2), angles, 5.0, {}, expected.data());
  world.CastRaysBullet(Vec2(0.1, -0.2), angles, 5.0, expected_bullet.data());
  std::vector<std::thread> threads;
  std::vector<int> failures(4, 0);
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      std::vector<double> r(angles.size()), rb(angles.size());
      for (int i = 0; i < 200; ++i) {
        world.CastRays(Vec2(0.1, -0.2), angles, 5.0, {}, r.data());
        world.CastRaysBullet(Vec2(0.1, -0.2), angles, 5.0, rb.data());
        if (r != expected || rb != expected_bullet) ++failures[t];
        if (world.SweepDisc(Vec2(-3, 0), Vec2(22, 0), 0.3).rect != 5) ++failures[t];
      }
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(failures, std::vector<int>(4, 0));
}

}  // namespace
}  // namespace crowdsim
