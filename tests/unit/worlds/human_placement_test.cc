// Shared human placement: free space, separation, goal distance, retries and errors.
#include "crowdsim/human_placement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace crowdsim {
namespace {

// A walled square room of side `size` centred at the origin, plus `obstacles`.
std::shared_ptr<const StaticMap> Room(double size, std::vector<Rect> obstacles = {}) {
  auto map = std::make_shared<StaticMap>();
  const double h = 0.5 * size;
  const double o = h + 0.5;
  map->bounds = Rect::FromCorners(-o, -o, o, o);
  map->rectangles = {Rect::FromCorners(-o, -o, o, -h), Rect::FromCorners(-o, h, o, o),
                     Rect::FromCorners(-o, -h, -h, h), Rect::FromCorners(h, -h, o, h)};
  for (const Rect& r : obstacles) map->rectangles.push_back(r);
  return map;
}

PlacementArea AreaOf(std::shared_ptr<const StaticMap> map, double clearance) {
  auto space = std::make_shared<DiscFreeSpace>(map, clearance);
  return {
      [space](const Vec2& p) { return space->Contains(p); }, UniformSampler(map->bounds), {}, {}};
}

ScenarioRequest Request(int humans, HumanGoalMode mode) {
  ScenarioRequest r;
  r.num_humans = humans;
  r.goal_mode = mode;
  return r;
}

// Checks every placement rule for the default radii (0.3) and discomfort distance (0.2).
void ExpectRules(const std::vector<HumanSpec>& humans, const DiscFreeSpace& space,
                 const Vec2& robot_start, const Vec2& robot_goal, double goal_min_dist) {
  constexpr double kGap = 0.8;  // 2 * 0.3 + 0.2, and 0.3 + 0.3 + 0.2 for the robot
  for (size_t i = 0; i < humans.size(); ++i) {
    const HumanSpec& h = humans[i];
    EXPECT_TRUE(space.Contains(h.start)) << "start of human " << i;
    EXPECT_GE((h.start - robot_start).norm(), kGap);
    Vec2 previous = h.start;
    for (size_t k = 0; k < h.goals.size(); ++k) {
      EXPECT_TRUE(space.Contains(h.goals[k])) << "goal " << k << " of human " << i;
      EXPECT_GE((h.goals[k] - robot_goal).norm(), kGap);
      EXPECT_GE((h.goals[k] - previous).norm(), goal_min_dist);
      previous = h.goals[k];
    }
    for (size_t j = 0; j < i; ++j) {
      EXPECT_GE((h.start - humans[j].start).norm(), kGap) << i << " vs " << j;
      for (size_t k = 0; k < h.goals.size(); ++k) {
        EXPECT_GE((h.goals[k] - humans[j].goals[k]).norm(), kGap) << i << " vs " << j;
      }
    }
  }
}

TEST(DiscFreeSpace, KeepsTheDiscInsideAndOffRectangles) {
  const auto map = Room(10.0, {Rect::FromCorners(-1, -1, 1, 1)});
  const DiscFreeSpace space(map, 0.4);
  EXPECT_TRUE(space.Contains(Vec2(3.0, 3.0)));
  EXPECT_FALSE(space.Contains(Vec2(4.7, 0.0)));  // disc reaches the wall
  EXPECT_TRUE(space.Contains(Vec2(4.55, 0.0)));
  EXPECT_FALSE(space.Contains(Vec2(0.0, 1.3)));  // disc reaches the obstacle
  EXPECT_TRUE(space.Contains(Vec2(0.0, 1.45)));
  EXPECT_FALSE(space.Contains(Vec2(0.0, 0.0)));
  EXPECT_FALSE(space.Contains(Vec2(20.0, 0.0)));  // outside the bounds
}

// The free-space test skips the exact disc test for rectangles the point is far from; the
// answers must stay those of the disc test everywhere, on the edge of that cut-off included.
TEST(DiscFreeSpace, AnswersAsTheDiscTestAtEveryDistance) {
  const auto map =
      Room(10.0, {Rect::FromCorners(-1.3, -0.7, 0.9, 1.1), Rect::FromCorners(2.0, -3.0, 2.5, 3.5)});
  for (double clearance : {0.0, 0.3, 0.4, 0.93}) {
    const DiscFreeSpace space(map, clearance);
    const Rect inner = map->bounds.Inflated(-clearance);
    auto reference = [&](const Vec2& p) {
      if (!inner.Contains(p)) return false;
      return std::none_of(map->rectangles.begin(), map->rectangles.end(),
                          [&](const Rect& r) { return DiscOverlapsRect(p, clearance, r); });
    };
    int checked = 0;
    for (const Rect& r : map->rectangles) {
      // Points at the clearance from each side and corner, and a hair either side of it.
      for (double dx : {-1.0, 0.0, 1.0}) {
        for (double dy : {-1.0, 0.0, 1.0}) {
          if (dx == 0.0 && dy == 0.0) continue;
          const Vec2 dir = Vec2(dx, dy).normalized();
          const Vec2 corner(dx < 0   ? r.min.x()
                            : dx > 0 ? r.max.x()
                                     : r.Center().x(),
                            dy < 0   ? r.min.y()
                            : dy > 0 ? r.max.y()
                                     : r.Center().y());
          for (double off : {-1e-6, -1e-9, -1e-12, 0.0, 1e-12, 1e-9, 1e-6}) {
            const Vec2 p = corner + (clearance + off) * dir;
            EXPECT_EQ(space.Contains(p), reference(p))
                << "clearance " << clearance << " point (" << p.x() << ", " << p.y() << ")";
            ++checked;
          }
        }
      }
    }
    Rng rng(7);
    for (int i = 0; i < 20000; ++i, ++checked) {
      const Vec2 p(rng.Uniform(-5.6, 5.6), rng.Uniform(-5.6, 5.6));
      ASSERT_EQ(space.Contains(p), reference(p)) << "clearance " << clearance;
    }
    EXPECT_GT(checked, 20000);
  }
}

TEST(HumanPlacement, OneGoalPerHumanFollowingEveryRule) {
  const auto map = Room(10.0, {Rect::FromCorners(-2, -1, 1, 2)});
  const Vec2 robot_start(-4, -4), robot_goal(4, 4);
  for (std::uint64_t seed = 1; seed <= 50; ++seed) {
    Rng rng(seed);
    const auto humans = PlaceHumans(AreaOf(map, 0.4), robot_start, robot_goal,
                                    Request(5, HumanGoalMode::kStay), HumanPlacementOptions{}, rng);
    ASSERT_EQ(humans.size(), 5u);
    for (const HumanSpec& h : humans) {
      EXPECT_EQ(h.goals.size(), 1u);
      EXPECT_DOUBLE_EQ(h.radius, 0.3);
      EXPECT_DOUBLE_EQ(h.v_pref, 1.0);
    }
    ExpectRules(humans, DiscFreeSpace(map, 0.4), robot_start, robot_goal, 3.0);
  }
}

TEST(HumanPlacement, NewGoalModeGivesASequenceOfDistantGoals) {
  const auto map = Room(10.0);
  HumanPlacementOptions options;
  options.new_goal_count = 16;
  Rng rng(7);
  const auto humans = PlaceHumans(AreaOf(map, 0.4), Vec2(0, -4), Vec2(0, 4),
                                  Request(6, HumanGoalMode::kNewGoal), options, rng);
  ASSERT_EQ(humans.size(), 6u);
  for (const HumanSpec& h : humans) EXPECT_EQ(h.goals.size(), 16u);
  ExpectRules(humans, DiscFreeSpace(map, 0.4), Vec2(0, -4), Vec2(0, 4), 3.0);
}

TEST(HumanPlacement, SameRngStateGivesSamePlacement) {
  const auto map = Room(10.0);
  auto place = [&](std::uint64_t seed) {
    Rng rng(seed);
    return PlaceHumans(AreaOf(map, 0.4), Vec2(0, -4), Vec2(0, 4), Request(5, HumanGoalMode::kStay),
                       HumanPlacementOptions{}, rng);
  };
  const auto a = place(42), b = place(42), c = place(43);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].start, b[i].start);
    EXPECT_EQ(a[i].goals, b[i].goals);
  }
  EXPECT_NE(a[0].start, c[0].start);
}

