// Suite validation: every error at once, each located (file:line:col), with the key path,
// the offending value and the valid choices.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "crowdsim/bench/results.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/data_root.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

using testing::TempDir;

class SuiteValidation : public ::testing::Test {
 protected:
  SuiteLoadResult Load(const std::string& yaml) {
    file_ = dir_.Write("suite.yaml", yaml);
    return LoadSuite(file_, registry_);
  }
  /// The formatted error that mentions `needle`, or "".
  static std::string Find(const SuiteLoadResult& r, const std::string& needle) {
    for (const auto& e : r.errors) {
      if (e.Format().find(needle) != std::string::npos) return e.Format();
    }
    return "";
  }
  static std::string All(const SuiteLoadResult& r) {
    std::string s;
    for (const auto& e : r.errors) s += e.Format() + "\n";
    return s;
  }

  TempDir dir_;
  std::filesystem::path file_;
  PluginRegistry registry_{{testing::PluginDir(), testing::FixturePluginDir()}};
};

constexpr const char* kGood = R"(name: t
episodes: 3
seed: 5
world: {source: random_rect, obstacles: 1, split: test}
humans: {count: 2, policy: linear}
rows:
  - {label: a, policy: linear, sensors: [person, {type: lidar2d, beams: 9}]}
  - {label: b, policy: linear, params: {speed_factor: 0.5}}
)";

TEST_F(SuiteValidation, GoodSuiteLoads) {
  auto r = Load(kGood);
  ASSERT_TRUE(r.suite) << All(r);
  EXPECT_EQ(r.suite->rows.size(), 2u);
  EXPECT_EQ(r.suite->rows[0].sensors.size(), 2u);
  EXPECT_EQ(r.suite->rows[0].sensors[1].params.GetInt("beams"), 9);
  EXPECT_DOUBLE_EQ(r.suite->rows[1].policy.params.GetDouble("speed_factor"), 0.5);
  EXPECT_EQ(r.suite->rows[1].humans.count, 2);
  EXPECT_EQ(r.suite->episodes, 3);
}

TEST_F(SuiteValidation, ConfigHashIgnoresEpisodesButNotParameters) {
  auto a = Load(kGood);
  std::string more = kGood;
  more.replace(more.find("episodes: 3"), 11, "episodes: 9");
  auto b = Load(more);
  std::string other = kGood;
  other.replace(other.find("speed_factor: 0.5"), 17, "speed_factor: 0.6");
  auto c = Load(other);
  ASSERT_TRUE(a.suite && b.suite && c.suite);
  EXPECT_EQ(a.suite->ConfigHash(), b.suite->ConfigHash());
  EXPECT_NE(a.suite->ConfigHash(), c.suite->ConfigHash());
}

TEST_F(SuiteValidation, ReportsAllErrorsAtOnceWithLocations) {
  auto r = Load(R"(name: t
episodes: 0
sede: 5
world: {source: random_rect, obstacles: 1, split: tset}
rows:
  - {policy: lineer}
  - {policy: linear, params: {speed_factor: 7, speedfactor: 1}}
  - {policy: linear, sensors: [{type: lidar2d, beams: many}]}
)");
  ASSERT_FALSE(r.suite);
  const std::string all = All(r);
  EXPECT_GE(r.errors.size(), 7u) << all;
  // Range, with the offending value and the valid range.
  EXPECT_NE(Find(r, ":2:11: episodes: value 0 is out of range; valid: [1,"), "") << all;
  // Unknown top-level key.
  EXPECT_NE(Find(r, ":3:1: sede: unknown key 'sede'"), "") << all;
  // A choice.
  EXPECT_NE(Find(r, "world.split: value 'tset' is not valid; valid: train, test"), "") << all;
  // Unknown plugin: the valid choices.
  const std::string unknown = Find(r, "rows[0].policy: unknown policy plugin 'lineer'");
  EXPECT_NE(unknown, "") << all;
  EXPECT_NE(unknown.find("linear"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find(":6:14:"), std::string::npos) << unknown;
  EXPECT_TRUE(unknown.ends_with("; did you mean 'linear'?")) << unknown;
  // Parameter range and unknown parameter.
  EXPECT_NE(Find(r, "rows[1].params.speed_factor: value 7 is out of range; valid: [0, 2]"), "")
      << all;
  EXPECT_NE(Find(r,
                 "rows[1].params.speedfactor: unknown parameter 'speedfactor' for policy plugin "
                 "'linear' (valid: speed_factor, slow_down); did you mean 'speed_factor'?"),
            "")
      << all;
  // Type.
  EXPECT_NE(Find(r, "rows[2].sensors[0].beams: must be a whole number, found 'many'"), "") << all;
}

TEST_F(SuiteValidation, NumbersInAnyNotationAreTheirValue) {
  // 1e3 is a whole number; 2.5 is not; 1e400 and 1e30 are numbers out of range ("must be a
  // number" / "must be a whole number" before).
  auto ok = Load(std::string(kGood).replace(std::string(kGood).find("beams: 9"), 8, "beams: 9e1"));
  ASSERT_TRUE(ok.suite) << All(ok);
  EXPECT_EQ(ok.suite->rows[0].sensors[1].params.GetInt("beams"), 90);
  auto r = Load(R"(name: t
episodes: 3
world: {source: random_rect, obstacles: 1, split: test}
rows:
  - {policy: linear, sensors: [{type: lidar2d, beams: 2.5}]}
  - {policy: linear, sensors: [{type: lidar2d, beams: 1e30}]}
  - {policy: linear, params: {speed_factor: 1e400}}
  - {policy: linear, sensors: [{type: lidar2d, beams: 1e-400}]}
)");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r, "rows[0].sensors[0].beams: must be a whole number, found '2.5'"), "") << All(r);
  EXPECT_NE(Find(r, "rows[1].sensors[0].beams: value 1e30 is out of range; valid: ["), "")
      << All(r);
  EXPECT_NE(Find(r, "rows[2].params.speed_factor: value 1e400 is out of range; valid: [0, 2]"), "")
      << All(r);
  EXPECT_NE(Find(r, "rows[3].sensors[0].beams: must be a whole number, found '1e-400'"), "")
      << All(r);
}

TEST_F(SuiteValidation, MissingPiecesAreNamed) {
  auto r = Load("episodes: 5\n");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r, "missing key 'name'"), "");
  EXPECT_NE(Find(r, "missing or empty 'rows'"), "");
}

