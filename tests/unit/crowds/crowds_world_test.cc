// The crowds world and the replay policy: windows, presence, the robot's crossing, and episodes
// in which every recorded person is where it was recorded, and absent people are nobody.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "crowd_scene.h"
#include "crowd_tracks/track_position.h"
#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/plugin_registry.h"
#include "suite_runs.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

using crowdsim::testing::TempDir;

// A robot that stands still: the people alone move.
class StandStill final : public Policy {
 public:
  Action Decide(const Observation&) override { return Action{}; }
};

class CrowdsWorld : public ::testing::Test {
 protected:
  void SetUp() override { tracks_ = testing::WriteSyntheticTracks(dir_.path()); }
  std::shared_ptr<WorldSource> World(const std::string& split) {
    const LoadedPlugin& p = registry_.Load("crowds", PluginKind::kWorld);
    Params params = Params::Defaults(p.schema);
    params.Set("file", tracks_.string());
    params.Set("split", split);
    return registry_.MakeWorld(p, params);
  }
  std::shared_ptr<Policy> Plugin(const char* name) {
    const LoadedPlugin& p = registry_.Load(name, PluginKind::kPolicy);
    return registry_.MakePolicy(p, Params::Defaults(p.schema));
  }
  static ScenarioRequest Request(int humans, std::int64_t episode = 0) {
    ScenarioRequest r;
    r.seed = 11 + static_cast<std::uint64_t>(episode);
    r.episode_index = episode;
    r.num_humans = humans;
    return r;
  }
  TempDir dir_;
  std::filesystem::path tracks_;
  PluginRegistry registry_{{crowdsim::testing::PluginDir()}};
};

TEST_F(CrowdsWorld, AWindowHoldsItsRecordedPeopleAndTheRestAreNeverPresent) {
  const auto train = World("train");
  const auto test = World("test");
  EXPECT_EQ(train->Identity(), "crowds:synthetic:train");
  // 60 s: two whole 25 s windows, the first for training, the last for tests.
  EXPECT_EQ(train->LayoutCount(), 1);
  EXPECT_EQ(test->LayoutCount(), 1);
  const Scenario s = train->Make(Request(6));
  ASSERT_EQ(s.humans.size(), 6u);
  // Persons 1 (0-60 s) and 2 (4-16 s) walk in [0, 25] s; the other four never appear.
  EXPECT_DOUBLE_EQ(s.humans[0].appear, 0.0);
  EXPECT_DOUBLE_EQ(s.humans[0].leave, 60.0);
  EXPECT_NEAR(s.humans[1].appear, 4.0, 1e-12);
  EXPECT_NEAR(s.humans[1].leave, 16.0, 1e-12);
  EXPECT_EQ(s.humans[1].start, Vec2(3.0, 2.0));  // where it appears
  for (int i = 2; i < 6; ++i) EXPECT_FALSE(PresentAt(s.humans[i], 10.0));
  EXPECT_NE(s.map->attribution.find("none (a test)"), std::string::npos);
  // The test window starts at 25 s: person 1 mid-track is present from step 0.
  const Scenario t = test->Make(Request(6));
  EXPECT_DOUBLE_EQ(t.humans[0].appear, 0.0);
  EXPECT_LT((t.humans[0].start - Vec2(-1.0, 0.0)).norm(), 1e-9);
  EXPECT_NEAR(t.humans[1].appear, 3.0, 1e-12);  // person 3 at 28 s
  EXPECT_NEAR(t.humans[2].appear, 7.0, 1e-12);  // person 4 at 32 s
}

TEST_F(CrowdsWorld, TheRobotCrossesTheMainFlowInsideTheArea) {
  const auto world = World("test");
  for (std::int64_t e = 0; e < 40; ++e) {
    const Scenario s = world->Make(Request(4, e));
    const Vec2 d = s.robot_goal - s.robot_start;
    // The people walk along x: the robot crosses along y, from edge to edge less 0.5 m.
    EXPECT_NEAR(d.x(), 0.0, 1e-9);
    EXPECT_NEAR(std::abs(d.y()), 4.0, 1e-9);
    EXPECT_LE(std::abs(s.robot_start.x()), 3.0 + 1e-9);
    EXPECT_TRUE(s.map->bounds.Contains(s.robot_start));
  }
}

TEST_F(CrowdsWorld, ACrowdSmallerThanAWindowIsRefusedWithTheCountNeeded) {
  try {
    World("test")->Make(Request(2));
    FAIL() << "3 people fitted in humans.count 2";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "crowds: window synthetic/test/0 holds 3 people, more than humans.count 2: set "
              "humans.count to at least 3 (the most of any window of this split)");
  }
}