TEST(HumanPlacement, RequestRadiiAreUsed) {
  ScenarioRequest request = Request(4, HumanGoalMode::kStay);
  request.sim.human_radius = 0.4;
  request.sim.human_v_pref = 1.3;
  const HumanPlacementOptions o = HumanPlacementOptions::FromRequest(request);
  EXPECT_DOUBLE_EQ(o.human_radius, 0.4);
  EXPECT_DOUBLE_EQ(o.human_v_pref, 1.3);
  const auto map = Room(10.0);
  Rng rng(3);
  const auto humans = PlaceHumans(AreaOf(map, 0.5), Vec2(0, -4), Vec2(0, 4), request, o, rng);
  for (size_t i = 0; i < humans.size(); ++i) {
    EXPECT_DOUBLE_EQ(humans[i].radius, 0.4);
    EXPECT_DOUBLE_EQ(humans[i].v_pref, 1.3);
    for (size_t j = 0; j < i; ++j) EXPECT_GE((humans[i].start - humans[j].start).norm(), 1.0);
  }
}

TEST(HumanPlacement, GoalDistanceRelaxesInASmallRoom) {
  // A 2 x 2 m room cannot hold a 3 m walk: the goal still lands in free space.
  const auto map = Room(2.0);
  Rng rng(5);
  const auto humans = PlaceHumans(AreaOf(map, 0.4), Vec2(-0.5, -0.5), Vec2(0.5, 0.5),
                                  Request(1, HumanGoalMode::kStay), HumanPlacementOptions{}, rng);
  ASSERT_EQ(humans.size(), 1u);
  const DiscFreeSpace space(map, 0.4);
  EXPECT_TRUE(space.Contains(humans[0].goals[0]));
  EXPECT_LT((humans[0].goals[0] - humans[0].start).norm(), 3.0);
}