TEST_F(SuiteValidation, YamlSyntaxErrorHasLocation) {
  auto r = Load("name: t\nrows: [ {policy: linear\n");
  ASSERT_FALSE(r.suite);
  ASSERT_EQ(r.errors.size(), 1u);
  EXPECT_NE(r.errors[0].Format().find("not valid YAML"), std::string::npos);
  EXPECT_GT(r.errors[0].line, 0);
}

// yaml-cpp reports a '{' or '[' without its closing bracket at the line after it, where it gave
// up ("end of map flow not found" at 5:5); the bracket it means is said with its place.
TEST_F(SuiteValidation, AnUnclosedBracketIsNamedWhereItOpens) {
  auto map = Load(
      "name: t\nepisodes: 2\nrows:  # [not a bracket\n  - {label: a, policy: orca\n"
      "  - {label: 'b}', policy: linear}\n");
  ASSERT_FALSE(map.suite);
  EXPECT_NE(Find(map,
                 "end of map flow not found (the '{' at line 4, column 5 is not closed: end "
                 "it with '}')"),
            "")
      << All(map);
  auto list = Load(
      "name: t\nepisodes: 2\nrobot:\n  sensors: [person, {type: lidar2d}\n"
      "rows:\n  - {label: a, policy: orca}\n");
  ASSERT_FALSE(list.suite);
  EXPECT_NE(Find(list, "(the '[' at line 4, column 12 is not closed: end it with ']')"), "")
      << All(list);
}

// yaml-cpp says "illegal map value" at the next key's ':', a line after the mistake: a key
// without its ':', or a key indented under one whose value is already given.
TEST_F(SuiteValidation, AnIllegalMapValueNamesTheLineBeforeIt) {
  auto no_colon = Load("name: t\nepisodes 2\nrows:\n  - {label: a, policy: orca}\n");
  ASSERT_FALSE(no_colon.suite);
  EXPECT_NE(Find(no_colon,
                 "illegal map value (line 2, 'episodes 2', has no ':' after its key: write "
                 "'key: value')"),
            "")
      << All(no_colon);
  // With a comment after it, yaml-cpp stops at that line itself ("end of map not found").
  auto commented = Load("name: t\nepisodes 2  # a comment\nrows:\n  - {label: a, policy: orca}\n");
  ASSERT_FALSE(commented.suite);
  EXPECT_NE(Find(commented,
                 "end of map not found (line 2, 'episodes 2', has no ':' after its key: write "
                 "'key: value')"),
            "")
      << All(commented);
  auto deeper = Load("name: t\nepisodes: 2\n\n  seed: 3\nrows:\n  - {label: a, policy: orca}\n");
  ASSERT_FALSE(deeper.suite);
  EXPECT_NE(Find(deeper,
                 "illegal map value (line 2, 'episodes: 2', already has its value, and line 4 "
                 "is indented deeper: indent its key as the keys beside it)"),
            "")
      << All(deeper);
}

// The bracket's column as yaml-cpp counts its own: a UTF-8 byte order mark is no column (it
// was said 3 columns to the right), and a UTF-16 file's bytes are not its columns (the '{' at
// column 5 was said at column 10): no hint there rather than a wrong one.
TEST_F(SuiteValidation, AnUnclosedBracketIsPlacedAsYamlPlacesItsErrors) {
  auto bom = Load("\xef\xbb\xbfrows: [{label: a, policy: orca}, {label: b, policy: linear\n");
  ASSERT_FALSE(bom.suite);
  EXPECT_NE(Find(bom, "(the '{' at line 1, column 34 is not closed"), "") << All(bom);
  const std::string text =
      "name: t\nepisodes: 2\nrows:\n  - {label: a, policy: orca\n"
      "  - {label: b, policy: linear}\n";
  std::string utf16 = "\xff\xfe";
  for (const char c : text) utf16 += std::string{c, '\0'};
  auto wide = Load(utf16);
  ASSERT_FALSE(wide.suite);
  const std::string error = Find(wide, "end of map flow not found");
  ASSERT_NE(error, "") << All(wide);
  EXPECT_EQ(error.find("column 10"), std::string::npos) << error;
}

