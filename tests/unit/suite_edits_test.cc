// One suite file, many experiments: `--set key.path=value` overrides and `sweep:` rows.
#include <gtest/gtest.h>

#include <algorithm>

#include "crowdsim/bench/suite.h"
#include "crowdsim/bench/training/train_spec.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim {
namespace {

class SuiteEdits : public ::testing::Test {
 protected:
  SuiteLoadResult Load(const std::string& yaml, const std::vector<std::string>& overrides = {}) {
    file_ = dir_.Write("suite.yaml", yaml);
    return LoadSuite(file_, registry_, overrides);
  }
  static std::string All(const SuiteLoadResult& r) {
    std::string s;
    for (const auto& e : r.errors) s += e.Format() + "\n";
    return s;
  }

  testing::TempDir dir_;
  std::filesystem::path file_;
  PluginRegistry registry_{{testing::PluginDir()}};
};

constexpr const char* kSuite = R"(name: t
episodes: 3
world: {source: random_rect, obstacles: 1, split: test}
humans: {count: 5, policy: orca}
robot:
  sensors: [person, {type: lidar2d, beams: 45}]
columns: [model]
rows:
  - label: orca
    policy: orca
    info: {model: ORCA}
    sweep: {humans.count: [2, 8], world.obstacles: [1, 3], params.safety_space: [0.0, 0.1, 0.2]}
  - {label: linear, policy: linear}
)";

TEST_F(SuiteEdits, SweepExpandsARowIntoEveryCombination) {
  const auto r = Load(kSuite);
  ASSERT_TRUE(r.suite) << All(r);
  const auto& rows = r.suite->rows;
  ASSERT_EQ(rows.size(), 2u * 2u * 3u + 1u);
  // The first key varies slowest; labels and info columns name the values.
  EXPECT_EQ(rows[0].label, "orca/humans.count=2/world.obstacles=1/params.safety_space=0.0");
  EXPECT_EQ(rows[1].label, "orca/humans.count=2/world.obstacles=1/params.safety_space=0.1");
  EXPECT_EQ(rows[3].label, "orca/humans.count=2/world.obstacles=3/params.safety_space=0.0");
  EXPECT_EQ(rows[11].label, "orca/humans.count=8/world.obstacles=3/params.safety_space=0.2");
  EXPECT_EQ(rows[12].label, "linear");
  EXPECT_EQ(rows[11].humans.count, 8);
  EXPECT_EQ(rows[11].world.params.GetInt("obstacles"), 3);
  EXPECT_DOUBLE_EQ(rows[11].policy.params.GetDouble("safety_space"), 0.2);
  EXPECT_EQ(rows[0].world.params.GetInt("obstacles"), 1);
  // Each row still has the suite's sensors and its own info besides the swept values.
  EXPECT_EQ(rows[11].sensors.size(), 2u);
  EXPECT_EQ(r.suite->info_columns,
            (std::vector<std::string>{"model", "humans.count", "world.obstacles",
                                      "params.safety_space"}));
  EXPECT_EQ(rows[4].info.front(), (std::pair<std::string, std::string>{"model", "ORCA"}));
  // Other rows keep the suite's settings: nothing was changed in place.
  EXPECT_EQ(rows[12].humans.count, 5);
  EXPECT_EQ(rows[12].world.params.GetInt("obstacles"), 1);
}

TEST_F(SuiteEdits, ErrorsInASweptValuePointAtThatValue) {
  std::string yaml = kSuite;
  yaml.replace(yaml.find("[0.0, 0.1, 0.2]"), 15, "[0.0, 7.5]");
  const auto r = Load(yaml);
  ASSERT_FALSE(r.suite);
  // Once, at the value, under the sweep entry that gave it (it named rows[1], an expanded row
  // the file does not have).
  EXPECT_NE(
      All(r).find("suite.yaml:12:87: rows[0].sweep.params.safety_space: value 7.5 is out of range"),
      std::string::npos)
      << All(r);
  EXPECT_EQ(r.errors.size(), 1u) << All(r);
  const auto bad = Load(std::string(kSuite).replace(std::string(kSuite).find("[2, 8]"), 6, "[]"));
  ASSERT_FALSE(bad.suite);
  EXPECT_NE(All(bad).find("rows[0].sweep.humans.count: must be a non-empty list"),
            std::string::npos)
      << All(bad);
}

