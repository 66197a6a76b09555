// Episode logs: `run --record` writes them, `score` gives from them alone the run's social
// metrics, and a damaged, foreign or cut-short log is an error naming file, line and field.
#include "crowdsim/bench/episode_log.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>

#include "crowdsim/bench/csv.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/bench/runner.h"
#include "shell.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

namespace fs = std::filesystem;
using testing::TempDir;

constexpr const char* kSuite = R"(name: logged
episodes: 6
seed: 3
world: {source: random_rect, obstacles: 1, split: test}
humans: {count: 5, policy: orca, groups: {share: 0.6, size: 2}}
robot:
  sensors: [person]
columns: [spl, group_intrusions]
rows:
  - {label: orca, policy: orca}
  - {label: unicycle, policy: orca, kinematics: unicycle}
)";

constexpr const char* kHeader =
    R"({"format": "crowdsim-episode-log", "version": 1, "units": {"length": "m", "time": "s", "angle": "rad"}, "dt": 0.25, "robot": {"holonomic": false, "goal_radius": 0.2}, "map": {"bounds": [-5, -5, 15, 5], "rectangles": []}})";

// A state line of a robot still at the origin (goal 10 m away) and one person at (1, 0).
std::string State(double t, const std::string& robot_extra = "") {
  std::ostringstream s;
  s << R"({"t": )" << t
    << R"(, "robot": {"x": 0, "y": 0, "vx": 0, "vy": 0, "heading": 0, "radius": 0.3, "goal": [10, 0])"
    << robot_extra
    << R"(}, "people": [{"id": 0, "x": 1, "y": 0, "vx": 0, "vy": 0, "radius": 0.3}]})";
  return s.str();
}

class EpisodeLogTest : public ::testing::Test {
 protected:
  std::string ReadError(const std::string& text) {
    try {
      ReadEpisodeLog(dir_.Write("bad.jsonl", text));
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  }
  TempDir dir_;
};

TEST_F(EpisodeLogTest, ScoringTheRecordedLogsGivesTheRunsColumns) {
  PluginRegistry registry{{testing::PluginDir()}};
  SuiteLoadResult loaded = LoadSuite(dir_.Write("suite.yaml", kSuite), registry);
  ASSERT_TRUE(loaded.suite);
  RunOptions o;
  o.out_dir = dir_.path() / "run";
  o.jobs = 2;
  o.progress = false;
  o.record = true;
  RunSuite(*loaded.suite, registry, o);
  const auto lines = ReadEpisodesCsv(o.out_dir / "episodes.csv");
  ASSERT_EQ(lines.size(), 12u);
  for (const EpisodeLine& run : lines) {
    char name[32];
    std::snprintf(name, sizeof(name), "%06d.jsonl.gz", run.episode);
    const fs::path log_path =
        o.out_dir / "logs" / ((run.row == "orca" ? "1_" : "2_") + run.row) / name;
    const EpisodeLog log = ReadEpisodeLog(log_path);
    EXPECT_EQ(log.holonomic, run.row == "orca");
    EpisodeLine scored;
    scored.outcome.status = *log.status;
    scored.outcome.social = ScoreEpisodeLog(log);
    EXPECT_EQ(scored.outcome.status, run.outcome.status) << log_path;
    // Every family a log holds: the groups' metrics come from the people's logged groups.
    for (const EpisodeColumn* c : EpisodeColumnsOf(kLogMetrics)) {
      if (!Social(*c)) continue;
      EXPECT_EQ(FormatEpisodeCell(*c, scored), FormatEpisodeCell(*c, run))
          << log_path << " " << c->name;
    }
  }
  // The CLI over the folder: one line per log and the header, exit 0.
  const std::string exe = (testing::BinaryDir() / "bin" / "crowdsim-bench").string();
  const auto [rc, text] = testing::Shell(exe + " score " + (o.out_dir / "logs").string());
  EXPECT_EQ(rc, 0) << text;
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 1 + 12 + 1) << text;  // + the note
  EXPECT_NE(text.find("score: 12 of 12 log(s) scored"), std::string::npos) << text;
}

