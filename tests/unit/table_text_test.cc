// Text that users put in suites (labels, info values) cannot break the result files: a '|'
// would open a new Markdown cell, a carriage return would split a CSV record.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <fstream>
#include <nlohmann/json.hpp>

#include "crowdsim/bench/csv.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/bench/suite.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

// A suite written into `dir` and loaded with the built plugins (the registry outlives it).
SuiteLoadResult LoadText(const testing::TempDir& dir, const std::string& yaml) {
  static PluginRegistry registry{{testing::PluginDir()}};
  return LoadSuite(dir.Write("s.yaml", yaml), registry);
}

TEST(TableText, CsvFieldsKeepOneRecordPerLine) {
  EXPECT_EQ(CsvField("plain"), "plain");
  EXPECT_EQ(CsvField("a,b"), "\"a,b\"");
  EXPECT_EQ(CsvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvField("two\r\nlines"), "\"two  lines\"");
  EXPECT_EQ(CsvField("cr\ronly"), "\"cr only\"");
  EXPECT_EQ(SplitCsvLine(CsvField("a,\"b\"\rc")), std::vector<std::string>{"a,\"b\" c"});
}

// table.csv's user cells (labels, info) that a spreadsheet would run as a formula start with
// a quote; numbers, a lone dash and the harness's own columns are written as they are.
TEST(TableText, CsvCellsAreNoFormulas) {
  testing::TempDir dir;
  const SuiteLoadResult loaded = LoadText(
      dir,
      "name: t\nepisodes: 1\nworld: {source: random_rect, obstacles: 1, split: test}\n"
      "columns: [model, \"@note\"]\nrows:\n"
      "  - {label: \"=HYPERLINK(1)\", policy: linear, info: {model: \"+cmd\", \"@note\": \"-\"}}\n"
      "  - {label: \"-orca\", policy: linear, info: {model: \"-1.5\", \"@note\": \"@x\"}}\n");
  ASSERT_TRUE(loaded.suite) << loaded.errors[0].Format();
  RowMetrics metrics;
  metrics.discounted_return = -0.25;
  const std::vector<TableRow> rows = {TableRow{&loaded.suite->rows[0], metrics},
                                      TableRow{&loaded.suite->rows[1], metrics}};
  const std::string csv = FormatTableCsv(*loaded.suite, rows);
  EXPECT_NE(csv.find("row,label,model,'@note,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("1,'=HYPERLINK(1),'+cmd,-,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("2,'-orca,-1.5,'@x,"), std::string::npos) << csv;
  EXPECT_NE(csv.find(",-0.2500"), std::string::npos) << csv;  // a number of ours, unchanged
}

TEST(TableText, MarkdownCellsEscapeThePipe) {
  testing::TempDir dir;
  const SuiteLoadResult loaded = LoadText(
      dir,
      "name: t\nepisodes: 1\nworld: {source: random_rect, obstacles: 1, split: test}\n"
      "columns: [model]\nrows:\n  - {label: a, policy: linear, info: {model: \"x | y\"}}\n");
  ASSERT_TRUE(loaded.suite) << loaded.errors[0].Format();
  const std::vector<TableRow> rows = {TableRow{&loaded.suite->rows[0], RowMetrics{}}};
  const std::string md = FormatTableMarkdown(*loaded.suite, rows);
  EXPECT_NE(md.find("| x \\| y |"), std::string::npos) << md;
  // In each of table.md's tables, every line has as many unescaped cell separators as its header.
  std::vector<std::vector<int>> tables(1);
  std::size_t start = 0;
  for (std::size_t end = md.find('\n'); end != std::string::npos;
       start = end + 1, end = md.find('\n', start)) {
    if (md[start] != '|') {
      if (!tables.back().empty()) tables.emplace_back();
      continue;
    }
    int n = 0;
    for (std::size_t i = start; i < end; ++i) n += md[i] == '|' && (i == 0 || md[i - 1] != '\\');
    tables.back().push_back(n);
  }
  ASSERT_EQ(tables.size(), 2u);  // the paper's columns; ours with intervals
  for (const auto& separators : tables) {
    ASSERT_EQ(separators.size(), 3u);
    EXPECT_EQ(separators[0], separators[1]);
    EXPECT_EQ(separators[0], separators[2]);
  }
}

RowMetrics Made(int episodes, int successes, int collisions, double nav_time, double se) {
  RowMetrics m;
  m.episodes = episodes;
  m.successes = successes;
  m.collisions = collisions;
  m.timeouts = episodes - successes - collisions;
  m.success_rate = static_cast<double>(successes) / episodes;
  m.collision_rate = static_cast<double>(collisions) / episodes;
  m.timeout_rate = static_cast<double>(m.timeouts) / episodes;
  m.nav_time = nav_time;
  m.nav_time_se = se;
  return m;
}

TEST(TableText, PublishedValuesIntervalsAndSummaryLines) {
  testing::TempDir dir;
  const SuiteLoadResult loaded = LoadText(
      dir,
      "name: t\nepisodes: 1\nworld: {source: random_rect, obstacles: 1, split: test}\nrows:\n"
      "  - {label: a, policy: linear, reference: {success: 0.70, collision: 0.30, nav_time: "
      "12.0, source: \"Paper, line 1\"}}\n"
      "  - {label: b, policy: linear}\n"
      "summaries:\n  - {label: avg, rows: [a, b], reference: {success: 0.6}}\n");
  ASSERT_TRUE(loaded.suite) << loaded.errors[0].Format();
  // a: 348/500 successes, interval [0.6543, 0.7347] holds 0.70; 10/500 collisions does not
  // hold 0.30; nav. time 14 +- 0.2 does not hold 12.
  std::vector<TableRow> rows = {TableRow{&loaded.suite->rows[0], Made(500, 348, 10, 14.0, 0.2)},
                                TableRow{&loaded.suite->rows[1], Made(500, 300, 100, 13.0, 0.3)}};
  AddSummaryLines(*loaded.suite, &rows);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[2].Label(), "avg");
  EXPECT_NEAR(rows[2].metrics.success_rate, 0.648, 1e-12);
  EXPECT_EQ(rows[2].metrics.successes, 648);

  const std::string md = FormatTableMarkdown(*loaded.suite, rows);
  EXPECT_NE(md.find("| 1 | a | 0.6960 [0.6543, 0.7347] | 0.7000 | -0.0040 | 0.0200 [0.0109, "
                    "0.0364] | 0.3000 | -0.2800 * |"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| 14.00 ± 0.20 | 12.00 | +2.00 * |"), std::string::npos) << md;
  EXPECT_NE(md.find("Paper, line 1"), std::string::npos) << md;
  // The summary line has no row number, its rows' range, and its own reference.
  EXPECT_NE(md.find("|  | avg | 0.6480 ["), std::string::npos) << md;
  EXPECT_NE(md.find("rows 0.6000–0.6960 | 0.6000 | +0.0480 * |"), std::string::npos) << md;

  const std::string csv = FormatTableCsv(*loaded.suite, rows);
  std::vector<std::vector<std::string>> lines;
  std::size_t start = 0;
  for (std::size_t end = csv.find('\n'); end != std::string::npos;
       start = end + 1, end = csv.find('\n', start)) {
    lines.push_back(SplitCsvLine(csv.substr(start, end - start)));
  }
  ASSERT_EQ(lines.size(), 4u);
  for (const auto& line : lines) EXPECT_EQ(line.size(), lines[0].size());
  auto column = [&](const std::string& name) {
    const auto it = std::find(lines[0].begin(), lines[0].end(), name);
    EXPECT_NE(it, lines[0].end()) << name;
    return static_cast<std::size_t>(it - lines[0].begin());
  };
  EXPECT_EQ(lines[1][column("success 95% low")], "0.6543");
  EXPECT_EQ(lines[1][column("paper collision")], "0.3000");
  EXPECT_EQ(lines[1][column("Δ nav. time")], "+2.0000");
  EXPECT_EQ(lines[2][column("paper success")], "");
  EXPECT_EQ(lines[3][column("row")], "");
  EXPECT_EQ(lines[3][column("label")], "avg");

  const std::string text = FormatManifestJson(*loaded.suite, rows, RunFacts{});
  const auto manifest = nlohmann::json::parse(text);
  ASSERT_EQ(manifest["summaries"].size(), 1u) << text;
  EXPECT_EQ(manifest["summaries"][0]["label"], "avg") << text;
  EXPECT_EQ(manifest["summaries"][0]["rows"], nlohmann::json({"a", "b"})) << text;
  // The published values as the suite gave them: only those given, and their source.
  EXPECT_EQ(
      manifest["rows"][0]["reference"],
      nlohmann::json(
          {{"success", 0.7}, {"collision", 0.3}, {"nav_time", 12.0}, {"source", "Paper, line 1"}}))
      << text;
  EXPECT_FALSE(manifest["rows"][1].contains("reference")) << text;
  EXPECT_NEAR(manifest["summaries"][0]["metrics"]["success_rate"].get<double>(), 0.648, 1e-12)
      << text;
}

// The files in a folder other than `keep`, hidden ones included.
std::vector<std::string> OtherFiles(const std::filesystem::path& dir, const std::string& keep) {
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (e.path().filename() != keep) names.push_back(e.path().filename().string());
  }
  return names;
}

TEST(ResultFiles, AFailedWriteIsNamedAndLeavesNoTemporaryFile) {
  testing::TempDir dir;
  const auto target = dir.path() / "table.md";
  std::ofstream(target) << "the previous table\n";
  // In a child whose files may not grow past 4 kB (a full disk's failure, as a write sees it).
  const pid_t pid = fork();
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    setrlimit(RLIMIT_FSIZE, &limit);
    try {
      WriteFileAtomically(target, std::string(1 << 16, 'x'));
      _exit(1);
    } catch (const std::runtime_error& e) {
      const std::string what = e.what();
      _exit(what.find("cannot write " + target.string() + ": File too large") == 0 ? 0 : 2);
    }
  }
  int status = 0;
  waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: the write succeeded; 2: another message";
  EXPECT_EQ(OtherFiles(dir.path(), "table.md"), std::vector<std::string>{});
  EXPECT_EQ(testing::ReadText(target), "the previous table\n");
}

// A link planted in a shared output folder never leads a write outside it: not at the file's
// name (the link is replaced), nor at a temporary file's name (a new file is made each time).
TEST(ResultFiles, AWriteNeverFollowsALinkOutOfTheFolder) {
  testing::TempDir dir;
  const auto out = dir.path() / "out";
  std::filesystem::create_directories(out);
  const auto outside = dir.path() / "outside.txt";
  std::ofstream(outside) << "not yours\n";
  std::filesystem::create_symlink(outside, out / "table.md");
  std::filesystem::create_symlink(outside, out / "table.md.tmp");
  WriteFileAtomically(out / "table.md", "the table\n");
  EXPECT_EQ(testing::ReadText(outside), "not yours\n");
  EXPECT_FALSE(std::filesystem::is_symlink(out / "table.md"));
  EXPECT_EQ(testing::ReadText(out / "table.md"), "the table\n");
  EXPECT_TRUE(std::filesystem::is_symlink(out / "table.md.tmp"));
  EXPECT_EQ(OtherFiles(out, "table.md"), std::vector<std::string>{"table.md.tmp"});
}

}  // namespace
}  // namespace crowdsim