TEST_F(SuiteEdits, AMisspelledSweptKeyIsOneErrorAtItsSweepEntry) {
  // It was one error per expanded row, each naming a row the file does not have, without a
  // line; and a suite-level error copied into each swept row was repeated as often.
  std::string yaml = kSuite;
  yaml.replace(yaml.find("world.obstacles: [1, 3]"), 23, "world.obstacle: [1, 3]");
  yaml.replace(yaml.find("split: test"), 11, "split: tset");
  const auto r = Load(yaml);
  ASSERT_FALSE(r.suite);
  EXPECT_EQ(r.errors.size(), 2u) << All(r);
  EXPECT_NE(All(r).find("suite.yaml:12:35: rows[0].sweep.world.obstacle: unknown parameter "
                        "'obstacle' for world plugin 'random_rect'"),
            std::string::npos)
      << All(r);
  EXPECT_NE(All(r).find("suite.yaml:3:51: "), std::string::npos) << All(r);  // split, once
}

TEST_F(SuiteEdits, AKeyThatASetMadeOnItsWayIsBlamedOnTheSet) {
  // rows[linear].param.speed_factor: 'param' is new, so it has no line in the file.
  const auto r = Load(kSuite, {"rows[linear].param.speed_factor=0.5"});
  ASSERT_FALSE(r.suite);
  EXPECT_NE(All(r).find("--set rows[linear].param.speed_factor=0.5: rows[12].param: unknown key"),
            std::string::npos)
      << All(r);
  // Each such error is blamed on the --set whose path it lies on, not on another one that
  // only shares a key name.
  const auto two = Load(kSuite, {"rows[linear].param.speed_factor=0.5", "humans.params.param=1"});
  ASSERT_FALSE(two.suite);
  EXPECT_NE(All(two).find("--set rows[linear].param.speed_factor=0.5: rows[12].param: unknown key"),
            std::string::npos)
      << All(two);
  EXPECT_EQ(All(two).find("--set humans.params.param=1: rows[12].param"), std::string::npos)
      << All(two);
}

TEST_F(SuiteEdits, ASetIntoASweptRowIsOneErrorAndAnIndexTooLongIsNoItem) {
  // The row the sweep makes 12 of: one error, named by the --set (it was one per expanded row,
  // named rows[0] to rows[11]); an index beyond any number: no such item (std::stoul threw).
  const auto r = Load(kSuite, {"rows[0].params.bogus=1"});
  ASSERT_FALSE(r.suite);
  EXPECT_EQ(r.errors.size(), 1u) << All(r);
  EXPECT_NE(All(r).find("--set rows[0].params.bogus=1: rows[0].params.bogus: unknown parameter"),
            std::string::npos)
      << All(r);
  const auto huge = Load(kSuite, {"rows[99999999999999999999999].y=1"});
  ASSERT_FALSE(huge.suite);
  EXPECT_NE(All(huge).find("has no item [99999999999999999999999]"), std::string::npos)
      << All(huge);
}

TEST_F(SuiteEdits, ASetOfASweptKeyAndSweptKeysInsideEachOtherAreErrors) {
  // The sweep replaced the --set's value in every row, yet the manifest listed the override.
  for (const std::string set : {"rows[orca].params.safety_space=0.3", "rows[0].humans.count=7",
                                "rows[orca].params={safety_space: 0.3}"}) {
    const auto r = Load(kSuite, {set});
    ASSERT_FALSE(r.suite) << set;
    EXPECT_NE(All(r).find("--set " + set + ": rows[0] sweeps '"), std::string::npos) << All(r);
    EXPECT_NE(All(r).find("which replaces this value in every row it makes"), std::string::npos)
        << All(r);
  }
  EXPECT_TRUE(Load(kSuite, {"rows[orca].params.time_horizon=4"}).suite);  // not swept: fine
  EXPECT_TRUE(Load(kSuite, {"rows[linear].humans.count=7"}).suite);       // another row
  // Two axes where one holds the other: the outer one replaced the inner in every row, while
  // labels and info columns named the inner one's values.
  std::string yaml = kSuite;
  yaml.replace(yaml.find("world.obstacles: [1, 3]"), 23,
               "world.obstacles: [1, 3], world: [{source: random_rect}]");
  const auto r = Load(yaml);
  ASSERT_FALSE(r.suite);
  EXPECT_NE(All(r).find("suite.yaml:12:35: rows[0].sweep.world.obstacles: lies inside the swept "
                        "key 'world', which replaces it in every row: sweep one of the two"),
            std::string::npos)
      << All(r);
}

