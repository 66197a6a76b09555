// Text that users put in suites (labels, info values) cannot break the result files: a '|'
// would open a new Markdown cell, a carriage return would split a CSV record.
#include <gtest/gtest.h>

#include "crowdsim/csv.h"
#include "crowdsim/plugin_registry.h"
#include "crowdsim/results.h"
#include "crowdsim/suite.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

TEST(TableText, CsvFieldsKeepOneRecordPerLine) {
  EXPECT_EQ(CsvField("plain"), "plain");
  EXPECT_EQ(CsvField("a,b"), "\"a,b\"");
  EXPECT_EQ(CsvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvField("two\r\nlines"), "\"two  lines\"");
  EXPECT_EQ(CsvField("cr\ronly"), "\"cr only\"");
  EXPECT_EQ(SplitCsvLine(CsvField("a,\"b\"\rc")), std::vector<std::string>{"a,\"b\" c"});
}

TEST(TableText, MarkdownCellsEscapeThePipe) {
  testing::TempDir dir;
  const auto file = dir.Write("s.yaml",
      "name: t\nepisodes: 1\nworld: {source: random_rect, obstacles: 1, split: test}\n"
      "columns: [model]\nrows:\n  - {label: a, policy: linear, info: {model: \"x | y\"}}\n");
  PluginRegistry registry{{testing::PluginDir()}};
  const SuiteLoadResult loaded = LoadSuite(file, registry);
  ASSERT_TRUE(loaded.suite) << loaded.errors[0].Format();
  const std::vector<TableRow> rows = {TableRow{&loaded.suite->rows[0], RowMetrics{}}};
  const std::string md = FormatTableMarkdown(*loaded.suite, rows);
  EXPECT_NE(md.find("| x \\| y |"), std::string::npos) << md;
  // Every line has as many unescaped cell separators as the header.
  std::vector<int> separators;
  std::size_t start = 0;
  for (std::size_t end = md.find('\n'); end != std::string::npos; start = end + 1, end = md.find('\n', start)) {
    int n = 0;
    for (std::size_t i = start; i < end; ++i) n += md[i] == '|' && (i == 0 || md[i - 1] != '\\');
    separators.push_back(n);
  }
  ASSERT_EQ(separators.size(), 3u);
  EXPECT_EQ(separators[0], separators[1]);
  EXPECT_EQ(separators[0], separators[2]);
}

}  // namespace
}  // namespace crowdsim
