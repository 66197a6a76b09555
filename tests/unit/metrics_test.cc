#include "crowdsim/bench/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "crowdsim/bench/episode_columns.h"
#include "crowdsim/bench/results.h"
#include "temp_dir.h"

namespace crowdsim {
namespace {

EpisodeOutcome Rec(EpisodeStatus s, double time, int steps, int danger, double path = 0,
                   double dmin = kInfinity) {
  EpisodeOutcome r;
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
  const std::vector<EpisodeOutcome> e = {
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
  EXPECT_DOUBLE_EQ(m.nav_time, 11.0);  // successful episodes only
  EXPECT_DOUBLE_EQ(m.path_length, 10.0);
  EXPECT_DOUBLE_EQ(m.danger_frequency, 16.0 / 220.0);  // danger steps / all steps
  EXPECT_DOUBLE_EQ(m.min_human_distance, (0.3 + 0.5 - 0.1 + 1.0) / 4.0);  // episodes with humans
  EXPECT_DOUBLE_EQ(m.discounted_return, (0.5 + 0.5 - 0.25 * 3) / 5.0);
}

TEST(Metrics, NoSuccessGivesTimeLimitAsNavTime) {
  const std::vector<EpisodeOutcome> e = {Rec(EpisodeStatus::kTimeout, 25.0, 100, 0)};
  EXPECT_DOUBLE_EQ(Aggregate(e, 25.0).nav_time, 25.0);  // CrowdNav's convention (paper row 7)
  EXPECT_EQ(Aggregate({}, 25.0).episodes, 0);
}

TEST(Metrics, CountsAndNavTimeStandardError) {
  const std::vector<EpisodeOutcome> e = {
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
  EXPECT_TRUE(std::isnan(Aggregate(std::vector<EpisodeOutcome>{e[0], e[3]}, 25.0).nav_time_se));
}

// Social metrics' means carry standard errors: SPL 0, 0.5, 1 has mean 0.5, sample standard
// deviation 0.5, s.e. 0.5 / sqrt(3); group intrusions (NaN in one episode, not counted) 1 and 3:
// mean 2, s.e. sqrt(2) / sqrt(2) = 1. A summary of two rows: sqrt(se1^2 + se2^2) / 2.
TEST(Metrics, SocialMeansCarryTheirStandardErrors) {
  std::vector<EpisodeOutcome> e(3, Rec(EpisodeStatus::kSuccess, 10.0, 40, 0));
  const double spl[] = {0.0, 0.5, 1.0};
  const double intrusions[] = {1.0, 3.0, std::numeric_limits<double>::quiet_NaN()};
  for (size_t i = 0; i < e.size(); ++i) {
    e[i].social.spl = spl[i];
    e[i].social.group_intrusions = intrusions[i];
  }
  const RowMetrics m = Aggregate(e, 25.0);
  EXPECT_NEAR(m.social.spl, 0.5, 1e-12);
  EXPECT_NEAR(m.social_se.spl, 0.5 / std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(m.social.group_intrusions, 2.0, 1e-12);
  EXPECT_NEAR(m.social_se.group_intrusions, 1.0, 1e-12);
  const RowMetrics both[] = {m, m};
  EXPECT_NEAR(SummarizeRows(both).social_se.spl, std::sqrt(2.0) * 0.5 / std::sqrt(3.0) / 2.0,
              1e-12);
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
  a.episodes = 100;
  a.successes = 80;
  a.success_rate = 0.8;
  a.nav_time = 10.0;
  a.nav_time_se = 0.3;
  b.episodes = 100;
  b.successes = 60;
  b.success_rate = 0.6;
  b.nav_time = 14.0;
  b.nav_time_se = 0.4;
  a.timeouts = 5;
  b.collisions = 7;
  const std::vector<RowMetrics> rows = {a, b};
  const RowMetrics m = SummarizeRows(rows);
  EXPECT_EQ(m.episodes, 200);
  EXPECT_EQ(m.successes, 140);
  EXPECT_EQ(m.timeouts, 5);
  EXPECT_EQ(m.collisions, 7);
  EXPECT_NEAR(m.success_rate, 0.7, 1e-12);
  EXPECT_NEAR(m.nav_time, 12.0, 1e-12);     // the paper's average: the mean of the rows
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
  a.outcome = Rec(EpisodeStatus::kSuccess, 10.25, 41, 2, 9.5, 0.123456);
  a.outcome.error = "";
  EpisodeLine b = a;
  b.row = "plain";
  b.outcome = Rec(EpisodeStatus::kPolicyError, 1.0, 4, 0);
  b.outcome.error = "message with \"quotes\", commas";
  const std::string text = EpisodeCsvHeader(false) + "\n" + FormatEpisodeLine(a, false) + "\n" +
                           FormatEpisodeLine(b, false) + "\nplain,4,1,x,succ";
  const auto file = dir.Write("episodes.csv", text);
  const auto lines = ReadEpisodesCsv(file);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].row, a.row);
  EXPECT_EQ(lines[0].seed, a.seed);
  EXPECT_EQ(lines[0].outcome.status, EpisodeStatus::kSuccess);
  EXPECT_DOUBLE_EQ(lines[0].outcome.time, 10.25);
  EXPECT_NEAR(lines[0].outcome.min_human_distance, 0.123456, 1e-9);
  EXPECT_EQ(lines[1].outcome.error, b.outcome.error);
  EXPECT_EQ(lines[1].outcome.min_human_distance, kInfinity);
}

EpisodeLine SomeLine(int episode) {
  EpisodeLine e;
  e.row = "plain";
  e.episode = episode;
  e.seed = 42;
  e.layout = "rect1/test/000";
  e.outcome = Rec(EpisodeStatus::kTimeout, 25.0, 100, 3, 7.5);
  return e;
}

// SomeLine(episode) as episodes.csv holds it, with field `index` replaced by `value`: a damaged
// line that stays right as columns are added.
std::string Damaged(int episode, size_t index, const std::string& value) {
  std::vector<std::string> fields;
  std::stringstream ss(FormatEpisodeLine(SomeLine(episode), false));
  for (std::string f; std::getline(ss, f, ',');) fields.push_back(f);
  if (FormatEpisodeLine(SomeLine(episode), false).back() == ',') fields.push_back("");
  fields.at(index) = value;
  std::string line;
  for (size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + fields[i];
  return line;
}

// The message of the std::runtime_error that reading `file` throws ("" when it reads).
std::string ReadError(const std::filesystem::path& file) {
  try {
    ReadEpisodesCsvChecked(file);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(EpisodesCsv, DamagedLinesAreCountedAndTheFirstIsNamedWithItsLine) {
  testing::TempDir dir;
  const std::string text = EpisodeCsvHeader(false) + "\n" + FormatEpisodeLine(SomeLine(0), false) +
                           "\n" + Damaged(2, 1, "two") + "\n" +
                           FormatEpisodeLine(SomeLine(1), false) + "\n" +
                           Damaged(3, 4, "teleported") + "\n" + "plain,4,42,x,succ";
  const auto file = dir.Write("episodes.csv", text);
  const EpisodesCsvRead read = ReadEpisodesCsvChecked(file);
  ASSERT_EQ(read.lines.size(), 2u);
  EXPECT_EQ(read.lines[1].episode, 1);
  EXPECT_EQ(read.damaged, 2);
  EXPECT_EQ(read.first_damage, file.string() + ":3: its episode 'two' is not a whole number >= 0");
  EXPECT_TRUE(read.cut_last_line);
  EXPECT_EQ(ReadEpisodesCsv(file).size(), 2u);

  // Whole-field numbers only (std::stoi read "4x" as 4), and the field count.
  const auto partial = dir.Write("partial.csv", EpisodeCsvHeader(false) + "\n" +
                                                    FormatEpisodeLine(SomeLine(0), false) + "\n" +
                                                    Damaged(4, 1, "4x") + "\nplain,5\n");
  const EpisodesCsvRead p = ReadEpisodesCsvChecked(partial);
  EXPECT_EQ(p.lines.size(), 1u);
  EXPECT_EQ(p.damaged, 2);
  EXPECT_EQ(p.first_damage, partial.string() + ":3: its episode '4x' is not a whole number >= 0");
}

TEST(EpisodesCsv, AFileWithoutItsHeaderOrAReadableLineIsAnErrorNamingFileLineAndFix) {
  testing::TempDir dir;
  const auto garbage = dir.Write("garbage.csv", "garbage\nmore garbage, x\n\x01\x02\n");
  std::string msg = ReadError(garbage);
  EXPECT_NE(msg.find(garbage.string() + ":1: the header is 'garbage', expected 'row,episode,"),
            std::string::npos)
      << msg;
  EXPECT_NE(msg.find("not an episodes.csv written by `crowdsim-bench run`"), std::string::npos)
      << msg;
  EXPECT_NE(msg.find("--fresh"), std::string::npos) << msg;
  msg = ReadError(dir.Write("empty.csv", ""));
  EXPECT_NE(msg.find("empty.csv:1: the first line is empty"), std::string::npos) << msg;

  const auto unreadable =
      dir.Write("unreadable.csv",
                EpisodeCsvHeader(false) + "\nnot,an,episode\n\n" + Damaged(1, 6, "2.5") + "\n");
  msg = ReadError(unreadable);
  EXPECT_NE(
      msg.find(unreadable.string() + ": none of its 2 episode line(s) can be read (the first: " +
               unreadable.string() + ":2: it has 3 field(s), expected " +
               std::to_string(EpisodeColumnsOf(false).size()) + ")"),
      std::string::npos)
      << msg;
  EXPECT_NE(msg.find("--fresh"), std::string::npos) << msg;

  // No episode yet, or only the line a crash cut short: nothing to read, nothing wrong.
  EXPECT_EQ(ReadError(dir.Write("header.csv", EpisodeCsvHeader(false) + "\n")), "");
  const auto cut = dir.Write("cut.csv", EpisodeCsvHeader(false) + "\nplain,0,42,rect,succ");
  EXPECT_EQ(ReadError(cut), "");
  EXPECT_TRUE(ReadEpisodesCsvChecked(cut).cut_last_line);
}

}  // namespace
}  // namespace crowdsim