TEST_F(SuiteEdits, ALabelTwoSweepsBothMakeIsAnErrorAtTheSecondSweep) {
  // It had no line: the label is written by the sweep, not by the file.
  const auto r = Load(R"(name: t
episodes: 3
world: {source: random_rect, obstacles: 1, split: test}
rows:
  - {label: a, policy: linear, sweep: {humans.count: [1, 2]}}
  - {label: a, policy: orca, sweep: {humans.count: [2, 3]}}
)");
  ASSERT_FALSE(r.suite);
  EXPECT_NE(All(r).find("suite.yaml:6:38: rows[1].label: label 'a/humans.count=2' is used by an "
                        "earlier row"),
            std::string::npos)
      << All(r);
}

TEST_F(SuiteEdits, SetOverridesKeysAndRowsByName) {
  const auto base = Load(kSuite);
  ASSERT_TRUE(base.suite) << All(base);
  const auto r =
      Load(kSuite, {"humans.count=7", "rows[linear].params.speed_factor=0.5",
                    "robot.sensors[lidar2d].beams=9", "sim.time_limit=30", "episodes=2"});
  ASSERT_TRUE(r.suite) << All(r);
  const Suite& s = *r.suite;
  EXPECT_EQ(s.episodes, 2);
  EXPECT_DOUBLE_EQ(s.sim.time_limit, 30.0);
  EXPECT_EQ(s.rows[12].humans.count, 7);
  EXPECT_EQ(s.rows[0].humans.count, 2);  // the sweep's own value wins in its rows
  EXPECT_DOUBLE_EQ(s.rows[12].policy.params.GetDouble("speed_factor"), 0.5);
  EXPECT_EQ(s.rows[12].sensors[1].params.GetInt("beams"), 9);
  EXPECT_EQ(s.overrides.size(), 5u);
  EXPECT_NE(s.ConfigHash(), base.suite->ConfigHash());
  // The same change written into the file is the same configuration.
  std::string edited = kSuite;
  edited.replace(edited.find("beams: 45"), 9, "beams: 9");
  edited.replace(edited.find("count: 5"), 8, "count: 7");
  edited.replace(edited.find("episodes: 3"), 11, "episodes: 2\nsim: {time_limit: 30}");
  edited.replace(edited.find("{label: linear, policy: linear}"), 31,
                 "{label: linear, policy: linear, params: {speed_factor: 0.5}}");
  const auto same = Load(edited);
  ASSERT_TRUE(same.suite) << All(same);
  EXPECT_EQ(same.suite->ConfigHash(), s.ConfigHash());
}

// A sensor listed by its name alone takes --set keys as its map form {type: NAME, KEY: VALUE}
// ("'robot.sensors[0]' is not a map" before), the same configuration as writing that form.
TEST_F(SuiteEdits, SetReachesASensorListedByName) {
  const std::string suite = R"(name: t
episodes: 3
world: {source: random_rect, obstacles: 1, split: test}
humans: {count: 2, policy: linear}
robot:
  sensors: [lidar2d, person]
rows:
  - {label: a, policy: linear}
)";
  const auto r = Load(suite, {"robot.sensors[lidar2d].beams=9"});
  ASSERT_TRUE(r.suite) << All(r);
  EXPECT_EQ(r.suite->rows[0].sensors[0].params.GetInt("beams"), 9);
  std::string written = suite;
  written.replace(written.find("[lidar2d, person]"), 17, "[{type: lidar2d, beams: 9}, person]");
  const auto same = Load(written);
  ASSERT_TRUE(same.suite) << All(same);
  EXPECT_EQ(same.suite->ConfigHash(), r.suite->ConfigHash());
}

