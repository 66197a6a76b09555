// The HTML report of a real (small) run: self-contained, with the table, charts, thumbnails
// linking to full figures; clear errors for bad folders; and it opens in headless Chromium.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <regex>
#include <string>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/bench/runner.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/render/report.h"
#include "crowdsim/render/results_folder.h"
#include "crowdsim/render/training_report.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim::render {
namespace {

namespace fs = std::filesystem;
using crowdsim::testing::TempDir;

int CountOf(const std::string& text, const std::string& needle) {
  int n = 0;
  for (size_t pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1))
    ++n;
  return n;
}

// quick.yaml, 6 episodes per row, into a temporary results folder (once for all tests).
class ReportTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    PluginRegistry registry;
    SuiteLoadResult loaded =
        LoadSuite(crowdsim::testing::SourceDir() / "suites/quick.yaml", registry);
    ASSERT_TRUE(loaded.suite);
    RunOptions opt;
    opt.out_dir = dir_->path() / "quick";
    opt.jobs = 2;
    opt.episodes = 6;
    opt.progress = false;
    RunSuite(*loaded.suite, registry, opt);
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static fs::path Results() { return dir_->path() / "quick"; }
  static TempDir* dir_;
};
TempDir* ReportTest::dir_ = nullptr;

TEST_F(ReportTest, IsOneSelfContainedPageWithTableChartsAndFigures) {
  PluginRegistry registry;
  const std::string html = BuildReport(Results(), registry);
  EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_NE(html.find("<h1>quick</h1>"), std::string::npos);
  // The table: a header and one line per row.
  EXPECT_NE(html.find("<th>success rate</th>"), std::string::npos);
  EXPECT_EQ(CountOf(html, "<tr>"), 3);
  // Three charts; the outcome chart stacks success, collision, timeout per row.
  EXPECT_EQ(CountOf(html, "class=\"chart-title\""), 3);
  EXPECT_EQ(CountOf(html, "<rect class=\"bar success\""), 2);
  EXPECT_EQ(CountOf(html, "<rect class=\"bar nav-time\""), 2);
  // Every thumbnail links to a full figure embedded in the page, and vice versa.
  const std::regex link("href=\"#(fig-r[0-9]+-e[0-9]+)\"");
  int links = 0;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), link); it != std::sregex_iterator();
       ++it) {
    ++links;
    EXPECT_NE(html.find("id=\"" + (*it)[1].str() + "\""), std::string::npos) << (*it)[1].str();
  }
  EXPECT_GE(links, 2);  // at least one episode per row
  EXPECT_EQ(CountOf(html, "src=\"data:image/png;base64,"), links);
  EXPECT_EQ(CountOf(html, "<div class=\"figure\""), links);
  EXPECT_EQ(CountOf(html, "<polyline class=\"trajectory robot\""), links);
  // Nothing to fetch: no scripts, stylesheets, or remote URLs (the SVG namespace is a name).
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("<link"), std::string::npos);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);
  EXPECT_EQ(html.find("href=\"http"), std::string::npos);
  EXPECT_EQ(html.find("url("), std::string::npos);
}

TEST(SocialReport, ChartsTheSocialMetricsTheSuiteNames) {
  TempDir dir;
  PluginRegistry registry;
  SuiteLoadResult loaded = LoadSuite(crowdsim::testing::SourceDir() / "suites/quick.yaml", registry,
                                     {"columns=[spl, min_ttc]"});
  ASSERT_TRUE(loaded.suite);
  RunOptions opt;
  opt.out_dir = dir.path() / "social";
  opt.episodes = 4;
  opt.progress = false;
  RunSuite(*loaded.suite, registry, opt);
  const std::string html = BuildReport(opt.out_dir, registry);
  EXPECT_NE(html.find("<h2>Social navigation metrics</h2>"), std::string::npos);
  EXPECT_EQ(CountOf(html, "class=\"chart-title\""), 3 + 2);  // outcomes, time, danger; SPL, TTC
  EXPECT_NE(html.find(">SPL<"), std::string::npos);
  EXPECT_NE(html.find(">min. TTC<"), std::string::npos);
}

