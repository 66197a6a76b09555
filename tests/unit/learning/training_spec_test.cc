// Training files are validated like suites: file:line:col errors, unknown keys rejected,
// paper defaults filled in.
#include <gtest/gtest.h>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/bench/runner.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/bench/training/train_spec.h"
#include "crowdsim/bench/training/trainer.h"
#include "learning_test_util.h"
#include "test_paths.h"

namespace crowdsim::testing {
namespace {

training::TrainSpecLoadResult Load(const std::filesystem::path& file) {
  PluginRegistry registry;
  return training::LoadTrainSpec(file, registry);
}

TEST(TrainSpecTest, DefaultsAreThePapers) {
  TempDir dir;
  TrainFile f;
  f.humans = "{count: 5}";
  const auto r = Load(WriteTrainFile(dir, f));
  ASSERT_TRUE(r.spec) << r.errors[0].Format();
  const training::TrainingSettings& t = r.spec->training;
  EXPECT_EQ(t.il_episodes, 3000);
  EXPECT_EQ(t.il_epochs, 50);
  EXPECT_DOUBLE_EQ(t.il_learning_rate, 0.01);
  EXPECT_EQ(t.rl_episodes, 10000);
  EXPECT_DOUBLE_EQ(t.rl_learning_rate, 0.001);
  EXPECT_DOUBLE_EQ(t.epsilon_start, 0.9);
  EXPECT_DOUBLE_EQ(t.epsilon_end, 0.5);
  EXPECT_EQ(t.epsilon_decay_episodes, 5000);
  EXPECT_EQ(t.target_update_interval, 50);
  EXPECT_EQ(t.capacity, 100000);
  EXPECT_EQ(t.batch_size, 100);
  EXPECT_EQ(t.train_batches, 100);
  EXPECT_DOUBLE_EQ(t.momentum, 0.9);
  EXPECT_EQ(t.validation_interval, 1000);
  EXPECT_EQ(t.checkpoint_interval, 500);
  EXPECT_DOUBLE_EQ(r.spec->sim.gamma, 0.9);
  EXPECT_EQ(r.spec->teacher.plugin, "orca");
  EXPECT_DOUBLE_EQ(r.spec->teacher.params.GetDouble("safety_space"), 0.15);
  EXPECT_EQ(r.spec->row.world.params.GetString("split"), "train");
  EXPECT_EQ(r.spec->row.humans.count, 5);
  EXPECT_EQ(r.spec->row.humans.count_max, 5);
  EXPECT_DOUBLE_EQ(training::Epsilon(t, 0), 0.9);
  EXPECT_DOUBLE_EQ(training::Epsilon(t, 2500), 0.7);
  EXPECT_DOUBLE_EQ(training::Epsilon(t, 5000), 0.5);
  EXPECT_DOUBLE_EQ(training::Epsilon(t, 9999), 0.5);
  EXPECT_EQ(t.store_timeouts, training::StoreTimeouts::kOff);
  EXPECT_EQ(t.validation_episodes, 100);
  // The paper's literal schedule is accepted but warned about (it unlearns here).
  const auto warnings = training::TrainSpecWarnings(*r.spec);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("timeout episodes are not stored"), std::string::npos) << warnings[0];
}

TEST(TrainSpecTest, StoreTimeoutsIsAProcedureKey) {
  TempDir dir;
  TrainFile f;
  for (const auto& [text, value] : {std::pair{"terminal", training::StoreTimeouts::kTerminal},
                                    std::pair{"bootstrap", training::StoreTimeouts::kBootstrap},
                                    std::pair{"off", training::StoreTimeouts::kOff}}) {
    f.training = std::string("{store_timeouts: ") + text + ", epsilon_end: 0.1}";
    const auto r = Load(WriteTrainFile(dir, f));
    ASSERT_TRUE(r.spec) << r.errors[0].Format();
    EXPECT_EQ(r.spec->training.store_timeouts, value);
    EXPECT_NE(r.spec->canonical.find(std::string("store_timeouts=") + text), std::string::npos);
  }
  f.training = "{store_timeouts: yes}";
  const auto bad = Load(WriteTrainFile(dir, f));
  ASSERT_FALSE(bad.spec);
  EXPECT_NE(bad.errors[0].Format().find(
                "training.store_timeouts: expected off, terminal or bootstrap, got 'yes'"),
            std::string::npos)
      << bad.errors[0].Format();
}

TEST(TrainSpecTest, ExplorationIsAProcedureKeyAndTheDefaultKeepsEarlierHashes) {
  TempDir dir;
  TrainFile f;
  f.training = "{epsilon_end: 0.1}";
  const auto plain = Load(WriteTrainFile(dir, f));
  ASSERT_TRUE(plain.spec) << plain.errors[0].Format();
  EXPECT_EQ(plain.spec->training.exploration, training::ExplorationRule::kUniform);
  // The default is not written into the canonical text: trainings made before the key existed
  // keep their config hash (and so --resume).
  EXPECT_EQ(plain.spec->canonical.find("exploration"), std::string::npos);
  f.training = "{epsilon_end: 0.1, exploration: uniform}";
  const auto uniform = Load(WriteTrainFile(dir, f));
  ASSERT_TRUE(uniform.spec);
  EXPECT_EQ(uniform.spec->ConfigHash(), plain.spec->ConfigHash());

  f.training = "{epsilon_end: 0.1, exploration: collision_free}";
  const auto safe = Load(WriteTrainFile(dir, f));
  ASSERT_TRUE(safe.spec) << safe.errors[0].Format();
  EXPECT_EQ(safe.spec->training.exploration, training::ExplorationRule::kCollisionFree);
  EXPECT_NE(safe.spec->ConfigHash(), plain.spec->ConfigHash());

  f.training = "{exploration: careful}";
  const auto bad = Load(WriteTrainFile(dir, f));
  ASSERT_FALSE(bad.spec);
  EXPECT_NE(bad.errors[0].Format().find(
                "training.exploration: expected uniform or collision_free, got 'careful'"),
            std::string::npos)
      << bad.errors[0].Format();
}

TEST(TrainSpecTest, SeedOverrideChangesTheConfigurationAndDecayWarns) {
  TempDir dir;
  TrainFile f;
  f.training =
      "{rl_episodes: 100, epsilon_decay_episodes: 400, epsilon_end: 0.1, store_timeouts: terminal}";
  PluginRegistry registry;  // the spec points into it
  auto r = training::LoadTrainSpec(WriteTrainFile(dir, f), registry);
  ASSERT_TRUE(r.spec) << r.errors[0].Format();
  const std::string hash = r.spec->ConfigHash();
  training::OverrideSeed(*r.spec, 2020);
  EXPECT_EQ(r.spec->seed, 2020u);
  EXPECT_NE(r.spec->ConfigHash(), hash);
  EXPECT_EQ(r.spec->canonical.rfind("seed=2020\n", 0), 0u);
  const auto warnings = training::TrainSpecWarnings(*r.spec);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("epsilon_decay_episodes (400) exceeds rl_episodes (100)"),
            std::string::npos);
}

