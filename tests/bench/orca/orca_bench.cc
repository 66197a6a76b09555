// ORCA costs: one decision in a typical CrowdSim++ scene, its agent lines (scalar and AVX2),
// the obstacle query, the roadmap's path search, one step of RVO2's Blocks, and one decision of
// the loaded plugin (guidance included).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

#include "crowdsim/agent_index.h"
#include "crowdsim/bench/plugin_registry.h"
#include "human_decision.h"
#include "orca/agent_lines.h"
#include "orca/geometry.h"
#include "orca/obstacles.h"
#include "orca/roadmap.h"
#include "orca/solver.h"
#include "orca_test_sim.h"
#include "test_paths.h"

namespace crowdsim::orca {
namespace {

using bench::SevenRects;

// Five humans around the agent, walking in various directions.
std::vector<OrcaAgent> FiveNeighbours() {
  return {{Vec2(1.0, 1.2), Vec2(-0.6, 0.1), 0.31},
          {Vec2(-1.2, -0.8), Vec2(0.5, 0.5), 0.31},
          {Vec2(0.2, -1.6), Vec2(0.0, 0.9), 0.31},
          {Vec2(-2.0, 0.3), Vec2(0.8, -0.2), 0.31},
          {Vec2(1.1, 2.6), Vec2(-0.3, -0.9), 0.31}};
}

void BM_OrcaDecision5Neighbours7Rects(benchmark::State& state) {
  const std::vector<Rect> rects = SevenRects();
  const OrcaObstacles obstacles = OrcaObstacles::FromRects(rects);
  const std::vector<OrcaAgent> neighbours = FiveNeighbours();
  const OrcaAgent self{Vec2::Zero(), Vec2(0.8, 0.2), 0.31};
  const OrcaParams params{5.0, 5.0, 1.0};
  OrcaSolveInfo info;
  for (auto _ : state) {
    benchmark::DoNotOptimize(
        ComputeOrcaVelocity(self, neighbours, obstacles, params, Vec2(1.0, 0.0), 0.25, &info));
  }
  state.counters["lines"] = static_cast<double>(info.num_lines);
  state.counters["obstacle_lines"] = static_cast<double>(info.num_obstacle_lines);
}
BENCHMARK(BM_OrcaDecision5Neighbours7Rects);

// The agent lines alone (avx2: 0 one neighbour at a time, 1 four at a time in AVX2 lanes) for
// the first 4 or all 5 neighbours above, or 10 (two copies): a CrowdNav human has 4, its robot
// 5, a human of a larger crowd RVO2's 10.
void BM_AgentLines(benchmark::State& state) {
  const bool vector = state.range(0) == 1;
  if (vector && !HaveAvx2()) {
    state.SkipWithError("this processor runs no AVX2");
    return;
  }
  const std::vector<OrcaAgent> five = FiveNeighbours();
  std::vector<OrcaAgent> neighbours;
  while (neighbours.size() < static_cast<std::size_t>(state.range(1))) {
    neighbours.push_back(five[neighbours.size() % five.size()]);
  }
  const OrcaAgent self{Vec2::Zero(), Vec2(0.8, 0.2), 0.31};
  const OrcaParams params{5.0, 5.0, 1.0};
  std::vector<OrcaLine> lines(neighbours.size());
  for (auto _ : state) {
    if (vector) {
      AddAgentLinesAvx2(self, neighbours, params, 0.25, lines.data());
    } else {
      AddAgentLinesScalar(self, neighbours, params, 0.25, lines.data());
    }
    benchmark::DoNotOptimize(lines.data());
    benchmark::ClobberMemory();
  }
}
BENCHMARK(BM_AgentLines)->ArgNames({"avx2", "neighbours"})->ArgsProduct({{0, 1}, {4, 5, 10}});

// `count` boxes with sides of 0.5-1.5 m at random places of the square [0, side]^2.
std::vector<Rect> ScatteredBoxes(int count, double side, std::mt19937& rng) {
  std::uniform_real_distribution<double> where(0.0, side), size(0.5, 1.5);
  std::vector<Rect> rects;
  for (int i = 0; i < count; ++i) {
    const double x = where(rng), y = where(rng);
    rects.push_back(Rect::FromCorners(x, y, x + size(rng), y + size(rng)));
  }
  return rects;
}

// The obstacle edges near an agent (range 5.3 m, a CrowdNav human's), among boxes of 0.5-1.5 m
// scattered over a square: 30 in 12 m (a Gibson plan's count and size) and 600 in 44 m (an
// S3DIS building floor's), queried from random points.
void BM_ObstacleQuery(benchmark::State& state) {
  const int boxes = static_cast<int>(state.range(0));
  const double side = state.range(1);
  std::mt19937 rng(3);
  const std::vector<Rect> rects = ScatteredBoxes(boxes, side, rng);
  std::uniform_real_distribution<double> where(0.0, side);
  const OrcaObstacles obstacles = OrcaObstacles::FromRects(rects);
  std::vector<Vec2> points(256);
  for (Vec2& p : points) p = Vec2(where(rng), where(rng));
  std::vector<ObstacleNeighbor> near;
  std::size_t next = 0;
  double edges = 0.0;
  for (auto _ : state) {
    obstacles.Query(points[next], 5.3, &near);
    next = (next + 1) % points.size();
    edges += static_cast<double>(near.size());
    benchmark::DoNotOptimize(near.data());
  }
  state.counters["edges"] = edges / static_cast<double>(state.iterations());
}
BENCHMARK(BM_ObstacleQuery)->Args({30, 12})->Args({600, 44});

// The roadmap's path search, as an ORCA human replans round the boxes between it and its goal
// (ORCA's defaults: radius 0.3 m + 0.01 padding, corners 0.2 m farther out): trips between random
// free points among boxes of 0.5-1.5 m, 30 in 12 m and 100 in 22 m.
void BM_RoadmapShortestPath(benchmark::State& state) {
  const int boxes = static_cast<int>(state.range(0));
  const double side = state.range(1);
  std::mt19937 rng(5);
  const std::vector<Rect> rects = ScatteredBoxes(boxes, side, rng);
  std::uniform_real_distribution<double> where(0.0, side);
  const double clearance = 0.31;
  const Roadmap roadmap(rects, Rect::FromCorners(0.0, 0.0, side, side), clearance, 0.2);
  std::vector<std::pair<Vec2, Vec2>> trips;
  auto free_point = [&]() {
    for (;;) {
      const Vec2 p(where(rng), where(rng));
      if (DistanceToRects(rects, p) > clearance) return p;
    }
  };
  while (trips.size() < 256) trips.emplace_back(free_point(), free_point());
  std::size_t next = 0;
  double found = 0.0, waypoints = 0.0;
  for (auto _ : state) {
    const std::vector<Vec2> path = roadmap.ShortestPath(trips[next].first, trips[next].second);
    next = (next + 1) % trips.size();
    found += path.empty() ? 0.0 : 1.0;
    waypoints += static_cast<double>(path.size());
  }
  const auto n = static_cast<double>(state.iterations());
  state.counters["nodes"] = static_cast<double>(roadmap.nodes().size());
  state.counters["found"] = found / n;
  state.counters["waypoints"] = waypoints / n;
}
BENCHMARK(BM_RoadmapShortestPath)->Args({30, 12})->Args({100, 22})->Unit(benchmark::kMicrosecond);

// RVO2's Blocks (reference facts 2.6), restarted whenever every agent is within 20 m.
testing::TestSim MakeBlocks() { return testing::MakeBlocksSim(0.25); }

void BM_Blocks100AgentStep(benchmark::State& state) {
  testing::TestSim sim = MakeBlocks();
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  std::uniform_real_distribution<double> size(0.0, 0.0001);
  for (auto _ : state) {
    bool done = true;
    for (auto& a : sim.agents()) {
      const Vec2 d = a.goal - a.state.position;
      done = done && d.squaredNorm() <= 400.0;
      const double phi = angle(rng);
      a.pref_velocity = testing::TowardsGoal(a) + size(rng) * Vec2(std::cos(phi), std::sin(phi));
    }
    if (done) {
      state.PauseTiming();
      sim = MakeBlocks();
      state.ResumeTiming();
    }
    sim.Step();
  }
  state.SetItemsProcessed(state.iterations() * 100);  // agent decisions
}
BENCHMARK(BM_Blocks100AgentStep)->Unit(benchmark::kMicrosecond)->MinTime(3.0);

// The plugin as the harness runs it for a human: neighbour query, guidance, ORCA.
void BM_PluginDecideHuman(benchmark::State& state) {
  std::vector<AgentState> others;
  for (const OrcaAgent& n : FiveNeighbours()) {
    AgentState s;
    s.position = n.position;
    s.velocity = n.velocity;
    others.push_back(s);
  }
  bench::TimeHumanDecision(state, "orca", others);
}
BENCHMARK(BM_PluginDecideHuman);

}  // namespace
}  // namespace crowdsim::orca
