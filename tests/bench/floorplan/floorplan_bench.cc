// Import time of the largest source floor plan (target: well under a second).
#include <benchmark/benchmark.h>

#include "floorplan/floorplan_import.h"
#include "test_paths.h"

namespace {

// area6_floor_0: 1700 x 1700 px at 0.019 m/px, the largest Gibson map by pixel count.
void BM_ImportLargestPlan(benchmark::State& state) {
  const auto image =
      crowdsim::testing::SharedDir() / "floorplans" / "gibson" / "maps" / "area6_floor_0.png";
  if (!std::filesystem::exists(image)) {
    state.SkipWithError("source floor plans not found (../shared/floorplans)");
    return;
  }
  for (auto _ : state) {
    auto result = crowdsim::floorplan::ImportFloorplan(image, {});
    benchmark::DoNotOptimize(result.world.rectangles.data());
  }
}
BENCHMARK(BM_ImportLargestPlan)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