// A shorter run into the folder of a longer one: the table counts its own episodes, and the
// page says what episodes.csv holds besides and which --set the run was given.
TEST_F(ReportTest, CountsTheTablesEpisodesAndNamesTheRunsOverrides) {
  TempDir dir;
  PluginRegistry registry;
  SuiteLoadResult loaded =
      LoadSuite(crowdsim::testing::SourceDir() / "suites/quick.yaml", registry, {"humans.count=2"});
  ASSERT_TRUE(loaded.suite);
  RunOptions opt;
  opt.out_dir = dir.path() / "q";
  opt.jobs = 2;
  opt.progress = false;
  opt.episodes = 4;
  RunSuite(*loaded.suite, registry, opt);
  opt.episodes = 2;
  RunSuite(*loaded.suite, registry, opt);
  const std::string html = BuildReport(opt.out_dir, registry);
  EXPECT_NE(html.find(" 4 episodes in the table (episodes.csv holds 8, kept from a longer run"),
            std::string::npos)
      << html.substr(0, 2000);
  EXPECT_NE(html.find("run with --set humans.count=2"), std::string::npos);
}

TEST_F(ReportTest, ShowsTheFirstOfEachOutcome) {
  const auto lines = ReadEpisodesCsv(Results() / "episodes.csv");
  int first_success = -1;
  for (const EpisodeLine& l : lines) {
    if (l.row == "orca" && l.outcome.status == EpisodeStatus::kSuccess && first_success < 0)
      first_success = l.episode;
  }
  ASSERT_GE(first_success, 0) << "ORCA succeeds in quick.yaml";
  PluginRegistry registry;
  const std::string html = BuildReport(Results(), registry);
  EXPECT_NE(html.find("id=\"fig-r2-e" + std::to_string(first_success) + "\""), std::string::npos);
  // A replay that disagrees with the recorded outcome would be flagged.
  EXPECT_EQ(html.find("replay: "), std::string::npos);
}

TEST(ReportErrors, MissingFolderNamesIt) {
  PluginRegistry registry;
  try {
    BuildReport("/nonexistent/results/quick", registry);
    FAIL() << "expected ReportError";
  } catch (const ReportError& e) {
    EXPECT_NE(std::string(e.what()).find("'/nonexistent/results/quick' does not exist"),
              std::string::npos)
        << e.what();
  }
}