TEST_F(EpisodeLogTest, AHandWrittenLogIsScored) {
  // A converter's output: plain JSON lines, no gzip; parked 1.0 m from a person for 10 s.
  std::string text = std::string(kHeader) + "\n";
  for (int k = 0; k <= 40; ++k) text += State(k * 0.25) + "\n";
  text += R"({"outcome": "timeout"})"
          "\n";
  const EpisodeLog log = ReadEpisodeLog(dir_.Write("parked.jsonl", text));
  const SocialMetrics m = ScoreEpisodeLog(log);
  EXPECT_DOUBLE_EQ(m.personal_share, 1.0);
  EXPECT_DOUBLE_EQ(m.freezing_time, 10.0);
  EXPECT_DOUBLE_EQ(m.shortest_path, 10.0);
  EXPECT_DOUBLE_EQ(m.spl, 0.0);
}

TEST_F(EpisodeLogTest, DamagedForeignOrPartialLogsAreNamedErrors) {
  const std::string h = std::string(kHeader) + "\n";
  const std::string end = R"({"outcome": "success"})"
                          "\n";
  // A missing field: file, line and field.
  std::string missing = State(0);
  missing.replace(missing.find(R"("vx": 0, )"), 9, "");
  EXPECT_NE(ReadError(h + missing + "\n" + end).find("bad.jsonl:2: 'robot.vx' is missing"),
            std::string::npos)
      << ReadError(h + missing + "\n" + end);
  // Time that does not advance by dt.
  EXPECT_NE(ReadError(h + State(0) + "\n" + State(0.5) + "\n" + end).find(":3: 't' is 0.5"),
            std::string::npos)
      << ReadError(h + State(0) + "\n" + State(0.5) + "\n" + end);
  // A newer version, another unit.
  std::string newer = h;
  newer.replace(newer.find(R"("version": 1)"), 12, R"("version": 2)");
  EXPECT_NE(ReadError(newer + State(0) + "\n" + end).find("'version' is 2, newer"),
            std::string::npos);
  std::string feet = h;
  feet.replace(feet.find(R"("length": "m")"), 13, R"("length": "ft")");
  EXPECT_NE(ReadError(feet + State(0) + "\n" + end).find("'units.length' is \"ft\", not 'm'"),
            std::string::npos)
      << ReadError(feet + State(0) + "\n" + end);
  // Cut short: no outcome line; or a line after it.
  EXPECT_NE(ReadError(h + State(0) + "\n").find("no outcome line"), std::string::npos);
  EXPECT_NE(ReadError(h + State(0) + "\n" + end + State(0.25) + "\n").find("after the outcome"),
            std::string::npos);
  // Not a log at all.
  EXPECT_NE(ReadError("row,episode\n").find("bad.jsonl:1: is not a JSON object"), std::string::npos)
      << ReadError("row,episode\n");
  EXPECT_NE(ReadError(R"({"format": "other"})"
                      "\n")
                .find("'format' is not"),
            std::string::npos);
}

TEST_F(EpisodeLogTest, ScoreNamesABadLogAndExitsOne) {
  const std::string h = std::string(kHeader) + "\n";
  fs::create_directories(dir_.path() / "logs");
  dir_.Write("logs/good.jsonl", h + State(0) + "\n" +
                                    R"({"outcome": "timeout"})"
                                    "\n");
  dir_.Write("logs/cut.jsonl", h + State(0) + "\n");
  const std::string exe = (testing::BinaryDir() / "bin" / "crowdsim-bench").string();
  const auto [rc, text] = testing::Shell(exe + " score " + (dir_.path() / "logs").string());
  EXPECT_EQ(rc, 1) << text;
  EXPECT_NE(text.find("cut.jsonl: no outcome line"), std::string::npos) << text;
  EXPECT_NE(text.find("good.jsonl,timeout,"), std::string::npos) << text;
  EXPECT_EQ(text.find("cut.jsonl,"), std::string::npos) << text;  // never scored as complete
}

}  // namespace
}  // namespace crowdsim