// An apostrophe inside a plain value (rock 'n roll) opens no string: taken for one, it hid
// every bracket after it, and the hint named a '{' that its line closes.
TEST_F(SuiteValidation, AnApostropheInAPlainValueHidesNoBracket) {
  auto r = Load(
      "name: t\nepisodes: 2\nrows:\n  - {label: a, policy: orca, info: {note: rock 'n roll}}\n"
      "  - {label: b, policy: linear\n  - {label: c, policy: linear}\n");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r, "(the '{' at line 5, column 5 is not closed: end it with '}')"), "") << All(r);
  // A quote written twice inside a quoted value ('it''s {') ends nothing.
  auto twice = Load(
      "name: t\nepisodes: 2\nrows:\n  - {label: a, policy: orca, info: {note: 'it''s {'}}\n"
      "  - {label: b, policy: linear\n  - {label: c, policy: linear}\n");
  ASSERT_FALSE(twice.suite);
  EXPECT_NE(Find(twice, "(the '{' at line 5, column 5 is not closed"), "") << All(twice);
}

// A PNG (a floor plan given as the suite) or other binary file was read as YAML: "unknown
// escape character" and a stray byte printed to the terminal.
TEST_F(SuiteValidation, ABinaryFileIsNamedAsSuch) {
  const auto png = dir_.Write("plan.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
  const SuiteLoadResult image = LoadSuite(png, registry_);
  ASSERT_FALSE(image.suite);
  EXPECT_EQ(All(image), png.string() + ": is a PNG image, not a suite file (YAML text)\n");
  const auto zipped = dir_.Write("suite.yaml.gz", std::string("\x1f\x8b\x08\0\0\0\0\0", 8));
  const SuiteLoadResult binary = LoadSuite(zipped, registry_);
  ASSERT_FALSE(binary.suite);
  EXPECT_EQ(All(binary), zipped.string() + ": is binary data, not a suite file (YAML text)\n");
  // UTF-16 text (with or without its byte order mark) holds NUL bytes, and is YAML.
  for (const bool bom : {true, false}) {
    std::string utf16 = bom ? std::string("\xff\xfe", 2) : "";
    for (const char c : std::string(kGood)) utf16 += std::string{c, '\0'};
    const SuiteLoadResult wide = LoadSuite(dir_.Write("utf16.yaml", utf16), registry_);
    EXPECT_TRUE(wide.suite) << All(wide);
  }
}

// The README's `crowdsim-bench run suites/quick.yaml`, typed by a user of the installed package
// outside a source tree: the suite is the data folder's (PREFIX/share/crowdsim-bench/suites),
// and the error said only "suite file does not exist".
TEST_F(SuiteValidation, AMissingRelativeSuiteNamesTheDataFoldersOne) {
  namespace fs = std::filesystem;
  const fs::path before = fs::current_path();
  fs::current_path(dir_.path());
  const SuiteLoadResult r = LoadSuite("suites/quick.yaml", registry_);
  const SuiteLoadResult other = LoadSuite("suites/no_such_suite.yaml", registry_);
  fs::current_path(before);
  ASSERT_FALSE(r.suite);
  const fs::path shipped = DataRoot() / "suites" / "quick.yaml";
  ASSERT_TRUE(fs::exists(shipped)) << shipped;
  EXPECT_EQ(All(r), "suites/quick.yaml: suite file does not exist; did you mean " +
                        shipped.string() + " (the data folder's)?\n");
  // No such file in the data folder either: no suggestion.
  EXPECT_EQ(All(other), "suites/no_such_suite.yaml: suite file does not exist\n");
}

TEST_F(SuiteValidation, WrongKindAndWeightsWithoutParameter) {
  auto r = Load(R"(name: t
world: {source: linear}
rows:
  - {policy: person, weights: results/models/x.pt}
  - {policy: linear, weights: results/models/x.pt}
)");
  ASSERT_FALSE(r.suite);
  const std::string all = All(r);
  EXPECT_NE(Find(r, "world.source: plugin 'linear'"), "") << all;
  EXPECT_NE(Find(r, "is a policy plugin, but a world plugin is needed"), "") << all;
  EXPECT_NE(Find(r, "rows[0].policy: plugin 'person'"), "") << all;
  EXPECT_NE(Find(r, "rows[1].weights: policy 'linear' takes no weights"), "") << all;
}

TEST_F(SuiteValidation, BrokenPluginByPathIsReported) {
  const auto bad = (testing::FixturePluginDir() / "crowdsim_wrong_abi.so").string();
  auto r = Load("name: t\nworld: {source: random_rect}\nrows:\n  - {policy: " + bad + "}\n");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r, "rows[0].policy: plugin '"), "") << All(r);
  EXPECT_NE(Find(r, "ABI version"), "") << All(r);
}

TEST_F(SuiteValidation, EpisodesOfMoreThanAMillionStepsAreATypo) {
  std::string text = kGood;
  text.insert(text.find("world:"), "sim: {time_step: 1e-300}\n");
  const SuiteLoadResult r = Load(text);
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r, "sim.time_step: time_limit / time_step"), "") << All(r);
  EXPECT_NE(Find(r, "more than 1,000,000"), "") << All(r);
}

TEST_F(SuiteValidation, DuplicateLabels) {
  auto r = Load(
      "name: t\nworld: {source: random_rect}\nrows:\n  - {policy: linear}\n  - {policy: linear}\n");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r, "label 'linear' is used by an earlier row"), "") << All(r);
}

// A label or description that is not text (a list, a map) read as "": the label was called
// blank, the description dropped without a word.
TEST_F(SuiteValidation, ALabelOrDescriptionThatIsNotTextIsNamedAsSuch) {
  auto r =
      Load(std::string("description: [a, b]\n") + kGood + "  - {label: [x, y], policy: linear}\n");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r, "suite.yaml:1:14: description: must be a text value, found a list"), "")
      << All(r);
  EXPECT_NE(Find(r, "rows[2].label: must be a text value, found a list"), "") << All(r);
  EXPECT_EQ(Find(r, "must not be empty or blank"), "") << All(r);
  // `label:` with no value is an empty label, as before, not "found nothing".
  auto empty = Load(kGood + std::string("  - {label: , policy: linear}\n"));
  ASSERT_FALSE(empty.suite);
  EXPECT_NE(Find(empty, "rows[2].label: must not be empty or blank"), "") << All(empty);
}

