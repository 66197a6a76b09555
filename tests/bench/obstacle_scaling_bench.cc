// Obstacle scaling: one whole episode step with 20 ORCA humans and the costly robot (ORCA,
// lidar 45 beams + person) among 0, 3, 30 and 100 boxes (plus 4 walls), to show what grows
// with the obstacles (ORCA obstacle lines, lidar, sweeps) while the crowd stays the same.
//
// The frozen random_rect rooms stop at 3 obstacles, so the rooms are built here, one room for
// every count so that only the count changes: 22 x 22 m inside four walls, a 10 x 10 grid of
// 2 m cells of which the first N of a fixed shuffle hold one box (0.6-1.2 m sides). A box stays
// 0.4 m inside its cell, so neighbouring boxes leave at least 0.8 m for a 0.6 m disc: the free
// space is always connected, which human placement needs, and the robot's line x = 0 is a
// corridor between cells. The humans of measured episode k are placed with seed 14 + k (see
// TimeSteps: a replayed episode is learned by the branch predictor).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

#include "crowdsim/human_placement.h"
#include "crowdsim/rng.h"
#include "episode_bench.h"

namespace crowdsim {
namespace {

constexpr int kHumans = 20;
constexpr double kHalf = 11.0;  // m; the room inside the walls is [-kHalf, kHalf]^2
constexpr int kCells = 10;      // per side, 2 m each, over [-10, 10]^2

std::shared_ptr<const StaticMap> MakeBoxRoom(int boxes) {
  auto map = std::make_shared<StaticMap>();
  const double w = kHalf + 0.5;
  map->name = "boxes_" + std::to_string(boxes);
  map->bounds = Rect::FromCorners(-w, -w, w, w);
  map->rectangles = {Rect::FromCorners(-w, -w, w, -kHalf), Rect::FromCorners(-w, kHalf, w, w),
                     Rect::FromCorners(-w, -kHalf, -kHalf, kHalf),
                     Rect::FromCorners(kHalf, -kHalf, w, kHalf)};
  // One shuffle for every count: the 30-box room contains the 3-box room's boxes.
  std::vector<int> cells(kCells * kCells);
  std::iota(cells.begin(), cells.end(), 0);
  Rng rng(7);
  for (std::size_t i = cells.size() - 1; i > 0; --i) std::swap(cells[i], cells[rng.Below(i + 1)]);
  for (int k = 0; k < boxes; ++k) {
    const double x0 = -10.0 + 2.0 * (cells[k] % kCells);
    const double y0 = -10.0 + 2.0 * (cells[k] / kCells);
    const double sx = rng.Uniform(0.6, 1.2), sy = rng.Uniform(0.6, 1.2);
    const double x = x0 + rng.Uniform(0.4, 1.6 - sx), y = y0 + rng.Uniform(0.4, 1.6 - sy);
    map->rectangles.push_back(Rect::FromCorners(x, y, x + sx, y + sy));
  }
  return map;
}

// The room of `boxes` boxes with the humans of episode `episode` (placed with seed 14 + episode).
Scenario MakeBoxScenario(std::shared_ptr<const StaticMap> map, int episode) {
  Scenario s;
  s.map = std::move(map);
  s.robot_start = Vec2(0.0, -10.5);
  s.robot_goal = Vec2(0.0, 10.5);
  ScenarioRequest request;
  request.num_humans = kHumans;
  const HumanPlacementOptions options = HumanPlacementOptions::FromRequest(request);
  const DiscFreeSpace free_space(s.map, options.human_radius + 0.1);
  PlacementArea area;
  area.is_free = [&free_space](const Vec2& p) { return free_space.Contains(p); };
  area.sample = UniformSampler(Rect::FromCorners(-kHalf, -kHalf, kHalf, kHalf));
  Rng rng(14 + static_cast<std::uint64_t>(episode));
  s.humans = PlaceHumans(area, s.robot_start, s.robot_goal, request, options, rng);
  return s;
}

void BM_ObstacleStep(benchmark::State& state) {
  const int boxes = static_cast<int>(state.range(0));
  bench::RowAgents row(bench::RobotKind::kOrcaLidarPerson, kHumans);
  const std::shared_ptr<const StaticMap> map = MakeBoxRoom(boxes);
  bench::TimeSteps(
      state, [&](int episode) { return MakeBoxScenario(map, episode); }, row.agents, kHumans + 1);
}
BENCHMARK(BM_ObstacleStep)
    ->ArgName("boxes")
    ->Arg(0)
    ->Arg(3)
    ->Arg(30)
    ->Arg(100)
    ->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace crowdsim