TEST(HumanPlacement, ImpossibleRequestThrowsAClearError) {
  const auto map = Room(2.0);
  Rng rng(1);
  HumanPlacementOptions options;
  options.max_tries = 200;
  try {
    PlaceHumans(AreaOf(map, 0.4), Vec2(0, 0), Vec2(0, 0), Request(10, HumanGoalMode::kStay),
                options, rng);
    FAIL() << "expected PlacementError";
  } catch (const PlacementError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("human"), std::string::npos) << what;
    EXPECT_NE(what.find("(the row's humans.count)"), std::string::npos) << what;
  }
}

TEST(HumanPlacement, ListSamplerDrawsOnlyListedPoints) {
  const auto map = Room(10.0);
  std::vector<Vec2> points;
  for (int i = -4; i <= 4; ++i) {
    for (int j = -4; j <= 4; ++j) points.emplace_back(i, j);
  }
  const auto space = std::make_shared<DiscFreeSpace>(map, 0.4);
  const PlacementArea area{
      [space](const Vec2& p) { return space->Contains(p); }, ListSampler(points), {}, {}};
  Rng rng(11);
  const auto humans =
      PlaceHumans(area, Vec2(0, -4), Vec2(0, 4), Request(5, HumanGoalMode::kNewGoal),
                  HumanPlacementOptions{}, rng);
  auto listed = [&](const Vec2& p) {
    return std::find(points.begin(), points.end(), p) != points.end();
  };
  for (const HumanSpec& h : humans) {
    EXPECT_TRUE(listed(h.start));
    for (const Vec2& g : h.goals) EXPECT_TRUE(listed(g));
  }
  ExpectRules(humans, *space, Vec2(0, -4), Vec2(0, 4), 3.0);
  EXPECT_THROW(ListSampler({}), std::invalid_argument);
}

