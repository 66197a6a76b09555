// A suite that names social metrics in `columns:`: they join episodes.csv, table.csv and the
// manifest, leave the episodes as they were, resume, and travel from isolated workers.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "crowdsim/bench/csv.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/bench/runner.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

namespace fs = std::filesystem;
using testing::ReadText;
using testing::TempDir;

constexpr const char* kPlain = R"(name: social
episodes: 8
seed: 5
world: {source: random_rect, obstacles: 1, split: test}
humans: {count: 5, policy: orca}
robot:
  sensors: [person]
rows:
  - {label: linear, policy: linear}
  - {label: orca, policy: orca}
)";

// The column of `name` in every line of an episodes.csv.
std::vector<std::string> Column(const std::string& csv, const std::string& name) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  const auto header = SplitCsvLine(line);
  const size_t k = std::find(header.begin(), header.end(), name) - header.begin();
  std::vector<std::string> values;
  while (std::getline(in, line)) values.push_back(SplitCsvLine(line).at(k));
  return values;
}

class SocialMetricsRunTest : public ::testing::Test {
 protected:
  Suite Load(const std::string& yaml) {
    SuiteLoadResult r = LoadSuite(dir_.Write("suite.yaml", yaml), registry_);
    std::string errors;
    for (const auto& e : r.errors) errors += e.Format() + "\n";
    EXPECT_TRUE(r.suite) << errors;
    return r.suite ? *r.suite : Suite{};
  }
  RunSummary Run(const Suite& s, const std::string& out) {
    RunOptions o;
    o.out_dir = dir_.path() / out;
    o.jobs = 2;
    o.progress = false;
    return RunSuite(s, registry_, o);
  }
  std::string Text(const std::string& out, const std::string& file) {
    return ReadText(dir_.path() / out / file);
  }

  TempDir dir_;
  PluginRegistry registry_{{testing::PluginDir(), testing::FixturePluginDir()}};
};