// A parameter marked hashed_at_default = false (value_rl's route_prior, added after the tables
// were committed) leaves the configuration as it was at its default, and changes it otherwise.
TEST_F(SuiteEdits, AParameterAddedLaterLeavesTheHashAtItsDefault) {
  const std::string suite = R"(name: t
episodes: 3
world: {source: random_rect, obstacles: 1, split: test}
humans: {count: 5, policy: orca}
robot:
  sensors: [person, route]
rows:
  - {label: sarl, policy: sarl, params: {sensors: person+route}}
)";
  const auto plain = Load(suite);
  ASSERT_TRUE(plain.suite) << All(plain);
  EXPECT_EQ(plain.suite->rows[0].canonical.find("route_prior"), std::string::npos)
      << plain.suite->rows[0].canonical;
  const auto zero = Load(suite, {"rows[sarl].params.route_prior=0"});
  ASSERT_TRUE(zero.suite) << All(zero);
  EXPECT_EQ(zero.suite->rows[0].canonical, plain.suite->rows[0].canonical);
  const auto prior = Load(suite, {"rows[sarl].params.route_prior=0.1"});
  ASSERT_TRUE(prior.suite) << All(prior);
  EXPECT_NE(prior.suite->rows[0].canonical.find("route_prior=0.1"), std::string::npos);
  EXPECT_NE(prior.suite->ConfigHash(), plain.suite->ConfigHash());
  // Parameters without the mark enter at their default too, as they always did.
  EXPECT_NE(plain.suite->rows[0].canonical.find("torch_threads=1"), std::string::npos);
}

// A row a sweep makes, named by its label, which holds an '=': the --set was cut at that '='
// and said "an unclosed or empty [...] in 'rows[orca/humans.count'". Now the label is looked
// up, and the row that has the sweep is named.
TEST_F(SuiteEdits, ASetOfARowASweepMakesNamesTheSweepRow) {
  const auto r = Load(kSuite, {"rows[orca/humans.count=2].params.safety_space=0.1"});
  ASSERT_FALSE(r.suite);
  EXPECT_NE(All(r).find("'rows' has no item [orca/humans.count=2] (items: 0 orca, 1 linear); the "
                        "rows of a sweep are set through the row that has it: rows[orca]"),
            std::string::npos)
      << All(r);
  // A value may hold '=' and '[' as before.
  const auto ok = Load(kSuite, {"rows[linear].info={model: a=b}"});
  ASSERT_TRUE(ok.suite) << All(ok);
  const auto& info = ok.suite->rows.back().info;
  EXPECT_NE(
      std::find(info.begin(), info.end(), std::pair<std::string, std::string>("model", "a=b")),
      info.end());
}

// The hint names the row before the '/' only when that row has a sweep: rows labelled `orca`
// and `orca/fast` by hand, and a typo of the second, were told to set `orca`'s sweep.
TEST_F(SuiteEdits, ATypoOfALabelWithASlashIsNotToldOfASweep) {
  std::string yaml = kSuite;
  yaml += "  - {label: orca/fast, policy: orca, params: {safety_space: 0.1}}\n";
  std::string no_sweep = yaml;
  no_sweep.erase(no_sweep.find("    sweep:"), no_sweep.find('\n', no_sweep.find("    sweep:")) -
                                                  no_sweep.find("    sweep:") + 1);
  const auto r = Load(no_sweep, {"rows[orca/fats].params.safety_space=0.2"});
  ASSERT_FALSE(r.suite);
  EXPECT_NE(All(r).find("'rows' has no item [orca/fats]"), std::string::npos) << All(r);
  EXPECT_EQ(All(r).find("sweep"), std::string::npos) << All(r);
  // With the sweep, the hint stays.
  const auto swept = Load(yaml, {"rows[orca/fats].params.safety_space=0.2"});
  EXPECT_NE(All(swept).find("set through the row that has it: rows[orca]"), std::string::npos)
      << All(swept);
}