TEST(TrainSpecTest, ErrorsAreLocated) {
  TempDir dir;
  TrainFile f;
  f.world = "{source: random_rect, obstacles: 1, split: test}";
  f.humans = "{count: [4, 2]}";
  f.training = "{il_episodes: 10, epsilon: 0.3, rl_learning_rate: -1}";
  const auto r = Load(WriteTrainFile(dir, f));
  ASSERT_FALSE(r.spec);
  std::string all;
  for (const auto& e : r.errors) all += e.Format() + "\n";
  EXPECT_NE(all.find("train.yaml:6:"), std::string::npos) << all;  // world line
  EXPECT_NE(all.find("world.split: training uses the world's train split"), std::string::npos)
      << all;
  EXPECT_NE(all.find("humans.count: min is larger than max"), std::string::npos) << all;
  EXPECT_NE(all.find("training.epsilon: unknown key 'epsilon'"), std::string::npos) << all;
  EXPECT_NE(all.find("training.rl_learning_rate: value -1 is out of range"), std::string::npos)
      << all;
  EXPECT_EQ(r.errors.size(), 4u) << all;
}

TEST(TrainSpecTest, ValidationsOfNoEpisodeAreRefused) {
  // Every validation of 0 episodes read "success 0 (best so far)"; interval 0 is "none".
  TempDir dir;
  TrainFile f;
  f.training = "{il_episodes: 10, validation_interval: 5, validation_episodes: 0}";
  const auto r = Load(WriteTrainFile(dir, f));
  ASSERT_FALSE(r.spec);
  EXPECT_NE(r.errors[0].Format().find("training.validation_episodes: 0 episodes validate nothing "
                                      "every 5 RL episodes"),
            std::string::npos)
      << r.errors[0].Format();
  f.training = "{il_episodes: 10, validation_interval: 0, validation_episodes: 0}";
  EXPECT_TRUE(Load(WriteTrainFile(dir, f, "none.yaml")).spec);
}