// A floor plan's list of free points holds a few dozen humans; the area's region takes the
// crowd on from where the list has no place left, and changes nothing for a crowd the list holds.
TEST(HumanPlacement, TheRegionPlacesWhatTheListHasNoPlaceFor) {
  const auto map = Room(10.0);
  std::vector<Vec2> points;  // 3 x 3 points 3 m apart: at most 9 starts
  for (int i = -1; i <= 1; ++i) {
    for (int j = -1; j <= 1; ++j) points.emplace_back(3.0 * i, 3.0 * j);
  }
  const auto space = std::make_shared<DiscFreeSpace>(map, 0.4);
  auto is_free = [space](const Vec2& p) { return space->Contains(p); };
  const PlacementArea list_only{is_free, ListSampler(points), {}, {}};
  const PlacementArea with_region{is_free, ListSampler(points), {}, map->bounds};
  HumanPlacementOptions options;
  options.max_tries = 300;
  Rng rng(3);
  EXPECT_THROW(PlaceHumans(list_only, Vec2(0, -4.5), Vec2(0, 4.5),
                           Request(20, HumanGoalMode::kStay), options, rng),
               PlacementError);
  rng = Rng(3);
  const auto crowd = PlaceHumans(with_region, Vec2(0, -4.5), Vec2(0, 4.5),
                                 Request(20, HumanGoalMode::kStay), options, rng);
  ASSERT_EQ(crowd.size(), 20u);
  ExpectRules(crowd, *space, Vec2(0, -4.5), Vec2(0, 4.5), 3.0);
  auto listed = [&](const Vec2& p) {
    return std::find(points.begin(), points.end(), p) != points.end();
  };
  EXPECT_TRUE(std::any_of(crowd.begin(), crowd.end(),
                          [&](const HumanSpec& h) { return !listed(h.start); }));

  // Four humans fit the list: the region is never drawn from, the crowd is the list's own.
  rng = Rng(8);
  const auto small = PlaceHumans(with_region, Vec2(0, -4.5), Vec2(0, 4.5),
                                 Request(4, HumanGoalMode::kStay), options, rng);
  rng = Rng(8);
  const auto small_listed = PlaceHumans(list_only, Vec2(0, -4.5), Vec2(0, 4.5),
                                        Request(4, HumanGoalMode::kStay), options, rng);
  ASSERT_EQ(small.size(), small_listed.size());
  for (std::size_t i = 0; i < small.size(); ++i) {
    EXPECT_EQ(small[i].start, small_listed[i].start) << i;
    EXPECT_EQ(small[i].goals, small_listed[i].goals) << i;
  }
}

// "At least the gap apart" includes exactly the gap: two points 1 m apart (radius 0.25 m and a
// discomfort distance of 0.5 m make the gap exactly 1 m) take two humans.
TEST(HumanPlacement, PointsExactlyTheGapApartHoldTwoHumans) {
  const auto map = Room(10.0);
  const auto space = std::make_shared<DiscFreeSpace>(map, 0.35);
  const PlacementArea area{[space](const Vec2& p) { return space->Contains(p); },
                           ListSampler({Vec2(0.0, 0.0), Vec2(1.0, 0.0)}),
                           {},
                           {}};
  HumanPlacementOptions options;
  options.human_radius = 0.25;
  options.discomfort_dist = 0.5;
  options.max_tries = 400;
  Rng rng(2);
  const auto humans =
      PlaceHumans(area, Vec2(0, -4), Vec2(0, 4), Request(2, HumanGoalMode::kStay), options, rng);
  ASSERT_EQ(humans.size(), 2u);
  EXPECT_EQ((humans[0].start - humans[1].start).norm(), 1.0);
  EXPECT_EQ((humans[0].goals[0] - humans[1].goals[0]).norm(), 1.0);
}

TEST(HumanPlacement, AnImpossibleDensityIsNamedInTheError) {
  const auto map = Room(2.0);  // centres fit in 1.2 x 1.2 m with a clearance of 0.4 m
  const auto space = std::make_shared<DiscFreeSpace>(map, 0.4);
  const PlacementArea area{[space](const Vec2& p) { return space->Contains(p); },
                           UniformSampler(map->bounds),
                           {},
                           map->bounds};
  HumanPlacementOptions options;
  options.max_tries = 200;
  Rng rng(1);
  try {
    PlaceHumans(area, Vec2(0, 0), Vec2(0, 0), Request(10, HumanGoalMode::kStay), options, rng);
    FAIL() << "expected PlacementError";
  } catch (const PlacementError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("10 humans in about 1 m^2 of free space"), std::string::npos) << what;
    // 0.547 of the plane covered by discs of diameter 0.8 m: 1.09 per m^2.
    EXPECT_NE(what.find("0.8 m apart (starts from starts, goals from goals) jam at about 1.09"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("(the row's humans.count)"), std::string::npos) << what;
  }
}

