// Lidar scans and swept-disc tests: the fast CollisionWorld paths against a brute-force
// exact scan and Bullet's own ray test, in a small room and a floor-plan-sized world.
#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>

#include "crowdsim/collision_world.h"

namespace crowdsim {
namespace {

constexpr int kBeams = 45;
constexpr double kMaxRange = 5.0;
constexpr int kOrigins = 64;

struct Scene {
  std::shared_ptr<const StaticMap> map;
  std::vector<Circle> humans;
  std::vector<Vec2> origins;     // free of rectangles and humans; scans cycle through them
  std::vector<double> angles;    // 45 beams over 180 deg, world frame
  std::vector<Vec2> directions;  // the same beams as unit vectors (what lidar2d passes)
};

bool Free(const Scene& s, const Vec2& p, double clearance) {
  for (const Rect& r : s.map->rectangles) {
    if (PointToRectDistance(p, r) < clearance) return false;
  }
  for (const Circle& c : s.humans) {
    if ((p - c.center).norm() < c.radius + clearance) return false;
  }
  return true;
}

void AddWalls(double size, std::vector<Rect>* rects) {
  rects->push_back(Rect::FromCorners(0, 0, size, 0.1));
  rects->push_back(Rect::FromCorners(0, size - 0.1, size, size));
  rects->push_back(Rect::FromCorners(0, 0, 0.1, size));
  rects->push_back(Rect::FromCorners(size - 0.1, 0, size, size));
}

// Fills humans and origins at random free places of `size` x `size`.
void Populate(Scene* s, double size, int humans, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.5, size - 0.5);
  while (static_cast<int>(s->humans.size()) < humans) {
    const Vec2 p(u(rng), u(rng));
    if (Free(*s, p, 0.3)) s->humans.push_back({p, 0.3});
  }
  while (static_cast<int>(s->origins.size()) < kOrigins) {
    const Vec2 p(u(rng), u(rng));
    if (Free(*s, p, 0.3)) s->origins.push_back(p);
  }
  for (int k = 0; k < kBeams; ++k) {
    s->angles.push_back(-0.5 * std::numbers::pi + k * std::numbers::pi / (kBeams - 1));
    s->directions.emplace_back(std::cos(s->angles.back()), std::sin(s->angles.back()));
  }
}

// The paper's training world: a 10 x 10 room with 3 boxes and 5 humans.
const Scene& Room() {
  static const Scene scene = [] {
    Scene s;
    auto map = std::make_shared<StaticMap>();
    AddWalls(10.0, &map->rectangles);
    map->rectangles.push_back(Rect::FromCorners(2.0, 2.0, 3.0, 4.0));
    map->rectangles.push_back(Rect::FromCorners(6.0, 5.5, 7.5, 6.5));
    map->rectangles.push_back(Rect::FromCorners(4.0, 7.5, 4.8, 8.5));
    map->bounds = Rect::FromCorners(0, 0, 10, 10);
    s.map = map;
    Populate(&s, 10.0, 5, 1);
    return s;
  }();
  return scene;
}

// A floor-plan-sized world: 25 x 25 m, 30 rectangles (walls with doors, boxes), 20 humans.
const Scene& FloorPlan() {
  static const Scene scene = [] {
    Scene s;
    auto map = std::make_shared<StaticMap>();
    AddWalls(25.0, &map->rectangles);
    // Two interior walls each way, each with two door gaps: 4 x 3 = 12 segments.
    for (double c : {8.3, 16.6}) {
      for (auto [a, b] : {std::pair{0.1, 3.5}, std::pair{4.5, 12.0}, std::pair{13.0, 24.9}}) {
        map->rectangles.push_back(Rect::FromCorners(c, a, c + 0.15, b));
        map->rectangles.push_back(Rect::FromCorners(a, c, b, c + 0.15));
      }
    }
    // 14 pieces of furniture.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> pos(0.5, 23.0);
    std::uniform_real_distribution<double> size(0.4, 1.5);
    while (map->rectangles.size() < 30) {
      const double x = pos(rng), y = pos(rng);
      map->rectangles.push_back(Rect::FromCorners(x, y, x + size(rng), y + size(rng)));
    }
    map->bounds = Rect::FromCorners(0, 0, 25, 25);
    s.map = map;
    Populate(&s, 25.0, 20, 2);
    return s;
  }();
  return scene;
}

void BruteForceScan(const Scene& s, const Vec2& origin, double* ranges) {
  for (size_t k = 0; k < s.angles.size(); ++k) {
    const Vec2 dir(std::cos(s.angles[k]), std::sin(s.angles[k]));
    double best = kMaxRange;
    for (const Rect& r : s.map->rectangles) best = std::min(best, RayRectDistance(origin, dir, r));
    for (const Circle& c : s.humans) {
      best = std::min(best, RayCircleDistance(origin, dir, c.center, c.radius));
    }
    ranges[k] = best;
  }
}

// kFast takes world angles (a sine and cosine per beam); kFastDirections the beams' unit
// vectors, as the lidar2d sensor passes them (its fixed beams rotated by the heading).
enum class Variant { kFast, kFastDirections, kBruteForce, kBullet };

void Scan(benchmark::State& state, const Scene& (*scene)(), Variant variant) {
  const Scene& s = scene();
  CollisionWorld world(s.map);
  double ranges[kBeams];
  size_t i = 0;
  for (auto _ : state) {
    const Vec2& origin = s.origins[i++ % s.origins.size()];
    switch (variant) {
      case Variant::kFast:
        world.CastRays(origin, s.angles, kMaxRange, s.humans, ranges);
        break;
      case Variant::kFastDirections:
        world.CastRays(origin, s.directions, kMaxRange, s.humans, ranges);
        break;
      case Variant::kBruteForce:
        BruteForceScan(s, origin, ranges);
        break;
      case Variant::kBullet:
        world.CastRaysBullet(origin, s.angles, kMaxRange, ranges);
        break;
    }
    benchmark::DoNotOptimize(ranges);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * kBeams);
}

BENCHMARK_CAPTURE(Scan, room_fast, &Room, Variant::kFast)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Scan, room_fast_directions, &Room, Variant::kFastDirections)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Scan, room_brute_force, &Room, Variant::kBruteForce)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Scan, room_bullet_no_humans, &Room, Variant::kBullet)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Scan, floorplan_fast, &FloorPlan, Variant::kFast)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Scan, floorplan_fast_directions, &FloorPlan, Variant::kFastDirections)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Scan, floorplan_brute_force, &FloorPlan, Variant::kBruteForce)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(Scan, floorplan_bullet_no_humans, &FloorPlan, Variant::kBullet)
    ->Unit(benchmark::kMicrosecond);

// One robot step's obstacle check: a 0.3 m disc swept over 0.25 s at up to 2 m/s.
void Sweep(benchmark::State& state, const Scene& (*scene)()) {
  const Scene& s = scene();
  CollisionWorld world(s.map);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> step(-0.5, 0.5);
  std::vector<std::pair<Vec2, Vec2>> moves;
  for (const Vec2& o : s.origins) moves.push_back({o, o + Vec2(step(rng), step(rng))});
  size_t i = 0;
  for (auto _ : state) {
    const auto& [a, b] = moves[i++ % moves.size()];
    benchmark::DoNotOptimize(world.SweepDisc(a, b, 0.3));
  }
}

BENCHMARK_CAPTURE(Sweep, room, &Room)->Unit(benchmark::kNanosecond);
BENCHMARK_CAPTURE(Sweep, floorplan, &FloorPlan)->Unit(benchmark::kNanosecond);

}  // namespace
}  // namespace crowdsim