TEST(TrainSpecTest, UnknownTopKeyAndPolicyParameter) {
  TempDir dir;
  const auto file =
      dir.Write("bad.yaml",
                "name: bad\npolicy: sarl\nparams: {sensors: lidar, beams: 3}\nsensors: [person]\n"
                "world: {source: crowdnav}\nepisodes: 10\n");
  const auto r = Load(file);
  ASSERT_FALSE(r.spec);
  std::string all;
  for (const auto& e : r.errors) all += e.Format() + "\n";
  EXPECT_NE(all.find("bad.yaml:3:26: params.beams: unknown parameter 'beams'"), std::string::npos)
      << all;
  EXPECT_NE(all.find("bad.yaml:6:1: episodes: unknown key 'episodes'"), std::string::npos) << all;
}

// The top level of a training file is a suite row's spec, read by the suite's row reader:
// the same messages (file:line:col, key path, the offending value, the valid choices or the fix).
TEST(TrainSpecTest, TheRowPartIsReadByTheSuitesRowReader) {
  TempDir dir;
  const auto file = dir.Write(
      "row.yaml",
      "name: row\npolicy: linear\nweights: w.pt\nsensors: [person, {type: lidar2d, beamz: 9}]\n"
      "world: {source: random_rect, obstacles: 1}\nhumans: {count: 2, goal_mode: sideways}\n");
  const auto r = Load(file);
  ASSERT_FALSE(r.spec);
  std::string all;
  for (const auto& e : r.errors) all += e.Format() + "\n";
  EXPECT_NE(
      all.find("row.yaml:3:10: weights: policy 'linear' takes no weights (it has no 'weights' "
               "parameter)"),
      std::string::npos)
      << all;
  EXPECT_NE(all.find("row.yaml:4:35: sensors[1].beamz: unknown parameter 'beamz' for sensor plugin "
                     "'lidar2d' (valid: "),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("row.yaml:6:31: humans.goal_mode: value 'sideways' is not valid; valid: stay, "
                     "new_goal"),
            std::string::npos)
      << all;
  EXPECT_EQ(r.errors.size(), 3u) << all;

  // What a training file must give that a suite row may take from its suite.
  const auto bare = Load(dir.Write("bare.yaml", "name: bare\nhumans: {count: 1}\n"));
  ASSERT_FALSE(bare.spec);
  all.clear();
  for (const auto& e : bare.errors) all += e.Format() + "\n";
  EXPECT_NE(
      all.find("bare.yaml:1:1: policy: missing key 'policy' (the policy to train: cadrl or sarl)"),
      std::string::npos)
      << all;
  EXPECT_NE(all.find("bare.yaml:1:1: sensors: missing key 'sensors' (e.g. [person, {type: lidar2d, "
                     "beams: 45}])"),
            std::string::npos)
      << all;
  EXPECT_NE(all.find("bare.yaml:1:1: world: missing key 'world' (e.g. {source: random_rect, "
                     "obstacles: 1, split: train})"),
            std::string::npos)
      << all;
  EXPECT_EQ(bare.errors.size(), 3u) << all;
}

// The humans of a training file: the suite's keys (goal_mode too) plus a count range drawn per
// episode; a key left at its default keeps the hash of files written before it existed.
TEST(TrainSpecTest, HumansAreASuiteRowsWithACountRange) {
  TempDir dir;
  TrainFile f;
  f.humans = "{count: [2, 4], goal_mode: new_goal}";
  const auto ranged = Load(WriteTrainFile(dir, f));
  ASSERT_TRUE(ranged.spec) << ranged.errors[0].Format();
  EXPECT_EQ(ranged.spec->row.humans.count, 2);
  EXPECT_EQ(ranged.spec->row.humans.count_max, 4);
  EXPECT_EQ(ranged.spec->row.humans.goal_mode, HumanGoalMode::kNewGoal);
  EXPECT_NE(ranged.spec->canonical.find("\nhumans:2-4,goal_mode=new_goal,orca{"), std::string::npos)
      << ranged.spec->canonical;

  f.humans = "{count: 3}";
  const auto plain = Load(WriteTrainFile(dir, f));
  ASSERT_TRUE(plain.spec) << plain.errors[0].Format();
  EXPECT_NE(plain.spec->canonical.find("\nhumans:3-3,orca{"), std::string::npos)
      << plain.spec->canonical;
  f.humans = "{count: 3, goal_mode: stay}";
  const auto stay = Load(WriteTrainFile(dir, f));
  ASSERT_TRUE(stay.spec) << stay.errors[0].Format();
  EXPECT_EQ(stay.spec->ConfigHash(), plain.spec->ConfigHash());

  f.humans = "{count: [1, 2, 3]}";
  const auto bad = Load(WriteTrainFile(dir, f));
  ASSERT_FALSE(bad.spec);
  EXPECT_NE(bad.errors[0].Format().find(
                "train.yaml:7:17: humans.count: a range is a list of two counts [min, max]"),
            std::string::npos)
      << bad.errors[0].Format();
}

