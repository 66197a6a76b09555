// Crash isolation: a plugin that segfaults, aborts, exits or hangs in Decide costs its episode
// (policy_crash / policy_timeout, named on stderr with row, episode, plugin and signal), not
// the run; a resume does not run it again; a throw of a non-std exception is a policy_error;
// and isolated runs give the same episodes as threaded ones.
#include <gtest/gtest.h>

#include <map>
#include <optional>

#include "crowdsim/bench/results.h"
#include "crowdsim/bench/row_instance.h"
#include "crowdsim/bench/runner.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

using testing::ReadText;
using testing::TempDir;

/// Every row's robot misbehaves in its instance's third episode (episode 2 with one worker);
/// the replacement worker's fresh instance runs episode 3 normally.
std::string MisbehavingSuite() {
  const std::string plugin = (testing::FixturePluginDir() / "crowdsim_throwing_policy.so").string();
  auto row = [&](const std::string& mode) {
    return "  - {label: " + mode + ", policy: " + plugin + ", params: {mode: " + mode +
           ", fail_after_steps: 0, good_episodes: 2}}\n";
  };
  return "name: misbehaving\nepisodes: 4\nseed: 5\nepisode_timeout_s: 1\n"
         "world: {source: random_rect, obstacles: 1}\nhumans: {count: 2, policy: linear}\nrows:\n" +
         row("segfault") + row("abort") + row("exit") + row("hang") + row("throw_int") +
         "  - {label: good, policy: linear}\n";
}

/// Built-in plugins only, in CrowdNav's circle crossing and a 3-obstacle room.
constexpr const char* kPlainSuite = R"(name: plain
episodes: 10
seed: 3
humans: {count: 4, policy: orca, goal_mode: new_goal}
robot: {sensors: [person]}
world: {source: crowdnav, scenario: circle_crossing, circle_radius: 4}
rows:
  - {label: orca, policy: orca}
  - {label: planner, policy: ompl_planner, world: {source: random_rect, obstacles: 3}}
)";

class CrashIsolationTest : public ::testing::Test {
 protected:
  Suite LoadOrDie(const std::string& yaml, const std::vector<std::string>& set = {}) {
    const auto file = dir_.Write("suite.yaml", yaml);
    SuiteLoadResult r = LoadSuite(file, registry_, set);
    std::string errors;
    for (const auto& e : r.errors) errors += e.Format() + "\n";
    EXPECT_TRUE(r.suite) << errors;
    return r.suite ? *r.suite : Suite{};
  }
  std::string LoadErrors(const std::string& yaml) {
    SuiteLoadResult r = LoadSuite(dir_.Write("bad.yaml", yaml), registry_);
    std::string errors;
    for (const auto& e : r.errors) errors += e.Format() + "\n";
    return errors;
  }
  RunSummary Run(const Suite& s, const std::string& out, int jobs,
                 std::optional<IsolationMode> isolation = std::nullopt) {
    RunOptions options;
    options.out_dir = dir_.path() / out;
    options.jobs = jobs;
    options.isolation = isolation;
    options.progress = false;
    return RunSuite(s, registry_, options);
  }
  std::string Manifest(const std::string& out) {
    return ReadText(dir_.path() / out / "manifest.json");
  }

  TempDir dir_;
  PluginRegistry registry_{{testing::PluginDir(), testing::FixturePluginDir()}};
};