// `columns:` names info keys: an item that is not text became a column without a name, one
// named twice a second copy. A name no row fills stays valid: a suite copied with its own rows
// (quick.yaml's `columns: [model]`, rows without info) shows an empty column, not an error.
TEST_F(SuiteValidation, ColumnsNamedTwiceOrNotTextAreErrors) {
  const std::string rows =
      "rows:\n  - {label: a, policy: linear, info: {model: A}}\n"
      "  - {label: b, policy: linear, info: {model: B, seed: 1}}\n";
  const std::string head =
      "name: t\nepisodes: 3\nworld: {source: random_rect, obstacles: 1, split: test}\n";
  auto good = Load(head + "columns: [seed, model, note]\n" + rows);
  ASSERT_TRUE(good.suite) << All(good);
  EXPECT_EQ(good.suite->info_columns, (std::vector<std::string>{"seed", "model", "note"}));
  auto r = Load(head + "columns: [model, {a: b}, seed, seed]\n" + rows);
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r, "suite.yaml:4:18: columns[1]: must be a text value, found a map"), "")
      << All(r);
  EXPECT_NE(Find(r, "suite.yaml:4:32: columns[3]: 'seed' is named twice"), "") << All(r);
  EXPECT_EQ(r.errors.size(), 2u) << All(r);
}

/// kGood with its last row in block style, so keys can be added to it.
std::string GoodWithOpenLastRow() {
  std::string yaml = kGood;
  const std::string flow = "  - {label: b, policy: linear, params: {speed_factor: 0.5}}\n";
  yaml.replace(yaml.find(flow), flow.size(),
               "  - label: b\n    policy: linear\n    params: {speed_factor: 0.5}\n");
  return yaml;
}

TEST_F(SuiteValidation, ConfigHashCoversTheBytesOfAUsersPluginFile) {
  // A plugin given by path is the user's: rebuilding it is another configuration (its stored
  // episodes are not resumed as the new one's). The harness's own are covered by the commit.
  namespace fs = std::filesystem;
  const fs::path own = testing::PluginDir() / "crowdsim_linear.so";
  fs::create_directories(dir_.path() / "v1");
  fs::create_directories(dir_.path() / "v2");
  fs::create_directories(dir_.path() / "same");
  fs::copy_file(own, dir_.path() / "v1" / "crowdsim_linear.so");
  fs::copy_file(own, dir_.path() / "v2" / "crowdsim_linear.so");
  fs::copy_file(own, dir_.path() / "same" / "crowdsim_linear.so");
  std::ofstream(dir_.path() / "v2" / "crowdsim_linear.so", std::ios::app) << "rebuilt";
  auto by_path = [&](const std::string& folder) {
    std::string yaml = kGood;
    const std::string row = "{label: b, policy: linear,";
    yaml.replace(
        yaml.find(row), row.size(),
        "{label: b, policy: " + (dir_.path() / folder / "crowdsim_linear.so").string() + ",");
    PluginRegistry registry({testing::PluginDir()});
    SuiteLoadResult r = LoadSuite(dir_.Write("suite_" + folder + ".yaml", yaml), registry);
    EXPECT_TRUE(r.suite) << All(r);
    return r.suite ? r.suite->rows[1].ConfigHash() : std::string();
  };
  const std::string v1 = by_path("v1"), v2 = by_path("v2"), same = by_path("same");
  EXPECT_NE(v1, v2);
  EXPECT_EQ(v1, same);  // the bytes count, not the folder
  auto own_row = Load(kGood);
  ASSERT_TRUE(own_row.suite) << All(own_row);
  EXPECT_EQ(own_row.suite->rows[1].canonical.find("plugin:"), std::string::npos);
  EXPECT_NE(own_row.suite->rows[1].ConfigHash(), v1);
}

TEST_F(SuiteValidation, ARelativePluginPathIsTheSuitesFolderWhenNotTheWorkingFolders) {
  // As for the files parameters name: a suite and its plugins move together.
  namespace fs = std::filesystem;
  fs::create_directories(dir_.path() / "mine");
  fs::copy_file(testing::PluginDir() / "crowdsim_person.so",
                dir_.path() / "mine" / "crowdsim_person.so");
  std::string yaml = kGood;
  yaml.replace(yaml.find("sensors: [person,"), 17, "sensors: [mine/crowdsim_person.so,");
  ASSERT_FALSE(fs::exists("mine/crowdsim_person.so"));  // not from the working folder
  auto r = Load(yaml);
  ASSERT_TRUE(r.suite) << All(r);
  EXPECT_EQ(fs::weakly_canonical(r.suite->rows[0].sensors[0].loaded->path),
            fs::weakly_canonical(dir_.path() / "mine" / "crowdsim_person.so"));
  // The table names the sensor by its plugin name, not by the path it was given as.
  std::vector<TableRow> rows(1);
  rows[0].spec = &r.suite->rows[0];
  EXPECT_NE(FormatTableMarkdown(*r.suite, rows).find("| person+lidar2d |"), std::string::npos)
      << FormatTableMarkdown(*r.suite, rows);
  yaml.replace(yaml.find("mine/crowdsim_person.so"), 23, "gone/crowdsim_person.so");
  auto missing = Load(yaml);
  EXPECT_NE(Find(missing, "looked from the working folder and from the suite's folder"), "")
      << All(missing);
}

