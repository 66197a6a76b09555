// The validation against recorded people (tools/crowds): its metrics against hand-worked numbers,
// people replayed by the replay policy itself (ADE 0), a straight walker walked by linear (ADE
// 0), and the same table from two runs.
#include <gtest/gtest.h>

#include <vector>

#include "crowd_scene.h"
#include "crowds/scene_validation.h"
#include "crowds/validation_table.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim::crowds {
namespace {

TEST(TrackComparison, AnOffsetTrackHasTheOffsetAsAdeAndFde) {
  std::vector<Vec2> recorded, simulated;
  for (int k = 0; k <= 12; ++k) {
    recorded.emplace_back(0.5 * k, 0.1 * k * k);
    simulated.push_back(recorded.back() + Vec2(0.3, 0.4));
  }
  const TrackComparison c = CompareTracks(simulated, recorded, 4.8);
  EXPECT_NEAR(c.ade, 0.5, 1e-12);
  EXPECT_NEAR(c.fde, 0.5, 1e-12);
  EXPECT_NEAR(c.simulated_speed, c.recorded_speed, 1e-12);
}

TEST(TrackComparison, AStandingPersonAgainstAWalkingOne) {
  // Recorded: 1 m a point along x; simulated: standing at the start. Errors 1 and 2 m.
  const std::vector<Vec2> recorded{{0, 0}, {1, 0}, {2, 0}};
  const std::vector<Vec2> simulated(3, Vec2(0, 0));
  const TrackComparison c = CompareTracks(simulated, recorded, 0.8);
  EXPECT_DOUBLE_EQ(c.ade, 1.5);
  EXPECT_DOUBLE_EQ(c.fde, 2.0);
  EXPECT_DOUBLE_EQ(c.simulated_speed, 0.0);
  EXPECT_DOUBLE_EQ(c.recorded_speed, 2.5);
  EXPECT_THROW(CompareTracks(simulated, std::vector<Vec2>(2, Vec2(0, 0)), 0.8),
               std::invalid_argument);
}

TEST(ValidationTable, SummariesAreMeansOverThePeople) {
  std::vector<PersonValidation> people(2);
  people[0].comparison = {1.0, 2.0, 1.0, 1.2};
  people[1].comparison = {3.0, 4.0, 0.6, 1.0};
  people[1].collided = true;
  const ValidationRow r = Summarise("s", "m", people);
  EXPECT_EQ(r.people, 2);
  EXPECT_DOUBLE_EQ(r.ade, 2.0);
  EXPECT_DOUBLE_EQ(r.fde, 3.0);
  EXPECT_DOUBLE_EQ(r.collision_rate, 0.5);
  EXPECT_DOUBLE_EQ(r.simulated_speed, 0.8);
  EXPECT_DOUBLE_EQ(r.recorded_speed, 1.1);
  EXPECT_EQ(ValidationCsv(std::vector<ValidationRow>{r}),
            "scene,model,people,ade_m,fde_m,collision_rate,simulated_speed_mps,"
            "recorded_speed_mps\ns,m,2,2.0000,3.0000,0.5000,0.8000,1.1000\n");
}

class SceneValidationTest : public ::testing::Test {
 protected:
  std::shared_ptr<Policy> Plugin(const char* name) {
    const LoadedPlugin& p = registry_.Load(name, PluginKind::kPolicy);
    return registry_.MakePolicy(p, Params::Defaults(p.schema));
  }
  testing::TempDir dir_;
  PluginRegistry registry_{{testing::PluginDir()}};
};

// The synthetic scene's people observed from their first frame to their last inside a window:
// person 3 in the test window (25-50 s), walking +x at 0.25 m/s over 28-40 s, and person 2 in the
// train window (0-25 s), walking -x at 0.5 m/s over 4-16 s.
TEST_F(SceneValidationTest, ReplayAndAStraightWalkerHaveNoError) {
  const SceneValidation scene(registry_, testing::WriteSyntheticTracks(dir_.path()),
                              ValidationSettings{});
  EXPECT_EQ(scene.scene(), "synthetic");
  for (const char* model : {"replay", "linear"}) {
    const auto policy = Plugin(model);
    const std::vector<PersonValidation> people = scene.Run(*policy);
    ASSERT_EQ(people.size(), 2u) << model;
    EXPECT_EQ(people[0].split, "test");
    EXPECT_EQ(people[1].split, "train");
    for (std::size_t k = 0; k < people.size(); ++k) {
      const TrackComparison& c = people[k].comparison;
      EXPECT_LT(c.ade, 1e-9) << model;
      EXPECT_LT(c.fde, 1e-9) << model;
      EXPECT_NEAR(c.recorded_speed, k == 0 ? 0.25 : 0.5, 1e-9) << model;
      EXPECT_NEAR(c.simulated_speed, c.recorded_speed, 1e-9) << model;
      EXPECT_FALSE(people[k].collided) << model;
    }
  }
}

// On a recorded scene, replay walking each person itself stays within the interpolation
// tolerance: the path sampled at 0.25 s steps cuts the corners of the 0.4 s track, by at most
// about half a step's walk (0.19 m at 1.5 m/s) where a person turns sharply.
TEST_F(SceneValidationTest, ReplayOnARecordedSceneIsWithinInterpolationTolerance) {
  const SceneValidation scene(registry_, testing::SourceDir() / "worlds/crowds/zara1.tracks",
                              ValidationSettings{});
  const auto replay = Plugin("replay");
  const std::vector<PersonValidation> people = scene.Run(*replay);
  ASSERT_EQ(people.size(), 88u);  // results/crowds_validation/table.md
  for (const PersonValidation& p : people) {
    EXPECT_LT(p.comparison.ade, 0.1) << p.split << " window " << p.window << " person " << p.person;
    EXPECT_LT(p.comparison.fde, 0.1) << p.split << " window " << p.window << " person " << p.person;
  }
  const ValidationRow row = Summarise(scene.scene(), "replay", people);
  EXPECT_LT(row.ade, 0.005);
  EXPECT_LT(row.fde, 0.005);
}

TEST_F(SceneValidationTest, TwoRunsGiveTheSameTable) {
  const SceneValidation scene(registry_, testing::WriteSyntheticTracks(dir_.path()),
                              ValidationSettings{});
  std::vector<std::string> tables;
  for (int run = 0; run < 2; ++run) {
    std::vector<ValidationRow> rows;
    for (const char* model : {"orca", "social_force", "hsfm"}) {
      const auto policy = Plugin(model);
      rows.push_back(Summarise(scene.scene(), model, scene.Run(*policy)));
    }
    tables.push_back(ValidationCsv(rows));
  }
  EXPECT_EQ(tables[0], tables[1]);
}

}  // namespace
}  // namespace crowdsim::crowds