TEST_F(SocialMetricsRunTest, NamedMetricsJoinEveryFileAndChangeNoEpisode) {
  const Suite plain = Load(kPlain);
  const Suite social = Load(std::string(kPlain) + "columns: [spl, personal_intrusions]\n");
  EXPECT_FALSE(plain.social_metrics);
  ASSERT_TRUE(social.social_metrics);
  EXPECT_NE(plain.ConfigHash(), social.ConfigHash());  // stored plain results are not resumed
  Run(plain, "plain");
  Run(social, "social");

  const std::string csv = Text("social", "episodes.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), EpisodeCsvHeader(true));
  EXPECT_EQ(Text("plain", "episodes.csv").substr(0, csv.find('\n')).find("spl"), std::string::npos);
  // The episodes are the plain suite's: every column both have agrees.
  const auto read = ReadEpisodesCsvChecked(dir_.path() / "social" / "episodes.csv");
  ASSERT_TRUE(read.social);
  std::string without;
  without = EpisodeCsvHeader(false) + "\n";
  for (const EpisodeLine& e : read.lines) without += FormatEpisodeLine(e, false) + "\n";
  EXPECT_EQ(WithoutTimingColumns(without), WithoutTimingColumns(Text("plain", "episodes.csv")));

  // SPL: 0 without success, in (0, 1] with it.
  const auto status = Column(csv, "status"), spl = Column(csv, "spl");
  int successes = 0;
  for (size_t i = 0; i < status.size(); ++i) {
    const double x = std::stod(spl[i]);
    if (status[i] == "success") {
      ++successes;
      EXPECT_GT(x, 0.0);
      EXPECT_LE(x, 1.0);
    } else {
      EXPECT_EQ(x, 0.0);
    }
  }
  EXPECT_GT(successes, 0);

  // table.md shows what the suite named; table.csv and the manifest carry every metric.
  const std::string md = Text("social", "table.md");
  EXPECT_NE(md.find("| SPL |"), std::string::npos) << md;
  EXPECT_NE(md.find("| personal intrusions |"), std::string::npos) << md;
  EXPECT_EQ(md.find("jerk max"), std::string::npos) << md;
  EXPECT_NE(Text("social", "table.csv").find("jerk max"), std::string::npos);
  EXPECT_EQ(Text("plain", "table.csv").find("jerk max"), std::string::npos);
  const auto manifest = nlohmann::json::parse(Text("social", "manifest.json"));
  EXPECT_TRUE(manifest["rows"][0]["metrics"].contains("min_ttc"));
  EXPECT_FALSE(
      nlohmann::json::parse(Text("plain", "manifest.json"))["rows"][0]["metrics"].contains("spl"));
}

// The walking groups' metrics are a family of their own: naming one adds its columns alone, so a
// suite naming only the first family's metrics keeps its files; both together carry both.
TEST_F(SocialMetricsRunTest, GroupMetricsAreAFamilyOfTheirOwn) {
  std::string grouped = kPlain;
  grouped.replace(grouped.find("policy: orca}"), 13, "policy: orca, groups: {share: 1, size: 2}}");
  const Suite groups = Load(grouped + "columns: [group_intrusions]\n");
  const Suite core = Load(grouped + "columns: [spl]\n");
  const Suite both = Load(grouped + "columns: [spl, group_share]\n");
  EXPECT_EQ(groups.social_metrics, kGroupMetrics);
  EXPECT_EQ(core.social_metrics, kCoreMetrics);
  EXPECT_EQ(both.social_metrics, kCoreMetrics | kGroupMetrics);
  EXPECT_NE(groups.canonical.find("group_metrics"), std::string::npos);
  EXPECT_EQ(core.canonical.find("group_metrics"), std::string::npos);
  Run(groups, "groups");
  Run(core, "core");
  Run(both, "both");
  const std::string csv = Text("groups", "episodes.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')), EpisodeCsvHeader(kGroupMetrics));
  EXPECT_EQ(Text("core", "episodes.csv").substr(0, csv.find('\n')).find("group_"),
            std::string::npos);
  const std::string all = Text("both", "episodes.csv");
  EXPECT_EQ(all.substr(0, all.find('\n')), EpisodeCsvHeader(kCoreMetrics | kGroupMetrics));
  // Two pairs and one person alone in every episode: the metrics apply everywhere.
  for (const std::string& v : Column(csv, "group_intrusions")) EXPECT_FALSE(v.empty());
  EXPECT_EQ(Column(csv, "group_share"), Column(all, "group_share"));
  EXPECT_EQ(Column(csv, "status"), Column(Text("core", "episodes.csv"), "status"));
}

TEST_F(SocialMetricsRunTest, AMistypedMetricIsAnErrorNamingTheMetricMeant) {
  const SuiteLoadResult r = LoadSuite(
      dir_.Write("typo.yaml", std::string(kPlain) + "columns: [spl, jerk_meen]\n"), registry_);
  EXPECT_FALSE(r.suite);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_EQ(r.errors[0].line, 11);  // the columns: line after kPlain's ten
  EXPECT_NE(r.errors[0].Format().find("'jerk_meen' is no row's info key and no social metric; "
                                      "did you mean 'jerk_mean'?"),
            std::string::npos)
      << r.errors[0].Format();
  // An info column of any other name stays what it was: filled from the rows' info.
  EXPECT_TRUE(
      LoadSuite(dir_.Write("info.yaml", std::string(kPlain) + "columns: [notes]\n"), registry_)
          .suite);
}

TEST_F(SocialMetricsRunTest, AStoredRunResumesWithItsMetrics) {
  const Suite social = Load(std::string(kPlain) + "columns: [jerk_mean]\n");
  Run(social, "out");
  const std::string first = Text("out", "episodes.csv");
  const RunSummary again = Run(social, "out");
  EXPECT_EQ(again.episodes_run, 0);
  EXPECT_EQ(again.episodes_resumed, 16);
  EXPECT_EQ(WithoutTimingColumns(Text("out", "episodes.csv")), WithoutTimingColumns(first));
}

TEST_F(SocialMetricsRunTest, IsolatedWorkersSendTheMetricsUnrounded) {
  const std::string yaml = std::string(kPlain) + "columns: [min_ttc]\n";
  Run(Load(yaml), "threads");
  Run(Load(yaml + "isolation: on\n"), "processes");
  EXPECT_EQ(WithoutTimingColumns(Text("threads", "episodes.csv")),
            WithoutTimingColumns(Text("processes", "episodes.csv")));
}

}  // namespace
}  // namespace crowdsim