TEST_F(SuiteValidation, AMissingPluginPathOfASuiteInTheWorkingFolderSaysWhereItLooked) {
  // `run suite.yaml` from the suite's folder: its folder is the working folder, not "".
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(dir_.path());
  std::string yaml = kGood;
  yaml.replace(yaml.find("sensors: [person,"), 17, "sensors: [gone/crowdsim_person.so,");
  dir_.Write("suite.yaml", yaml);
  const auto r = LoadSuite("suite.yaml", registry_);
  std::filesystem::current_path(before);
  const std::string error = Find(r, "gone/crowdsim_person.so' does not exist");
  EXPECT_NE(error.find("(looked from the working folder, which holds the suite)"),
            std::string::npos)
      << All(r);
  EXPECT_EQ(error.find("suite's folder, )"), std::string::npos) << error;
}

TEST_F(SuiteValidation, AnUnknownPluginFarFromEveryNameSaysWhereItLookedAndHowToAddAFolder) {
  // A plugin you built whose folder is not on CROWDSIM_PLUGIN_PATH: no typo to point at.
  std::string yaml = kGood;
  yaml.replace(yaml.find("policy: linear, params"), 14, "policy: my_own_walker");
  const auto r = Load(yaml);
  const std::string error = Find(r, "unknown policy plugin 'my_own_walker'");
  EXPECT_NE(error.find("looked for crowdsim_my_own_walker.so in " + testing::PluginDir().string()),
            std::string::npos)
      << All(r);
  EXPECT_NE(error.find("on CROWDSIM_PLUGIN_PATH"), std::string::npos) << error;
  // A typo of a plugin found is told that one alone.
  yaml.replace(yaml.find("my_own_walker"), 13, "lineer");
  const std::string typo = Find(Load(yaml), "did you mean 'linear'");
  ASSERT_NE(typo, "");
  EXPECT_EQ(typo.find("CROWDSIM_PLUGIN_PATH"), std::string::npos) << typo;
}

TEST_F(SuiteValidation, AnUnknownPluginNamesTheFileThatCallsItselfSo) {
  // crowdsim_walker.so whose descriptor says 'linear': `policy: linear` finds no
  // crowdsim_linear.so, and the message points at the misnamed file.
  namespace fs = std::filesystem;
  fs::create_directories(dir_.path() / "plugins");
  fs::copy_file(testing::PluginDir() / "crowdsim_linear.so",
                dir_.path() / "plugins" / "crowdsim_walker.so");
  PluginRegistry only_walker({dir_.path() / "plugins"});
  const auto r = LoadSuite(dir_.Write("walker.yaml", kGood), only_walker);
  EXPECT_NE(Find(r, "unknown policy plugin 'linear'"), "") << All(r);
  EXPECT_NE(Find(r, "is named 'walker' but its descriptor calls it 'linear'"), "") << All(r);
}

TEST_F(SuiteValidation, APluginIsTheHarnesssOwnByTheFolderItIsFoundIn) {
  // Not by where its file links to: an installed copy whose plugin files are symlinks into a
  // package store keeps the committed config hashes; a link of yours to a built-in plugin is
  // yours.
  namespace fs = std::filesystem;
  fs::create_directories(dir_.path() / "linked");
  fs::create_symlink(testing::PluginDir() / "crowdsim_linear.so",
                     dir_.path() / "linked" / "crowdsim_linear.so");
  PluginRegistry registry({testing::PluginDir()});
  const LoadedPlugin& linked =
      registry.Load((dir_.path() / "linked" / "crowdsim_linear.so").string(), PluginKind::kPolicy);
  EXPECT_FALSE(PluginRegistry::IsHarnessPlugin(linked));
  EXPECT_TRUE(PluginRegistry::IsHarnessPlugin(registry.Load("person", PluginKind::kSensor)));
  // In the harness's folder, only a plugin this build ships: one of yours copied there (the
  // SDK's CROWDSIM_PLUGIN_INSTALL_DIR) was taken for the harness's, so a rebuild of it resumed
  // the old build's episodes.
  PluginDescriptor yours = *registry.Load("linear", PluginKind::kPolicy).descriptor;
  yours.name = "walker";
  LoadedPlugin copied;
  copied.path = fs::weakly_canonical(testing::PluginDir()) / "crowdsim_walker.so";
  copied.folder = fs::weakly_canonical(testing::PluginDir());
  copied.descriptor = &yours;
  EXPECT_FALSE(PluginRegistry::IsHarnessPlugin(copied));
  yours.name = "linear";  // a shipped name, in a file not named for it: yours too
  EXPECT_FALSE(PluginRegistry::IsHarnessPlugin(copied));
  copied.path = copied.folder / "crowdsim_linear.so";
  EXPECT_TRUE(PluginRegistry::IsHarnessPlugin(copied));
}