TEST_F(SuiteEdits, BadOverridesAreNamedByTheOption) {
  auto r = Load(kSuite, {"rows[ocra].policy=orca"});
  ASSERT_FALSE(r.suite);
  EXPECT_EQ(All(r),
            "--set rows[ocra].policy=orca: 'rows' has no item [ocra] (items: 0 orca, 1 linear)\n");
  r = Load(kSuite, {"humans.count=abc"});
  ASSERT_FALSE(r.suite);
  EXPECT_EQ(All(r), "--set humans.count=abc: humans.count: must be a whole number, found 'abc'\n");
  r = Load(kSuite, {"humans.count"});
  ASSERT_FALSE(r.suite);
  EXPECT_NE(All(r).find("give key.path=value"), std::string::npos) << All(r);
  r = Load(kSuite, {"rows[1.policy=orca"});
  ASSERT_FALSE(r.suite);
  EXPECT_NE(All(r).find("unclosed"), std::string::npos) << All(r);
  r = Load(kSuite, {"name.x=1"});
  ASSERT_FALSE(r.suite);
  EXPECT_NE(All(r).find("'name' is not a map"), std::string::npos) << All(r);
}

TEST_F(SuiteEdits, TrainingFilesTakeOverridesToo) {
  const auto file =
      dir_.Write("train.yaml",
                 "name: tr\nseed: 1\npolicy: cadrl\nparams: {sensors: person}\nsensors: [person]\n"
                 "world: {source: random_rect, obstacles: 0}\nhumans: {count: 1}\ntraining: "
                 "{rl_episodes: 100}\n");
  const auto r = training::LoadTrainSpec(file, registry_, {"training.rl_episodes=250", "seed=9"});
  ASSERT_TRUE(r.spec) << (r.errors.empty() ? "" : r.errors[0].Format());
  EXPECT_EQ(r.spec->training.rl_episodes, 250);
  EXPECT_EQ(r.spec->seed, 9u);
}

// The config hash tells apart numbers that differ past six significant digits (a resume would
// take episodes made with 1.3 for 1.3000004), and prints what six digits give as it always did.
TEST_F(SuiteEdits, TheConfigHashCarriesNumbersExactly) {
  const auto base = Load(kSuite, {"sim.robot_v_pref=1.3"});
  ASSERT_TRUE(base.suite) << All(base);
  for (const char* set : {"sim.robot_v_pref=1.3000004", "sim.robot_v_pref=1.30000000000001"}) {
    const auto near = Load(kSuite, {set});
    ASSERT_TRUE(near.suite) << All(near);
    EXPECT_NE(near.suite->ConfigHash(), base.suite->ConfigHash()) << set;
  }
  const auto param = Load(kSuite, {"rows[linear].params.speed_factor=1.2"});
  const auto param_near = Load(kSuite, {"rows[linear].params.speed_factor=1.2000001"});
  ASSERT_TRUE(param.suite && param_near.suite) << All(param) << All(param_near);
  EXPECT_NE(param.suite->ConfigHash(), param_near.suite->ConfigHash());
  EXPECT_NE(base.suite->canonical.find("1.3,"), std::string::npos) << base.suite->canonical;
  EXPECT_EQ(FormatParamValue(1.3), "1.3");
  EXPECT_EQ(FormatParamValue(0.25), "0.25");
  EXPECT_EQ(FormatParamValue(1e-05), "1e-05");
  EXPECT_EQ(FormatParamValue(1.3000004), "1.3000004000000001");
  EXPECT_EQ(FormatParamValue(std::vector<double>{0.1, 1.0000001}), "[0.1, 1.0000001000000001]");
}

TEST_F(SuiteEdits, TheTrainingHashCarriesNumbersExactly) {
  const auto file =
      dir_.Write("train.yaml",
                 "name: tr\nseed: 1\npolicy: cadrl\nparams: {sensors: person}\nsensors: [person]\n"
                 "world: {source: random_rect, obstacles: 0}\nhumans: {count: 1}\ntraining: "
                 "{rl_episodes: 100}\n");
  const auto a = training::LoadTrainSpec(file, registry_, {"training.rl_learning_rate=0.001"});
  const auto b =
      training::LoadTrainSpec(file, registry_, {"training.rl_learning_rate=0.0010000001"});
  ASSERT_TRUE(a.spec && b.spec);
  EXPECT_NE(a.spec->ConfigHash(), b.spec->ConfigHash());
}

}  // namespace
}  // namespace crowdsim