TEST(HumanPlacement, ZeroHumansIsEmpty) {
  Rng rng(1);
  EXPECT_TRUE(PlaceHumans(AreaOf(Room(10.0), 0.4), Vec2(0, -4), Vec2(0, 4),
                          Request(0, HumanGoalMode::kStay), HumanPlacementOptions{}, rng)
                  .empty());
}

// People of their own sizes keep their own gaps: r_i + r_j + discomfort between any two, r_i +
// r_robot + discomfort from the robot, each with its drawn radius, speed and attention.
TEST(HumanPlacement, VariedPeopleKeepGapsOfTheirOwnRadii) {
  const auto map = Room(12.0, {Rect::FromCorners(-1, -1, 1, 1)});
  const Vec2 robot_start(-4.0, -4.0), robot_goal(4.0, 4.0);
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    ScenarioRequest request = Request(8, HumanGoalMode::kStay);
    Rng draws(seed);
    for (int i = 0; i < 8; ++i) {
      request.humans.push_back(
          {std::round(draws.Uniform(0.3, 0.5) * 100) / 100, draws.Uniform(0.5, 1.5), i % 3 == 0});
    }
    const double largest = LargestHumanRadius(request);
    const DiscFreeSpace space(map, largest);
    Rng rng(seed);
    const auto humans = PlaceHumans(AreaOf(map, largest), robot_start, robot_goal, request,
                                    HumanPlacementOptions::FromRequest(request), rng);
    ASSERT_EQ(humans.size(), 8u);
    for (size_t i = 0; i < humans.size(); ++i) {
      const HumanSpec& h = humans[i];
      EXPECT_EQ(h.radius, request.humans[i].radius);
      EXPECT_EQ(h.v_pref, request.humans[i].v_pref);
      EXPECT_EQ(h.ignores_robot, request.humans[i].ignores_robot);
      EXPECT_TRUE(space.Contains(h.start));
      EXPECT_GE((h.start - robot_start).norm(), h.radius + 0.3 + 0.2);
      EXPECT_GE((h.goals[0] - robot_goal).norm(), h.radius + 0.3 + 0.2);
      for (size_t j = 0; j < i; ++j) {
        const double gap = h.radius + humans[j].radius + 0.2;
        EXPECT_GE((h.start - humans[j].start).norm(), gap) << "seed " << seed;
        EXPECT_GE((h.goals[0] - humans[j].goals[0]).norm(), gap) << "seed " << seed;
      }
    }
  }
}

// Attributes equal to the sim's place exactly the people the sim's radius places.
TEST(HumanPlacement, AttributesOfTheSimsPersonChangeNoPlacement) {
  const auto map = Room(10.0, {Rect::FromCorners(-1, -1, 1, 1)});
  ScenarioRequest plain = Request(6, HumanGoalMode::kNewGoal);
  ScenarioRequest drawn = plain;
  drawn.humans.assign(6, HumanAttributes{0.3, 1.0, false});
  Rng a(11), b(11);
  const auto x = PlaceHumans(AreaOf(map, 0.3), Vec2(-3, -3), Vec2(3, 3), plain,
                             HumanPlacementOptions::FromRequest(plain), a);
  const auto y = PlaceHumans(AreaOf(map, 0.3), Vec2(-3, -3), Vec2(3, 3), drawn,
                             HumanPlacementOptions::FromRequest(drawn), b);
  ASSERT_EQ(x.size(), y.size());
  for (size_t i = 0; i < x.size(); ++i) {
    EXPECT_EQ(x[i].start, y[i].start);
    EXPECT_EQ(x[i].goals, y[i].goals);
  }
}

}  // namespace
}  // namespace crowdsim