TEST_F(SuiteValidation, ReferencesAndSummariesLoadWithoutChangingTheConfigHash) {
  auto plain = Load(kGood);
  ASSERT_TRUE(plain.suite) << All(plain);
  auto r = Load(GoodWithOpenLastRow() +
                "    reference: {success: 0.67, nav_time: 12.9, source: \"Table 1\"}\n"
                "summaries:\n  - {label: avg, rows: [a, b], info: {model: both}, reference: "
                "{success: 0.7}}\n");
  ASSERT_TRUE(r.suite) << All(r);
  ASSERT_TRUE(r.suite->rows[1].reference.has_value());
  EXPECT_DOUBLE_EQ(*r.suite->rows[1].reference->success, 0.67);
  EXPECT_DOUBLE_EQ(*r.suite->rows[1].reference->nav_time, 12.9);
  EXPECT_FALSE(r.suite->rows[1].reference->collision.has_value());
  EXPECT_EQ(r.suite->rows[1].reference->source, "Table 1");
  EXPECT_FALSE(r.suite->rows[0].reference.has_value());
  ASSERT_EQ(r.suite->summaries.size(), 1u);
  EXPECT_EQ(r.suite->summaries[0].rows, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(r.suite->info_columns, std::vector<std::string>{"model"});
  // Published values are presentation: stored results stay valid when they are added.
  EXPECT_EQ(r.suite->ConfigHash(), plain.suite->ConfigHash());
}

TEST_F(SuiteValidation, BadReferencesAndSummariesAreNamed) {
  auto r = Load(GoodWithOpenLastRow() + "    reference: {success: 67, colision: 0.1}\n" +
                "summaries:\n"
                "  - {label: avg, rows: [a, c]}\n"
                "  - {label: a, rows: []}\n"
                "  - {rows: [b, b]}\n"
                "  - {label: x, rows: [a], reference: {source: only}}\n"
                "  - {label: y, rows: [a, {b: 1}]}\n");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r, "rows[1].reference.success"), "") << All(r);
  EXPECT_NE(Find(r, "unknown key 'colision'"), "") << All(r);
  EXPECT_NE(Find(r, "summaries[0].rows[1]: no row is labelled 'c' (valid: a, b)"), "") << All(r);
  EXPECT_NE(Find(r, "summaries[1].label: label 'a' is already"), "") << All(r);
  EXPECT_NE(Find(r, "summaries[1].rows: must be a non-empty list"), "") << All(r);
  EXPECT_NE(Find(r, "summaries[2]: missing key 'label'"), "") << All(r);
  EXPECT_NE(Find(r, "summaries[2].rows[1]: row 'b' is named twice"), "") << All(r);
  EXPECT_NE(Find(r, "summaries[3].reference: gives no value"), "") << All(r);
  // A member that is not a label was read as "" and called "no row is labelled ''".
  EXPECT_NE(Find(r, "summaries[4].rows[1]: must be a text value, found a map"), "") << All(r);
  EXPECT_EQ(Find(r, "no row is labelled ''"), "") << All(r);
}

TEST_F(SuiteValidation, DuplicateKeysAreErrorsNotSilentChoices) {
  auto r = Load(
      "name: t\nepisodes: 3\nepisodes: 4\n"
      "world: {source: random_rect, obstacles: 1, split: test}\n"
      "rows:\n  - label: a\n    policy: linear\n    policy: orca\n");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r, "suite.yaml:3:1: key 'episodes' is given twice in this map (first at line 2)"),
            "")
      << All(r);
  EXPECT_NE(Find(r, "suite.yaml:8:5: key 'policy' is given twice in this map (first at line 7)"),
            "")
      << All(r);
}

// Found while writing the fuzz targets (tests/fuzz): an alias of a map or list inside itself made
// the duplicate-key walk recurse until the stack overflowed (every reader: suites, world files,
// training files); aliases of aliases could stand for billions of values.
TEST_F(SuiteValidation, SelfContainingAndExplodingAliasesAreErrors) {
  for (const char* text :
       {"name: &a [*a]\n", "&a {x: *a}\n", "rows:\n  - &r {policy: linear, humans: [*r]}\n"}) {
    auto r = Load(text);
    ASSERT_FALSE(r.suite) << text;
    EXPECT_NE(Find(r, "contains an alias (*name) of itself, so it never ends"), "")
        << text << All(r);
  }
  // Eight levels of ten aliases each: 10^8 values in nine lines.
  std::ostringstream bomb;
  bomb << "a0: &a0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i <= 7; ++i) {
    bomb << "a" << i << ": &a" << i << " [*a" << i - 1;
    for (int k = 1; k < 10; ++k) bomb << ", *a" << i - 1;
    bomb << "]\n";
  }
  auto r = Load(bomb.str() + "name: t\n");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r, "more than 1000000 values once its aliases (*name) are expanded"), "")
      << All(r);
  // Over a million plain values, no alias: told to split the file, not to write fewer aliases.
  std::string big = "name: t\nvalues: [";
  for (int i = 0; i < 1'000'001; ++i) big += i ? ",0" : "0";
  auto plain = Load(big + "]\n");
  ASSERT_FALSE(plain.suite);
  EXPECT_NE(Find(plain,
                 "more than 1000000 values, ten times the largest committed world set; "
                 "split it into several files"),
            "")
      << All(plain).substr(0, 400);
  // An alias that is only a shared value is fine.
  auto shared = Load(std::string("defaults: &d {count: 2, policy: linear}\n") + kGood);
  EXPECT_NE(Find(shared, "unknown key 'defaults'"), "") << All(shared);
  EXPECT_EQ(Find(shared, "alias"), "") << All(shared);
}

