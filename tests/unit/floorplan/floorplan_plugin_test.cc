// The `floorplan` world plugin on a synthetic imported world.
#include <gtest/gtest.h>

#include <thread>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/world_file.h"
#include "floorplan/floorplan_import.h"
#include "floorplan_test_util.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim::floorplan {
namespace {

using crowdsim::testing::PluginDir;
using crowdsim::testing::TempDir;

class FloorplanPluginTest : public ::testing::Test {
 protected:
  void SetUp() override {
    Grid g = testing::OutlineRoom(140, 10, 10, 120, 8);
    testing::Fill(g, 50, 50, 69, 79, 0);
    testing::WritePgm(g, dir_.path() / "room.pgm");
    ImportOptions o;
    o.source_resolution = 0.1;
    o.test_pairs = 7;
    o.train_pairs = 5;
    o.free_points = 60;
    WriteWorldFile(ImportFloorplan(dir_.path() / "room.pgm", o).world, dir_.path() / "room.yaml");
    world_ = ReadWorldFile(dir_.path() / "room.yaml");
  }

  std::shared_ptr<WorldSource> Make(const std::string& world, const std::string& split) {
    const LoadedPlugin& p = registry_.Load("floorplan", PluginKind::kWorld);
    Params params = Params::Defaults(p.schema, dir_.path());
    params.Set("file", world);
    params.Set("split", split);
    return registry_.MakeWorld(p, params);
  }

  TempDir dir_;
  WorldFile world_;
  PluginRegistry registry_{{PluginDir()}};
};

TEST_F(FloorplanPluginTest, PairsCycleThroughTheSplit) {
  const auto test = Make("room.yaml", "test");  // relative to the suite folder
  EXPECT_EQ(test->Identity(), "floorplan:room:test");
  ScenarioRequest req;
  req.num_humans = 4;
  for (int k : {0, 3, 7, 10}) {
    req.episode_index = k;
    req.seed = 100 + k;
    const Scenario s = test->Make(req);
    EXPECT_EQ(s.robot_start, world_.test_pairs[k % 7].start);
    EXPECT_EQ(s.robot_goal, world_.test_pairs[k % 7].goal);
    ASSERT_EQ(s.humans.size(), 4u);
    for (const auto& h : s.humans) {
      for (const Rect& r : s.map->rectangles) EXPECT_GE(PointToRectDistance(h.start, r), h.radius);
    }
  }
  const auto train = Make((dir_.path() / "room.yaml").string(), "train");
  req.episode_index = 6;
  EXPECT_EQ(train->Make(req).robot_start, world_.train_pairs[1].start);
  EXPECT_EQ(train->Identity(), "floorplan:room:train");
}

TEST_F(FloorplanPluginTest, SameRequestSameScenarioFromManyThreads) {
  const auto w = Make("room.yaml", "test");
  ScenarioRequest req;
  req.episode_index = 2;
  req.seed = 42;
  req.num_humans = 5;
  const Scenario a = w->Make(req);
  Scenario b;
  std::thread t([&] { b = w->Make(req); });
  t.join();
  ASSERT_EQ(a.humans.size(), b.humans.size());
  for (size_t i = 0; i < a.humans.size(); ++i) {
    EXPECT_EQ(a.humans[i].start, b.humans[i].start);
    EXPECT_EQ(a.humans[i].goals, b.humans[i].goals);
  }
  EXPECT_EQ(a.map, b.map);  // one immutable map shared by every episode
}

// The world file's mask reaches the episode's map, so renders draw it under the rectangles.
TEST_F(FloorplanPluginTest, StaticMapCarriesTheWorldsMask) {
  ASSERT_TRUE(world_.mask);
  const auto w = Make("room.yaml", "test");
  ScenarioRequest req;
  req.num_humans = 2;
  const Scenario s = w->Make(req);
  ASSERT_TRUE(s.map->mask);
  const NavigableMask& m = *s.map->mask;
  EXPECT_EQ(m.width, world_.mask->width);
  EXPECT_EQ(m.height, world_.mask->height);
  EXPECT_EQ(m.cells, world_.mask->cells);
  EXPECT_DOUBLE_EQ(m.resolution, 0.1);
  // The mask spans the world's bounds (the import crops both to the same window).
  EXPECT_NEAR(m.origin.x(), s.map->bounds.min.x(), 1e-9);
  EXPECT_NEAR(m.origin.y(), s.map->bounds.min.y(), 1e-9);
  EXPECT_NEAR(m.origin.x() + m.width * m.resolution, s.map->bounds.max.x(), 1e-9);
  EXPECT_NEAR(m.origin.y() + m.height * m.resolution, s.map->bounds.max.y(), 1e-9);
  // The robot starts on a navigable cell (row 0 at max y).
  const int col = static_cast<int>((s.robot_start.x() - m.origin.x()) / m.resolution);
  const int row =
      m.height - 1 - static_cast<int>((s.robot_start.y() - m.origin.y()) / m.resolution);
  EXPECT_TRUE(m.Navigable(row, col));
}

TEST_F(FloorplanPluginTest, MissingWorldIsAClearError) {
  try {
    Make("no/such/world.yaml", "test");
    ADD_FAILURE() << "no error";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("no/such/world.yaml"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace crowdsim::floorplan
