#include "scenario_layouts.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace crowdsim::social_scenarios {

namespace {

constexpr double kWall = 0.3;  // m, wall thickness

void Add(StaticMap* map, double x0, double y0, double x1, double y1) {
  map->rectangles.push_back(Rect::FromCorners(x0, y0, x1, y1));
}

// A room x in [x0, x1], y in [-6, 6] walled around.
void Room(StaticMap* map, double x0, double x1) {
  Add(map, x0 - kWall, -6.0 - kWall, x1 + kWall, -6.0);
  Add(map, x0 - kWall, 6.0, x1 + kWall, 6.0 + kWall);
  Add(map, x0 - kWall, -6.0, x0, 6.0);
  Add(map, x1, -6.0, x1 + kWall, 6.0);
  map->bounds = Rect::FromCorners(x0 - kWall, -6.0 - kWall, x1 + kWall, 6.0 + kWall);
}

// Two rooms joined by a corridor free in x in [-4, 4], y in [-half, half].
void CorridorBetweenRooms(StaticMap* map, double x1, double half) {
  Room(map, -12.0, x1);
  Add(map, -4.0, half, 4.0, 6.0);
  Add(map, -4.0, -6.0, 4.0, -half);
}

// A person in a file along x: the k-th about `spacing` behind the first.
double InFile(double first, double spacing, int k, Rng& rng) {
  return first + spacing * k + rng.Uniform(-0.2, 0.2);
}

// A conversational group (an F-formation) of `count` people standing on a circle with one open
// place at `slot`, the circle's far side from there along +x: person k at the k-th of count + 1
// places around it (jittered by up to 0.05 rad), neighbours 1.1 m apart or more.
Vec2 InCircle(const Vec2& slot, int k, int count, Rng& rng) {
  const double places = count + 1.0;
  const double radius = std::max(0.8, 0.55 / std::sin(std::numbers::pi / places));
  const Vec2 centre = slot + Vec2(radius, 0.0);
  const double angle =
      std::numbers::pi + 2.0 * std::numbers::pi * (k + 1) / places + rng.Uniform(-0.05, 0.05);
  return centre + radius * Vec2(std::cos(angle), std::sin(angle));
}

}  // namespace

Layout MakeLayout(const std::string& name) {
  Layout l;
  l.map.name = "social_scenarios_" + name;
  l.robot_start = Vec2(-7.0, 0.0);
  l.robot_goal = Vec2(7.0, 0.0);
  const double far_end = 10.0 + 1.5 * kMaxPeople;  // room for a file of people ahead
  if (name == "frontal_approach" || name == "overtaking" || name == "standing_person") {
    CorridorBetweenRooms(&l.map, far_end, 1.5);  // 3 m wide, 8 m long
  } else if (name == "narrow_hallway") {
    CorridorBetweenRooms(&l.map, far_end, 0.9);  // 1.8 m: two people pass, barely
  } else if (name == "crossing" || name == "join_group" || name == "leave_group") {
    l.map.bounds = Rect::FromCorners(-12.0, -12.0, 12.0, 12.0);  // open space
  } else if (name == "doorway") {
    // A room split at x = 0 by a wall with a 1.2 m door.
    Room(&l.map, -12.0, 4.0 + 1.5 * kMaxPeople);
    Add(&l.map, -0.15, -6.0, 0.15, -0.6);
    Add(&l.map, -0.15, 0.6, 0.15, 6.0);
  } else if (name == "blind_corner") {
    // A room x in [-12, -9] opens into an L: free along y in [-1, 1] from x = -9 to 1, then up
    // x in [-1, 1] to `top`; the robot turns the corner towards (0, 5) and meets people coming
    // down out of its sight.
    const double top = 8.0 + 1.5 * kMaxPeople;
    Add(&l.map, -12.0 - kWall, -6.0 - kWall, 1.0 + kWall, -6.0);  // room and L, walled around
    Add(&l.map, -12.0 - kWall, -6.0, -12.0, top + kWall);
    Add(&l.map, -12.0, top, 1.0 + kWall, top + kWall);
    Add(&l.map, 1.0, -6.0, 1.0 + kWall, top);
    Add(&l.map, -9.0, -6.0, 1.0, -1.0);  // below the horizontal leg
    Add(&l.map, -9.0, 1.0, -1.0, top);   // the inner block the corner hides behind
    l.map.bounds = Rect::FromCorners(-12.0 - kWall, -6.0 - kWall, 1.0 + kWall, top + kWall);
    l.robot_goal = Vec2(0.0, 5.0);
  } else if (name == "intersection") {
    // Two 2.4 m corridors crossing at the origin: four corner blocks and four end walls.
    const double e = 9.0, h = 1.2;
    for (double sx : {-1.0, 1.0}) {
      for (double sy : {-1.0, 1.0}) {
        Add(&l.map, std::min(sx * h, sx * e), std::min(sy * h, sy * e), std::max(sx * h, sx * e),
            std::max(sy * h, sy * e));
      }
    }
    Add(&l.map, -e - kWall, -h, -e, h);
    Add(&l.map, e, -h, e + kWall, h);
    Add(&l.map, -h, -e - kWall, h, -e);
    Add(&l.map, -h, e, h, e + kWall);
    l.map.bounds = Rect::FromCorners(-e - kWall, -e - kWall, e + kWall, e + kWall);
  } else {
    throw std::invalid_argument("social_scenarios: unknown scenario '" + name + "'");
  }
  return l;
}