// yaml-cpp refuses deep nesting as a "bad file"; a huge file took gigabytes before bad_alloc.
TEST_F(SuiteValidation, DeepNestingAndHugeFilesAreNamedAsSuch) {
  auto deep = Load("name: t\nrows: " + std::string(3000, '[') + std::string(3000, ']') + "\n");
  ASSERT_FALSE(deep.suite);
  EXPECT_NE(Find(deep, "maps and lists are nested more than"), "") << All(deep).substr(0, 400);
  EXPECT_EQ(Find(deep, "bad file"), "") << All(deep).substr(0, 400);
  // 17 MB of comments: refused by its size before any parsing.
  std::string huge = "name: t\n";
  const std::string comment = "# " + std::string(1022, 'x') + "\n";
  while (huge.size() <= (17u << 20)) huge += comment;
  auto big = Load(huge);
  ASSERT_FALSE(big.suite);
  EXPECT_NE(Find(big, "is 17 MB; a suite file may be at most 16 MB"), "") << All(big);
}

// Found by the suite_reader fuzz target (tests/fuzz): a `robot:` map without `sensors` threw
// yaml-cpp's InvalidNode out of LoadSuite (the CLI ended with "terminate called").
TEST_F(SuiteValidation, RobotMapWithoutSensorsIsAnErrorNotACrash) {
  auto r = Load(
      "name: t\nepisodes: 3\nworld: {source: random_rect, obstacles: 1, split: test}\n"
      "robot: {sensor: [person]}\nrows:\n  - {label: a, policy: linear}\n");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r,
                 "suite.yaml:4:9: robot.sensor: unknown key 'sensor' (valid keys: sensors, "
                 "kinematics); did "
                 "you mean 'sensors'?"),
            "")
      << All(r);
  auto empty = Load(
      "name: t\nepisodes: 3\nworld: {source: random_rect, obstacles: 1, split: test}\n"
      "robot: {}\nrows:\n  - {label: a, policy: linear}\n");
  EXPECT_TRUE(empty.suite) << All(empty);
}

// A misspelled row key is told every key a row may have: `sweep` too (it is expanded into rows
// before they are read, and the list left it out, so `swep:` was never told of it).
TEST_F(SuiteValidation, AMisspelledRowKeyListsEveryRowKeySweepToo) {
  auto r = Load(
      "name: t\nepisodes: 3\nworld: {source: random_rect, obstacles: 1, split: test}\n"
      "rows:\n  - {label: a, policy: linear, swep: {humans.count: [1, 2]}}\n");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r,
                 "suite.yaml:5:32: rows[0].swep: unknown key 'swep' (valid keys: label, policy, "
                 "params, weights, sensors, kinematics, world, humans, sweep, info, reference)"),
            "")
      << All(r);
  // The other keys of that list are a row's (weights: WrongKindAndWeightsWithoutParameter): a
  // row giving them all loads.
  auto all = Load(
      "name: t\nepisodes: 3\nworld: {source: random_rect, obstacles: 1, split: test}\n"
      "rows:\n  - label: a\n    policy: linear\n    params: {speed_factor: 0.5}\n"
      "    sensors: [person]\n    world: {source: random_rect, obstacles: 3, split: test}\n"
      "    humans: {count: 2}\n    sweep: {humans.count: [1, 2]}\n    info: {m: x}\n"
      "    reference: {success: 0.5}\n");
  EXPECT_TRUE(all.suite) << All(all);
}

// Suites and training files share the row reader; a count range is a training file's (drawn
// per episode), and a suite row that gives one is told what to write instead.
TEST_F(SuiteValidation, AHumanCountRangeIsForTrainingFiles) {
  auto r = Load(
      "name: t\nepisodes: 3\nworld: {source: random_rect, obstacles: 1, split: test}\n"
      "rows:\n  - {label: a, policy: linear, humans: {count: [2, 4]}}\n");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(Find(r,
                 "suite.yaml:5:48: rows[0].humans.count: a range of counts is for training files "
                 "(drawn per episode); a suite row runs one count: give one number, or "
                 "`sweep: {humans.count: [...]}` for a row per count"),
            "")
      << All(r);
  EXPECT_EQ(r.errors.size(), 1u) << All(r);
}

// Defaults that name plugins are data (suites/schema/defaults.yaml under the data root): a
// file that leaves humans.policy out gets the default there, and a missing defaults file is
// named with the fix.
TEST_F(SuiteValidation, PluginDefaultsComeFromTheSchemaDefaultsFile) {
  const std::string suite =
      "name: t\nepisodes: 3\nworld: {source: random_rect, obstacles: 1, split: test}\n"
      "rows:\n  - {label: a, policy: linear}\n"
      "  - {label: b, policy: linear, humans: {count: 0}}\n";
  auto r = Load(suite);
  ASSERT_TRUE(r.suite) << All(r);
  EXPECT_EQ(r.suite->rows[0].humans.policy.plugin, "orca");
  EXPECT_EQ(r.suite->rows[1].humans.policy.plugin, "linear");

  TempDir data;
  std::filesystem::create_directories(data.path() / "suites/schema");
  data.Write("suites/schema/defaults.yaml",
             "humans: {policy: linear, policy_without_humans: linear}\n"
             "training: {il_policy: orca}\n");
  ::setenv("CROWDSIM_DATA_DIR", data.path().c_str(), 1);
  auto moved = Load(suite);
  ASSERT_TRUE(moved.suite) << All(moved);
  EXPECT_EQ(moved.suite->rows[0].humans.policy.plugin, "linear");
  std::filesystem::remove(data.path() / "suites/schema/defaults.yaml");
  auto none = Load(suite);
  ::unsetenv("CROWDSIM_DATA_DIR");
  ASSERT_FALSE(none.suite);
  EXPECT_NE(
      Find(none, (data.path() / "suites/schema/defaults.yaml").string() +
                     ": schema defaults file does not exist (every suite and training file "
                     "needs it: restore suites/schema/defaults.yaml from the source tree, or set "
                     "CROWDSIM_DATA_DIR to the project's root folder)"),
      "")
      << All(none);
}