// Every step of a test episode: each person present exactly in its recorded span, on its track
// (at recorded times: at its recorded position), and the sensors and judgement see the present.
TEST_F(CrowdsWorld, ReplayPutsEveryoneWhereAndWhenTheyWereRecorded) {
  const crowd_tracks::Tracks recorded = crowd_tracks::ReadTracks(tracks_);
  Scenario s = World("test")->Make(Request(5));
  s.robot_start = Vec2(5.5, -1.5);
  s.robot_goal = Vec2(5.5, 2.5);
  SimConfig sim;  // dt 0.25 s, 25 s
  StandStill robot;
  std::vector<std::shared_ptr<Policy>> people;
  EpisodeAgents agents{&robot, {}, {}, {}};
  for (int i = 0; i < 5; ++i) agents.humans.push_back(people.emplace_back(Plugin("replay")).get());
  const LoadedPlugin& person = registry_.Load("person", PluginKind::kSensor);
  const auto sensor = registry_.MakeSensor(person, Params::Defaults(person.schema));
  agents.sensors.push_back(MountedSensor{"person", sensor.get()});
  Episode episode(s, sim, agents);
  int recorded_checks = 0;
  while (!episode.done()) {
    const double t = episode.time();
    std::size_t present = 0;
    for (std::size_t i = 0; i < s.humans.size(); ++i) {
      const HumanSpec& h = s.humans[i];
      if (!PresentAt(h, t)) continue;
      ++present;
      const Vec2 at = episode.humans()[i].position;
      EXPECT_LT((at - crowd_tracks::TrackPosition(h.track, t)).norm(), 1e-9) << i << " " << t;
      // A recorded frame (every 2 s is both a step and a frame): the recorded position itself.
      const double frame = (t + 25.0) / crowd_tracks::kFramePeriod;
      if (std::abs(frame - std::round(frame)) < 1e-9) {
        const crowd_tracks::RecordedPerson& p = recorded.people[i == 0 ? 0 : i + 1];
        const auto k = static_cast<std::size_t>(std::llround(frame) - p.first_frame);
        EXPECT_LT((at - p.positions[k]).norm(), 1e-9) << i << " " << t;
        ++recorded_checks;
      }
    }
    EXPECT_EQ(episode.present_humans().size(), present) << t;
    EXPECT_EQ(episode.ObserveRobot().readings[0].people.size(), present) << t;
    episode.Step();
  }
  EXPECT_EQ(episode.result().status, EpisodeStatus::kTimeout);
  EXPECT_GT(recorded_checks, 20);
}

TEST_F(CrowdsWorld, TheRobotNeverHitsAnAbsentPerson) {
  Scenario s = World("test")->Make(Request(5));
  // On person 3's spot before it appears (3 s), then on a never-present person's.
  for (const Vec2& spot : {s.humans[1].start, s.humans[4].start}) {
    s.robot_start = spot;
    s.robot_goal = spot + Vec2(0.0, 0.5);
    StandStill robot;
    std::vector<std::shared_ptr<Policy>> people;
    EpisodeAgents agents{&robot, {}, {}, {}};
    for (int i = 0; i < 5; ++i) {
      agents.humans.push_back(people.emplace_back(Plugin("replay")).get());
    }
    Episode episode(s, SimConfig{}, agents);
    for (int k = 0; k < 8; ++k) episode.Step();  // 2 s
    EXPECT_EQ(episode.result().status, EpisodeStatus::kRunning);
    EXPECT_EQ(episode.result().collided_human, -1);
  }
}

TEST_F(CrowdsWorld, TheSameSeedGivesTheSameEpisodesOnAnyThreads) {
  const auto file =
      dir_.Write("replay.yaml",
                 "name: replay_threads\nepisodes: 4\nseed: 5\n"
                 "world: {source: crowds, file: synthetic.tracks, split: test}\n"
                 "humans: {count: 4, policy: replay}\n"
                 "robot: {sensors: [person, {type: lidar2d, beams: 45}]}\n"
                 "rows:\n  - {label: orca, policy: orca}\n  - {label: linear, policy: linear}\n");
  const auto runs = testing::RunOnOneAndTwoThreads(file, dir_.path() / "runs");
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[0].rows, 2u);
  EXPECT_EQ(runs[0].episodes, runs[1].episodes);
}

}  // namespace
}  // namespace crowdsim