// Every committed model was trained from its training file as it is now (or that file with
// `--seed N`, for NAME_seedN): the training file's config hash is the one in summary.json, so a
// change to the reader or a training file that altered the configuration would be seen here.
TEST(TrainSpecTest, CommittedModelsMatchTheirTrainingFiles) {
  int checked = 0;
  for (const auto& entry :
       std::filesystem::directory_iterator(SourceDir() / "results" / "models")) {
    const auto summary = entry.path() / "summary.json";
    if (!std::filesystem::exists(summary)) continue;
    std::string name = entry.path().filename().string();
    const auto seed_at = name.rfind("_seed");
    const bool reseeded = seed_at != std::string::npos;
    if (reseeded) name = name.substr(0, seed_at);
    const auto file = SourceDir() / "suites" / "train" / (name + ".yaml");
    if (!std::filesystem::exists(file)) continue;
    SCOPED_TRACE(entry.path().string());
    PluginRegistry registry;
    auto r = training::LoadTrainSpec(file, registry);
    ASSERT_TRUE(r.spec) << r.errors[0].Format();
    if (reseeded)
      training::OverrideSeed(*r.spec,
                             static_cast<std::uint64_t>(ReadManifestInteger(summary, "seed")));
    EXPECT_EQ(ReadManifestField(summary, "config_hash"), r.spec->ConfigHash()) << r.spec->canonical;
    ++checked;
  }
  EXPECT_GE(checked, 20);
}

TEST(TrainSpecTest, ShippedTrainingFilesAreValid) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SourceDir() / "suites" / "train")) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    const auto r = Load(entry.path());
    EXPECT_TRUE(r.spec) << (r.errors.empty() ? "" : r.errors[0].Format());
    // validate's checks (learner, teacher, world, first scenarios, first steps) pass too.
    PluginRegistry registry;
    const auto loaded = training::LoadTrainSpec(entry.path(), registry);
    ASSERT_TRUE(loaded.spec);
    EXPECT_NO_THROW(training::PreflightTraining(*loaded.spec, registry)) << entry.path();
  }
  EXPECT_GE(files, 17);  // every line of Table 1
}

// Every committed suite can run as it is: its plugins, world files and trained weights load
// (what `validate` checks). Run from the source folder, as the suites' weights paths expect.
TEST(TrainSpecTest, ShippedSuitesCanRun) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SourceDir() / "suites")) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    SCOPED_TRACE(entry.path().string());
    PluginRegistry registry;
    const SuiteLoadResult r = LoadSuite(entry.path(), registry);
    ASSERT_TRUE(r.suite) << (r.errors.empty() ? "" : r.errors[0].Format());
    for (const auto& e : PreflightSuite(*r.suite, registry)) ADD_FAILURE() << e;
  }
  EXPECT_GE(files, 5);
}

// The committed reference output of every suite belongs to the suite as it is now: a change to
// a suite, a world file or weights that alters the configuration must come with new results
// (else `run` refuses the committed ones as another configuration).
TEST(TrainSpecTest, CommittedResultsMatchTheirSuites) {
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(SourceDir() / "suites")) {
    if (entry.path().extension() != ".yaml") continue;
    SCOPED_TRACE(entry.path().string());
    PluginRegistry registry;
    const SuiteLoadResult r = LoadSuite(entry.path(), registry);
    ASSERT_TRUE(r.suite) << (r.errors.empty() ? "" : r.errors[0].Format());
    const auto manifest = SourceDir() / "results" / r.suite->name / "manifest.json";
    if (!std::filesystem::exists(manifest)) continue;
    ++checked;
    EXPECT_EQ(ReadManifestField(manifest, "config_hash"), r.suite->ConfigHash())
        << manifest << ": rerun `crowdsim-bench run " << entry.path().filename().string()
        << "` and commit its results";
  }
  EXPECT_GE(checked, 5);
}

}  // namespace
}  // namespace crowdsim::testing