// A label of bytes that are not UTF-8 (a file saved as Latin-1) is refused before any run:
// it would write malformed SVG and HTML. Valid multi-byte labels pass.
TEST_F(SuiteValidation, ALabelMustBeUtf8) {
  const std::string head =
      "name: u\nepisodes: 3\nworld: {source: random_rect, obstacles: 1, split: test}\nrows:\n";
  for (const std::string bad : {"caf\xe9", "\xff\xfe", "\xc0\xaf", "\xed\xa0\x80", "a\xe2\x82"}) {
    auto r = Load(head + "  - {label: \"" + bad + "\", policy: linear}\n");
    ASSERT_FALSE(r.suite) << bad;
    EXPECT_NE(Find(r, "rows[0].label: is not valid UTF-8 text"), "") << All(r);
  }
  auto good = Load(head + "  - {label: \"café ∆ 🚶\", policy: linear}\n");
  EXPECT_TRUE(good.suite) << All(good);
}

TEST_F(SuiteValidation, FolderNamesAndLabelsThatWouldMisplaceResults) {
  auto dotdot = Load(
      "name: ..\nepisodes: 3\nworld: {source: random_rect, obstacles: 1, split: test}\n"
      "rows:\n  - {label: \"a\\nb\", policy: linear}\n  - {label: \"a\\tb\", policy: linear}\n");
  ASSERT_FALSE(dotdot.suite);
  EXPECT_NE(Find(dotdot, "name: '..' must not start with '.'"), "") << All(dotdot);
  EXPECT_NE(Find(dotdot, "rows[0].label: must not contain control characters"), "") << All(dotdot);
  EXPECT_NE(Find(dotdot, "rows[1].label: must not contain control characters"), "") << All(dotdot);
  // A blank label passed; two sensors of one plugin too, the second never read.
  auto blank = Load(
      "name: b\nepisodes: 3\nworld: {source: random_rect, obstacles: 1, split: test}\n"
      "robot: {sensors: [person, {type: person, max_range: 3}]}\n"
      "rows:\n  - {label: \"  \", policy: linear}\n");
  ASSERT_FALSE(blank.suite);
  EXPECT_NE(Find(blank, "rows[0].label: must not be empty or blank"), "") << All(blank);
  EXPECT_NE(Find(blank,
                 "robot.sensors[1].type: a second 'person' sensor: readings are named by "
                 "their sensor, so only the first would ever be read; keep one"),
            "")
      << All(blank);
  // A folder given as the suite file.
  const SuiteLoadResult folder = LoadSuite(dir_.path(), registry_);
  ASSERT_FALSE(folder.suite);
  EXPECT_NE(Find(folder, "is a folder; give the suite file (a .yaml file) in it"), "")
      << All(folder);
  // A pipe (`run <(generate)`) and standard input: named as such, not read (a pipe's text went
  // to the first of the several reads, and the suite seemed empty).
  const auto fifo = dir_.path() / "generated.yaml";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const SuiteLoadResult piped = LoadSuite(fifo, registry_);
  ASSERT_FALSE(piped.suite);
  EXPECT_NE(Find(piped,
                 "is not a regular file (a pipe or a device); a suite file is read more than "
                 "once: write it to a file and give that file"),
            "")
      << All(piped);
  const SuiteLoadResult stdin_suite = LoadSuite("-", registry_);
  ASSERT_FALSE(stdin_suite.suite);
  EXPECT_NE(Find(stdin_suite, "standard input cannot be read; a suite file is read more than once"),
            "")
      << All(stdin_suite);
  // A tab in an indentation, where yaml-cpp reports only what it broke.
  const auto tabbed = dir_.path() / "tabbed.yaml";
  std::ofstream(tabbed) << "name: t\nepisodes: 2\nworld: {source: crowdnav}\nrows:\n"
                           "\t- {label: a, policy: linear}\n";
  const SuiteLoadResult tab = LoadSuite(tabbed, registry_);
  ASSERT_FALSE(tab.suite);
  EXPECT_NE(Find(tab, "line 5 is indented with a tab: YAML indents with spaces only"), "")
      << All(tab);
  // The output folder of a run: the suite it ran, as its manifest names it.
  const auto run_dir = dir_.path() / "a_run";
  std::filesystem::create_directories(run_dir);
  std::ofstream(run_dir / "manifest.json") << R"({"suite_file": "suites/quick.yaml"})";
  const SuiteLoadResult run_folder = LoadSuite(run_dir, registry_);
  ASSERT_FALSE(run_folder.suite);
  EXPECT_NE(Find(run_folder,
                 "is the output folder of a run; give the suite file it ran, which "
                 "its manifest.json names: suites/quick.yaml"),
            "")
      << All(run_folder);
}

// A mistyped key gets the one valid key a few edits away; a key far from every valid one (a
// training key at the top of a suite) only the list.
TEST_F(SuiteValidation, AMistypedKeyIsToldTheNearestValidOne) {
  auto r = Load(std::string("episode: 4\nrl_episodes: 2\n") + kGood);
  ASSERT_FALSE(r.suite);
  const std::string near = Find(r, "episode: unknown key 'episode' (valid keys: ");
  EXPECT_TRUE(near.ends_with("; did you mean 'episodes'?")) << All(r);
  const std::string far = Find(r, "rl_episodes: unknown key 'rl_episodes' (valid keys: ");
  EXPECT_NE(far, "") << All(r);
  EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
}

}  // namespace
}  // namespace crowdsim
