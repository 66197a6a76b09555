// manifest.json is written and read back as JSON: text the user wrote (descriptions, --set
// overrides, labels) survives the round trip, and a missing, damaged or foreign file reads as
// "absent" rather than as a wrong value.
#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/bench/suite.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

TEST(ManifestJson, UserTextSurvivesTheRoundTrip) {
  testing::TempDir dir;
  const auto file = dir.Write(
      "s.yaml",
      "name: t\nepisodes: 1\ndescription: \"a \\\"quoted\\\" \\\\ back, \\u00fc, tab\\there\"\n"
      "world: {source: random_rect, obstacles: 1, split: test}\nrows:\n"
      "  - {label: \"x \\\"y\\\" [z]\", policy: linear, info: {note: \"a, b: \\\"c\\\"\"}}\n");
  PluginRegistry registry{{testing::PluginDir()}};
  const SuiteLoadResult loaded = LoadSuite(file, registry, {"episodes=2"});
  ASSERT_TRUE(loaded.suite) << loaded.errors[0].Format();
  RowMetrics metrics;
  metrics.nav_time = std::numeric_limits<double>::quiet_NaN();
  const std::vector<TableRow> rows = {TableRow{&loaded.suite->rows[0], metrics}};
  RunFacts facts;
  facts.shard = "1/2";
  const auto manifest = dir.Write("manifest.json", FormatManifestJson(*loaded.suite, rows, facts));

  EXPECT_EQ(ReadManifestField(manifest, "description"), loaded.suite->description);
  EXPECT_EQ(ReadManifestStrings(manifest, "overrides"), loaded.suite->overrides);
  EXPECT_EQ(ReadManifestField(manifest, "shard"), "1/2");
  EXPECT_EQ(ReadManifestField(manifest, "/rows/0/label"), "x \"y\" [z]");
  EXPECT_EQ(ReadManifestField(manifest, "/rows/0/info/note"), "a, b: \"c\"");
  EXPECT_EQ(ReadManifestField(manifest, "config_hash"), loaded.suite->ConfigHash());
  EXPECT_EQ(ReadManifestInteger(manifest, "/rows/0/metrics/episodes"), 0);
  EXPECT_EQ(ReadManifestBool(manifest, "isolated"), false);
  // JSON has no NaN: a number that is not finite is written as null.
  const auto j = nlohmann::json::parse(testing::ReadText(manifest));
  EXPECT_TRUE(j["rows"][0]["metrics"]["nav_time"].is_null()) << j.dump(1);
  EXPECT_EQ(j["description"], "a \"quoted\" \\ back, \u00fc, tab\there");
}

TEST(ManifestJson, MissingDamagedOrForeignFilesReadAsAbsent) {
  testing::TempDir dir;
  for (const auto& [name, text] :
       {std::pair{"garbage.json", "{\"config_hash\": \"abc\", "},  // cut: no value, not "abc"
        {"list.json", "[\"config_hash\", \"abc\"]"},
        {"typed.json",
         "{\"config_hash\": 12, \"episodes\": \"12\", \"overrides\": \"a\", \"isolated\": 1}"},
        {"nested.json", "{\"rows\": [{\"config_hash\": \"abc\", \"episodes\": 3}]}"}}) {
    const auto file = dir.Write(name, text);
    EXPECT_EQ(ReadManifestField(file, "config_hash"), "") << name;
    EXPECT_EQ(ReadManifestInteger(file, "episodes"), -1) << name;
    EXPECT_TRUE(ReadManifestStrings(file, "overrides").empty()) << name;
    EXPECT_FALSE(ReadManifestBool(file, "isolated").has_value()) << name;
  }
  EXPECT_EQ(ReadManifestField(dir.path() / "none.json", "config_hash"), "");
  EXPECT_EQ(ReadManifestInteger(dir.path() / "none.json", "/a/b"), -1);
}

}  // namespace
}  // namespace crowdsim