TEST_F(CrashIsolationTest, CrashesAndHangsCostTheirEpisodeNotTheRun) {
  const Suite s = LoadOrDie(MisbehavingSuite());
  ::testing::internal::CaptureStderr();
  const RunSummary r = Run(s, "out", 1);
  const std::string err = ::testing::internal::GetCapturedStderr();
  ASSERT_EQ(r.rows.size(), 6u);
  EXPECT_EQ(r.episodes_run, 24);
  EXPECT_NE(Manifest("out").find("\"isolated\": true"), std::string::npos);

  const std::map<std::string, const char*> signal = {
      {"segfault", "signal SIGSEGV"},
      {"abort", "signal SIGABRT"},
      {"exit", "exited with status 3"},
      {"hang", "killed at the episode_timeout_s of 1 s"}};
  for (const TableRow& row : r.rows) {
    const RowMetrics& m = row.metrics;
    SCOPED_TRACE(row.Label());
    EXPECT_EQ(m.episodes, 4);
    // Every episode is counted exactly once, the lost ones in their own column.
    EXPECT_NEAR(m.success_rate + m.collision_rate + m.timeout_rate + m.policy_error_rate +
                    m.policy_crash_rate + m.policy_timeout_rate,
                1.0, 1e-12);
    const std::string label = row.Label();
    EXPECT_DOUBLE_EQ(m.policy_crash_rate,
                     label == "segfault" || label == "abort" || label == "exit" ? 0.25 : 0.0);
    EXPECT_DOUBLE_EQ(m.policy_timeout_rate, label == "hang" ? 0.25 : 0.0);
    // A thrown int is a policy error like any other throw, in every episode after the second.
    EXPECT_DOUBLE_EQ(m.policy_error_rate, label == "throw_int" ? 0.5 : 0.0);
    if (signal.count(label)) {
      // The message names the row, the episode, the plugin (and its file) and the signal.
      const std::string status = label == "hang" ? "policy_timeout" : "policy_crash";
      const std::string expected = "row '" + label + "', episode 2 (rows[";
      const size_t at = err.find(expected);
      ASSERT_NE(at, std::string::npos) << err;
      const std::string message = err.substr(at, err.find('\n', at) - at);
      EXPECT_NE(message.find(signal.at(label)), std::string::npos) << message;
      EXPECT_NE(message.find("policy 'throwing_policy'"), std::string::npos) << message;
      EXPECT_NE(message.find("crowdsim_throwing_policy.so"), std::string::npos) << message;
      EXPECT_NE(message.find("recorded as " + status), std::string::npos) << message;
    }
  }
  const std::string csv = ReadText(dir_.path() / "out" / "episodes.csv");
  EXPECT_NE(csv.find("segfault,2,"), std::string::npos);
  EXPECT_NE(csv.find(",policy_crash,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",policy_timeout,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("not derived from std::exception"), std::string::npos) << csv;
  const std::string table = ReadText(dir_.path() / "out" / "table.md");
  EXPECT_NE(table.find("| crashes | hangs |"), std::string::npos) << table;

  // The resume keeps the lost episodes: nothing runs (and crashes) again.
  const RunSummary again = Run(s, "out", 1);
  EXPECT_EQ(again.episodes_run, 0);
  EXPECT_EQ(again.episodes_resumed, 24);
  EXPECT_EQ(ReadText(dir_.path() / "out" / "episodes.csv"), csv);
  EXPECT_DOUBLE_EQ(again.rows[0].metrics.policy_crash_rate, 0.25);
}

// render and report replay an episode in their own process: one a run recorded as
// policy_crash or policy_timeout took the CLI down (exit 139) or hung it. A row that a run
// isolates is first replayed in a worker process.
TEST_F(CrashIsolationTest, AReplayThatCrashesOrHangsIsAnErrorNotTheEndOfTheCaller) {
  const std::string plugin = (testing::FixturePluginDir() / "crowdsim_throwing_policy.so").string();
  const Suite s = LoadOrDie(
      "name: replayed\nepisodes: 2\nepisode_timeout_s: 1\n"
      "world: {source: random_rect, obstacles: 1}\nhumans: {count: 2, policy: linear}\nrows:\n"
      "  - {label: segv, policy: " +
      plugin +
      ", params: {mode: segfault, fail_after_steps: 1}}\n"
      "  - {label: hang, policy: " +
      plugin +
      ", params: {mode: hang, fail_after_steps: 1}}\n"
      "  - {label: good, policy: " +
      plugin + ", params: {fail_after_steps: 1000}}\n");
  auto replay_error = [&](size_t row) {
    try {
      ReplayEpisode(s, row, 1, registry_, true);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("replayed");
  };
  EXPECT_NE(replay_error(0).find("episode 1 of row 'segv' cannot be replayed: a run records it "
                                 "as policy_crash (the worker process that replayed it here: "
                                 "killed by signal SIGSEGV"),
            std::string::npos)
      << replay_error(0);
  EXPECT_NE(replay_error(1).find("a run records it as policy_timeout (the worker process that "
                                 "replayed it here: killed at the episode_timeout_s of 1 s)"),
            std::string::npos)
      << replay_error(1);
  EXPECT_EQ(replay_error(2), "replayed");
}

// A TorchScript policy whose forward() hung in its load-time probe hung `validate` and `run` in
// the main process, isolation and episode_timeout_s notwithstanding.
TEST_F(CrashIsolationTest, APluginThatHangsOrCrashesWhileMadeIsARowErrorUnderIsolation) {
  const std::string plugin = (testing::FixturePluginDir() / "crowdsim_throwing_policy.so").string();
  const Suite s = LoadOrDie(
      "name: made\nepisodes: 2\nepisode_timeout_s: 1\n"
      "world: {source: random_rect, obstacles: 1}\nhumans: {count: 2, policy: linear}\nrows:\n"
      "  - {label: hangs, policy: " +
      plugin +
      ", params: {mode: hang_on_create}}\n"
      "  - {label: crashes, policy: " +
      plugin +
      ", params: {mode: segfault_on_create}}\n"
      "  - {label: good, policy: linear}\n");
  const std::vector<std::string> errors = PreflightSuite(s, registry_);
  ASSERT_EQ(errors.size(), 2u);
  EXPECT_NE(errors[0].find("row 'hangs' (rows[0]): making its plugins failed (the worker process "
                           "that made them killed at the episode_timeout_s of 1 s while making "
                           "policy 'throwing_policy'"),
            std::string::npos)
      << errors[0];
  EXPECT_NE(errors[1].find("row 'crashes' (rows[1]): making its plugins failed (the worker "
                           "process that made them killed by signal SIGSEGV"),
            std::string::npos)
      << errors[1];
  EXPECT_THROW(Run(s, "out", 2), RunError);
  EXPECT_FALSE(std::filesystem::exists(dir_.path() / "out" / "episodes.csv"));
  // A plugin's own error while made still names the row, from the worker.
  const Suite needs = LoadOrDie(
      "name: needs\nepisodes: 1\nisolation: on\n"
      "world: {source: random_rect, obstacles: 1}\nrows:\n"
      "  - {label: n, policy: " +
      plugin + ", params: {mode: needs_throw}}\n");
  const std::vector<std::string> needs_errors = PreflightSuite(needs, registry_);
  ASSERT_EQ(needs_errors.size(), 1u);
  EXPECT_NE(needs_errors[0].find("row 'n' (rows[0]): Needs failure (fixture)"), std::string::npos)
      << needs_errors[0];
}

TEST_F(CrashIsolationTest, IsolatedRunsGiveTheSameEpisodesAsThreads) {
  const Suite s = LoadOrDie(kPlainSuite);
  const RunSummary threads = Run(s, "threads", 2);
  const RunSummary processes = Run(s, "processes", 2, IsolationMode::kOn);
  EXPECT_NE(Manifest("threads").find("\"isolated\": false"), std::string::npos);
  EXPECT_NE(Manifest("processes").find("\"isolated\": true"), std::string::npos);
  EXPECT_EQ(WithoutTimingColumns(ReadText(dir_.path() / "threads" / "episodes.csv")),
            WithoutTimingColumns(ReadText(dir_.path() / "processes" / "episodes.csv")));
  ASSERT_EQ(threads.rows.size(), processes.rows.size());
  for (size_t i = 0; i < threads.rows.size(); ++i) {
    const RowMetrics& a = threads.rows[i].metrics;
    const RowMetrics& b = processes.rows[i].metrics;
    // Exact: the workers send every value unrounded.
    EXPECT_EQ(a.success_rate, b.success_rate);
    EXPECT_EQ(a.nav_time, b.nav_time);
    EXPECT_EQ(a.path_length, b.path_length);
    EXPECT_EQ(a.min_human_distance, b.min_human_distance);
    EXPECT_EQ(a.discounted_return, b.discounted_return);
    EXPECT_EQ(a.danger_frequency, b.danger_frequency);
  }
  // No crash, no extra columns.
  EXPECT_EQ(ReadText(dir_.path() / "processes" / "table.md").find("crashes"), std::string::npos);
}

TEST_F(CrashIsolationTest, AutoIsolatesOnlyPluginsFromOutsideTheHarness) {
  Run(LoadOrDie(kPlainSuite), "own", 1);
  EXPECT_NE(Manifest("own").find("\"isolated\": false"), std::string::npos);
  // A fixture plugin (not in the harness's plugin folder) turns isolation on, off overrides.
  const std::string outside =
      std::string(kPlainSuite) +
      "  - {label: fine, policy: throwing_policy, params: {good_episodes: 1000}}\n";
  Run(LoadOrDie(outside), "outside", 1);
  EXPECT_NE(Manifest("outside").find("\"isolated\": true"), std::string::npos);
  Run(LoadOrDie(outside, {"isolation=off"}), "off", 1);
  EXPECT_NE(Manifest("off").find("\"isolated\": false"), std::string::npos);
  // A timeout needs isolation, so it turns auto on.
  Run(LoadOrDie(kPlainSuite, {"episode_timeout_s=30"}), "timeout", 1);
  EXPECT_NE(Manifest("timeout").find("\"isolated\": true"), std::string::npos);
}

TEST_F(CrashIsolationTest, SuiteKeysAreChecked) {
  const std::string base =
      "name: k\nepisodes: 2\nworld: {source: random_rect}\nrows:\n  - {label: a, policy: linear}\n";
  EXPECT_NE(LoadErrors("isolation: sometimes\n" + base)
                .find("isolation: unknown value 'sometimes' (valid: auto, on, off)"),
            std::string::npos)
      << LoadErrors("isolation: sometimes\n" + base);
  EXPECT_NE(LoadErrors("episode_timeout_s: -1\n" + base)
                .find("episode_timeout_s: value -1 is out of range"),
            std::string::npos)
      << LoadErrors("episode_timeout_s: -1\n" + base);
  const std::string both = LoadErrors("isolation: off\nepisode_timeout_s: 5\n" + base);
  EXPECT_NE(both.find("episode_timeout_s 5 needs isolated episodes"), std::string::npos) << both;
  // Neither key decides results: the config hash (what resume compares) is unchanged.
  const Suite plain = LoadOrDie(base);
  const Suite isolated = LoadOrDie("isolation: on\nepisode_timeout_s: 5\n" + base);
  EXPECT_EQ(plain.ConfigHash(), isolated.ConfigHash());
}

// With no episode_timeout_s, an isolated run still bounds each episode (RunOptions::
// default_episode_timeout_s, kDefaultEpisodeTimeoutS by default): a hung plugin costs its
// episode, never the run. A threaded run cannot stop a hung episode: it names a slow one.
TEST_F(CrashIsolationTest, EpisodesAreWatchedWithoutATimeoutInTheSuite) {
  const std::string plugin = (testing::FixturePluginDir() / "crowdsim_throwing_policy.so").string();
  const std::string head =
      "name: watched\nepisodes: 1\nworld: {source: random_rect, obstacles: 1}\n"
      "humans: {count: 2, policy: linear}\nrows:\n  - {label: l, policy: " +
      plugin;
  const Suite hang = LoadOrDie(head + ", params: {mode: hang}}\n");
  EXPECT_EQ(hang.episode_timeout_s, 0.0);
  RunOptions options;
  options.out_dir = dir_.path() / "hang";
  options.isolation = IsolationMode::kOn;
  options.progress = false;
  options.default_episode_timeout_s = 1;
  const RunSummary r = RunSuite(hang, registry_, options);
  EXPECT_DOUBLE_EQ(r.rows.at(0).metrics.policy_timeout_rate, 1.0);
  EXPECT_GT(kDefaultEpisodeTimeoutS, 0.0);

  const Suite slow = LoadOrDie(head + ", params: {mode: slow}}\n");
  options.out_dir = dir_.path() / "slow";
  options.isolation = IsolationMode::kOff;
  options.slow_episode_note_s = 1;
  ::testing::internal::CaptureStderr();
  RunSuite(slow, registry_, options);
  const std::string said = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(said.find("note: row 'l', episode 0 has run 1 s"), std::string::npos) << said;
  EXPECT_NE(said.find("give the suite episode_timeout_s"), std::string::npos) << said;

  // A threaded row's plugins are made in the run's process: a slow one is named too.
  const Suite slow_made =
      LoadOrDie(head + ", params: {mode: slow_on_create, fail_after_steps: 1000}}\n");
  options.out_dir = dir_.path() / "slow_made";
  ::testing::internal::CaptureStderr();
  RunSuite(slow_made, registry_, options);
  const std::string made = ::testing::internal::GetCapturedStderr();
  EXPECT_NE(made.find("note: row 'l' (rows[0]), making its plugins, has run 1 s"),
            std::string::npos)
      << made;
}

}  // namespace
}  // namespace crowdsim