TEST(ReportErrors, FolderWithoutResultsSaysWhatIsExpected) {
  TempDir tmp;
  PluginRegistry registry;
  try {
    BuildReport(tmp.path(), registry);
    FAIL() << "expected ReportError";
  } catch (const ReportError& e) {
    EXPECT_NE(std::string(e.what()).find("has no manifest.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("table.csv, episodes.csv"), std::string::npos) << e.what();
  }
}

TEST(ReportErrors, AShardOrAnUnfinishedRunSaysWhatToDo) {
  TempDir tmp;
  PluginRegistry registry;
  auto error = [&]() {
    try {
      BuildReport(tmp.path(), registry);
    } catch (const ReportError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  std::ofstream(tmp.path() / "episodes.csv") << "row,episode\n";
  std::ofstream(tmp.path() / "manifest.json") << R"({"suite": "quick", "config_hash": "ab12"})";
  EXPECT_NE(error().find("holds a run that has not finished (no table.csv, or a manifest without "
                         "finished_utc): rerun the same"),
            std::string::npos)
      << error();
  std::ofstream(tmp.path() / "manifest.json")
      << R"({"suite": "quick", "config_hash": "ab12", "shard": "2/3"})";
  EXPECT_NE(error().find("is shard 2/3 of a run, which has no tables: join the shards with"),
            std::string::npos)
      << error();
}

// It advised a rerun, which then asked for --fresh: now the way out is said at once.
TEST(ReportErrors, ADamagedManifestSaysItsEpisodesCannotBeUsed) {
  TempDir tmp;
  PluginRegistry registry;
  std::ofstream(tmp.path() / "episodes.csv") << "row,episode\n";
  std::ofstream(tmp.path() / "table.csv") << "row\n";
  std::ofstream(tmp.path() / "manifest.json") << R"({"suite": "quick", "config_h)";
  try {
    BuildReport(tmp.path(), registry);
    FAIL() << "expected ReportError";
  } catch (const ReportError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("is damaged or not crowdsim-bench's (it names no config_hash)"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("into a new --out folder (or into this one with --fresh"),
              std::string::npos)
        << what;
    EXPECT_EQ(what.find("rerun the same"), std::string::npos) << what;
  }
}

TEST_F(ReportTest, MissingSuiteFileSaysHowToFix) {
  PluginRegistry registry;
  ReportOptions opt;
  opt.suite_file = "/nonexistent/suite.yaml";
  try {
    BuildReport(Results(), registry, opt);
    FAIL() << "expected ReportError";
  } catch (const ReportError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/suite.yaml"), std::string::npos) << e.what();
  }
}

TEST_F(ReportTest, AnotherSuitesFileIsRefused) {
  // It titled the page with the other suite and drew every row as "not in the suite file".
  PluginRegistry registry;
  ReportOptions opt;
  opt.suite_file = crowdsim::testing::SourceDir() / "suites/baselines.yaml";
  try {
    BuildReport(Results(), registry, opt);
    FAIL() << "expected ReportError";
  } catch (const ReportError& e) {
    EXPECT_NE(std::string(e.what()).find("is the suite 'baselines', but"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("holds a run of the suite 'quick'"), std::string::npos)
        << e.what();
  }
}

TEST(TrainingReport, ACommittedModelFolderReadsItsCompressedEpisodeLog) {
  // results/models/* keep training_episodes.csv.gz: the report drew an empty learning curve
  // and "no RL episode logged yet" for every committed model.
  const fs::path model =
      crowdsim::testing::SourceDir() / "results/models/cadrl_pp_lidar_person_rect1";
  ASSERT_TRUE(fs::exists(model / "training_episodes.csv.gz"));
  ASSERT_FALSE(fs::exists(model / "training_episodes.csv"));
  const std::string log = ReadTrainingEpisodes(model);
  EXPECT_GT(CountOf(log, "\nrl,"), 9000) << log.substr(0, 300);
  const std::string html = BuildTrainingReport(model);
  EXPECT_EQ(html.find("no RL episode logged yet"), std::string::npos);
}

TEST(TrainingReport, AnUnfinishedTrainingSaysSoAtTheTop) {
  // Its summary.json's "finished": false was the only sign, in the JSON at the bottom.
  TempDir tmp;
  std::ofstream(tmp.path() / "training_log.csv") << "rl_episode,success\n";
  std::ofstream(tmp.path() / "summary.json")
      << R"({"name": "t", "procedure": {"rl_episodes": 300}, "finished": false, "phase": 2,)"
      << R"( "counter": 120})";
  const std::string html = BuildTrainingReport(tmp.path());
  EXPECT_NE(html.find("Unfinished: the training stopped after 120 RL episodes of its 300; "
                      "continue it with the same `crowdsim-bench train` command and --resume."),
            std::string::npos)
      << html.substr(0, 2000);
  std::ofstream(tmp.path() / "summary.json")
      << R"({"name": "t", "procedure": {"rl_episodes": 300}, "finished": true})";
  EXPECT_EQ(BuildTrainingReport(tmp.path()).find("Unfinished"), std::string::npos);
}

// Opens the report offline in headless Chromium and takes a screenshot.
TEST_F(ReportTest, OpensInHeadlessChromium) {
  const fs::path chromium = "/usr/bin/chromium";
  if (!fs::exists(chromium))
    GTEST_SKIP() << "/usr/bin/chromium is absent (apt-get install chromium to run this test)";
  PluginRegistry registry;
  const fs::path page = dir_->path() / "report.html";
  std::ofstream(page) << BuildReport(Results(), registry);
  const fs::path shot = dir_->path() / "report.png";
  const fs::path profile = dir_->path() / "chromium-profile";
  const std::string cmd =
      "timeout 120 " + chromium.string() +
      " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
      " --disable-background-networking --disable-component-update --disable-sync"
      " --user-data-dir=" +
      profile.string() + " --screenshot=" + shot.string() + " --window-size=1400,1000 file://" +
      page.string() + " > " + (dir_->path() / "chromium.log").string() + " 2>&1";
  const int rc = std::system(cmd.c_str());
  ASSERT_EQ(rc, 0) << cmd << "\n" << crowdsim::testing::ReadText(dir_->path() / "chromium.log");
  ASSERT_TRUE(fs::exists(shot)) << crowdsim::testing::ReadText(dir_->path() / "chromium.log");
  std::ifstream in(shot, std::ios::binary);
  std::string magic(8, '\0');
  in.read(magic.data(), 8);
  EXPECT_EQ(magic, std::string("\x89PNG\r\n\x1a\n", 8));
  // A blank page compresses to a few kB; the table, charts and thumbnails do not.
  EXPECT_GT(fs::file_size(shot), 30000u);
  if (const char* keep = std::getenv("CROWDSIM_KEEP_SCREENSHOT"))
    fs::copy_file(shot, keep, fs::copy_options::overwrite_existing);
}

}  // namespace
}  // namespace crowdsim::render