PersonPlan MakePerson(const std::string& name, int k, int count, Rng& rng) {
  PersonPlan p;
  p.speed_factor = rng.Uniform(0.8, 1.2);  // people walk at 80-120% of the suite's v_pref
  if (name == "frontal_approach") {
    // Towards the robot along the corridor, spread across it.
    const double y = rng.Uniform(-0.8, 0.8);
    p.start = Vec2(InFile(5.0, 1.5, k, rng), y);
    p.goal = Vec2(-10.0, rng.Uniform(-4.0, 4.0));  // into the far room
  } else if (name == "overtaking") {
    // Ahead of the robot, the same way, at half speed: it must pass them.
    const double y = rng.Uniform(-0.8, 0.8);
    p.start = Vec2(InFile(-4.0, 1.5, k, rng), y);
    p.goal = Vec2(8.5 + 1.5 * kMaxPeople, rng.Uniform(-4.0, 4.0));
    p.speed_factor *= 0.5;
  } else if (name == "standing_person") {
    // Standing on the robot's line (their goal is where they stand).
    p.start = Vec2(InFile(-1.0, 1.5, k, rng), rng.Uniform(-0.5, 0.5));
    p.goal = p.start;
  } else if (name == "narrow_hallway") {
    p.start = Vec2(InFile(2.0, 1.5, k, rng), rng.Uniform(-0.2, 0.2));
    p.goal = Vec2(-10.0, rng.Uniform(-4.0, 4.0));
  } else if (name == "crossing") {
    // Across the robot's path at 90 degrees, timed to meet it near the middle.
    const double x = InFile(-1.5, 1.3, k, rng);
    p.start = Vec2(x, -5.0 - rng.Uniform(0.0, 1.0));
    p.goal = Vec2(x, 7.0);
  } else if (name == "doorway") {
    // From the far room through the door towards the robot's side.
    p.start = Vec2(InFile(3.0, 1.5, k, rng), rng.Uniform(-3.5, 3.5));
    p.goal = Vec2(-10.0, rng.Uniform(-4.0, 4.0));
  } else if (name == "blind_corner") {
    // Down the vertical leg, out of the robot's sight, then along the horizontal one.
    p.start = Vec2(rng.Uniform(-0.4, 0.4), InFile(7.0, 1.5, k, rng));
    p.goal = Vec2(-10.5, rng.Uniform(-4.0, 4.0));  // into the room
  } else if (name == "intersection") {
    // Along the cross corridor, from below (even k) and above (odd k).
    const double side = k % 2 == 0 ? -1.0 : 1.0;
    const double x = rng.Uniform(-0.6, 0.6);
    p.start = Vec2(x, side * InFile(4.5, 1.5, k / 2, rng));
    p.goal = Vec2(x, -side * 8.0);
  } else if (name == "join_group") {
    // A group standing in conversation whose open place is the robot's goal: the robot joins it.
    p.start = InCircle(Vec2(7.0, 0.0), k, count, rng);
    p.goal = p.start;
    p.group = 0;
  } else if (name == "leave_group") {
    // The robot stands in a group's open place, its goal beyond the group: it must walk round.
    p.start = InCircle(Vec2(-7.0, 0.0), k, count, rng);
    p.goal = p.start;
    p.group = 0;
  }
  return p;
}

}  // namespace crowdsim::social_scenarios
