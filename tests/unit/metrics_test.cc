#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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

TEST(Metrics, CountsAndNavTimeStandardError) {
  const std::vector<EpisodeRecord> e = {
      Rec(EpisodeStatus::kSuccess, 10.0, 40, 0), Rec(EpisodeStatus::kSuccess, 12.0, 48, 0),
      Rec(EpisodeStatus::kSuccess, 14.0, 56, 0), Rec(EpisodeStatus::kCollisionHuman, 3.0, 12, 0),
      Rec(EpisodeStatus::kTimeout, 25.0, 100, 0)};
  const RowMetrics m = Aggregate(e, 25.0);
  EXPECT_EQ(m.successes, 3);
  EXPECT_EQ(m.collisions, 1);
  EXPECT_EQ(m.timeouts, 1);
  // Sample standard deviation of 10, 12, 14 is 2; over sqrt(3) successes.
  EXPECT_NEAR(m.nav_time_se, 2.0 / std::sqrt(3.0), 1e-12);
  // One success gives no standard error.
  EXPECT_TRUE(std::isnan(Aggregate(std::vector<EpisodeRecord>{e[0], e[3]}, 25.0).nav_time_se));
}

TEST(Metrics, WilsonIntervalKnownValues) {
  // 348 of 500 (the line-10 seed-1010 model): p = 0.696.
  const Interval a = WilsonInterval95(348, 500);
  EXPECT_NEAR(a.low, 0.65431, 5e-5);
  EXPECT_NEAR(a.high, 0.73470, 5e-5);
  EXPECT_TRUE(a.Contains(0.696));
  // No event in 500: the interval starts at 0 and is not empty (unlike p +- 1.96 s.e.).
  const Interval zero = WilsonInterval95(0, 500);
  EXPECT_DOUBLE_EQ(zero.low, 0.0);
  EXPECT_NEAR(zero.high, 0.00762, 5e-5);
  const Interval all = WilsonInterval95(500, 500);
  EXPECT_NEAR(all.low, 1.0 - 0.00762, 5e-5);
  EXPECT_DOUBLE_EQ(all.high, 1.0);
  // 1 of 2: symmetric around 0.5 and wide.
  const Interval half = WilsonInterval95(1, 2);
  EXPECT_NEAR(half.low + half.high, 1.0, 1e-12);
  EXPECT_NEAR(half.low, 0.09453, 5e-5);
  const Interval none = WilsonInterval95(0, 0);
  EXPECT_EQ(none.low, 0.0);
  EXPECT_EQ(none.high, 1.0);
}

TEST(Metrics, SummaryIsTheMeanOfItsRowsWithPooledCounts) {
  RowMetrics a, b;
  a.episodes = 100; a.successes = 80; a.success_rate = 0.8; a.nav_time = 10.0; a.nav_time_se = 0.3;
  b.episodes = 100; b.successes = 60; b.success_rate = 0.6; b.nav_time = 14.0; b.nav_time_se = 0.4;
  a.timeouts = 5; b.collisions = 7;
  const std::vector<RowMetrics> rows = {a, b};
  const RowMetrics m = SummarizeRows(rows);
  EXPECT_EQ(m.episodes, 200);
  EXPECT_EQ(m.successes, 140);
  EXPECT_EQ(m.timeouts, 5);
  EXPECT_EQ(m.collisions, 7);
  EXPECT_NEAR(m.success_rate, 0.7, 1e-12);
  EXPECT_NEAR(m.nav_time, 12.0, 1e-12);  // the paper's average: the mean of the rows
  EXPECT_NEAR(m.nav_time_se, 0.25, 1e-12);  // sqrt(0.3^2 + 0.4^2) / 2
  b.nav_time_se = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(std::isnan(SummarizeRows(std::vector<RowMetrics>{a, b}).nav_time_se));
  EXPECT_EQ(SummarizeRows({}).episodes, 0);
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
