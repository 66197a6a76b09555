#include <gtest/gtest.h>

#include "crowdsim/metrics.h"
#include "crowdsim/results.h"
#include "temp_dir.h"

namespace crowdsim {
namespace {

EpisodeRecord Rec(EpisodeStatus s, double time, int steps, int danger, double path = 0, double dmin = kInfinity) {
  EpisodeRecord r;
  r.status = s;
  r.time = time;
  r.steps = steps;
  r.danger_steps = danger;
  r.path_length = path;
  r.min_human_distance = dmin;
  r.discounted_return = s == EpisodeStatus::kSuccess ? 0.5 : -0.25;
  r.decision_time_us = 10;
  return r;
}

TEST(Metrics, PaperColumnsOnHandMadeEpisodes) {
  const std::vector<EpisodeRecord> e = {
      Rec(EpisodeStatus::kSuccess, 10.0, 40, 4, 9.0, 0.3),
      Rec(EpisodeStatus::kSuccess, 12.0, 48, 0, 11.0, 0.5),
      Rec(EpisodeStatus::kCollisionHuman, 3.0, 12, 2, 3.0, -0.1),
      Rec(EpisodeStatus::kCollisionObstacle, 5.0, 20, 0, 5.0, 1.0),
      Rec(EpisodeStatus::kTimeout, 25.0, 100, 10),
  };
  const RowMetrics m = Aggregate(e, 25.0);
  EXPECT_EQ(m.episodes, 5);
  EXPECT_DOUBLE_EQ(m.success_rate, 0.4);
  EXPECT_DOUBLE_EQ(m.collision_rate, 0.4);
  EXPECT_DOUBLE_EQ(m.collision_human_rate, 0.2);
  EXPECT_DOUBLE_EQ(m.collision_obstacle_rate, 0.2);
  EXPECT_DOUBLE_EQ(m.timeout_rate, 0.2);
  EXPECT_DOUBLE_EQ(m.nav_time, 11.0);             // successful episodes only
  EXPECT_DOUBLE_EQ(m.path_length, 10.0);
  EXPECT_DOUBLE_EQ(m.danger_frequency, 16.0 / 220.0);  // danger steps / all steps
  EXPECT_DOUBLE_EQ(m.min_human_distance, (0.3 + 0.5 - 0.1 + 1.0) / 4.0);  // episodes with humans
  EXPECT_DOUBLE_EQ(m.discounted_return, (0.5 + 0.5 - 0.25 * 3) / 5.0);
}

TEST(Metrics, NoSuccessGivesTimeLimitAsNavTime) {
  const std::vector<EpisodeRecord> e = {Rec(EpisodeStatus::kTimeout, 25.0, 100, 0)};
  EXPECT_DOUBLE_EQ(Aggregate(e, 25.0).nav_time, 25.0);  // CrowdNav's convention (paper row 7)
  EXPECT_EQ(Aggregate({}, 25.0).episodes, 0);
}

TEST(EpisodesCsv, RoundTripAndDamagedLastLine) {
  testing::TempDir dir;
  EpisodeLine a;
  a.row = "row, with comma";
  a.episode = 3;
  a.seed = 123456789012345ULL;
  a.layout = "rect1/test/003";
  a.record = Rec(EpisodeStatus::kSuccess, 10.25, 41, 2, 9.5, 0.123456);
  a.error = "";
  EpisodeLine b = a;
  b.row = "plain";
  b.record = Rec(EpisodeStatus::kPolicyError, 1.0, 4, 0);
  b.error = "message with \"quotes\", commas";
  const std::string text = EpisodeCsvHeader() + "\n" + FormatEpisodeLine(a) + "\n" + FormatEpisodeLine(b) + "\nplain,4,1,x,succ";
  const auto file = dir.Write("episodes.csv", text);
  const auto lines = ReadEpisodesCsv(file);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].row, a.row);
  EXPECT_EQ(lines[0].seed, a.seed);
  EXPECT_EQ(lines[0].record.status, EpisodeStatus::kSuccess);
  EXPECT_DOUBLE_EQ(lines[0].record.time, 10.25);
  EXPECT_NEAR(lines[0].record.min_human_distance, 0.123456, 1e-9);
  EXPECT_EQ(lines[1].error, b.error);
  EXPECT_EQ(lines[1].record.min_human_distance, kInfinity);
}

}  // namespace
}  // namespace crowdsim
