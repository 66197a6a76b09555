// Trainings end to end: a short training beats the untrained network, a tiny one is
// deterministic and resumes exactly, and every model / sensor combination trains.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/runner.h"
#include "crowdsim/bench/suite.h"
#include "learning_test_util.h"
#include "test_paths.h"
#include "value_rl/value_policy.h"

namespace crowdsim::testing {
namespace {

namespace fs = std::filesystem;

// A few demonstrations and RL episodes with small batches: seconds, not minutes.
const char* kTiny =
    "{il_episodes: 10, il_epochs: 2, rl_episodes: 12, epsilon_decay_episodes: 6, "
    "target_update_interval: 4, batch_size: 20, train_batches: 3, validation_interval: 6, "
    "validation_episodes: 3, checkpoint_interval: 5}";

/// What a training of `f` (written into `dir`, out to dir/out) is refused with; a failure, and
/// "", when it is not refused.
std::string RefusalOf(const TempDir& dir, const TrainFile& f) {
  try {
    Train(WriteTrainFile(dir, f), dir.path() / "out");
  } catch (const training::TrainRefused& e) {
    return e.what();
  }
  ADD_FAILURE() << "trained, not refused";
  return "";
}

/// Greedy success rates of the trained and the untrained network on the same 100 test episodes.
std::pair<double, double> Evaluate(const TempDir& dir, const fs::path& weights) {
  const fs::path suite_file =
      dir.Write("eval.yaml",
                "name: eval\nepisodes: 100\nseed: 99\n"
                "world: {source: random_rect, obstacles: 0, split: test}\n"
                "humans: {count: 1, policy: orca}\n"
                "robot: {sensors: [person]}\n"
                "rows:\n"
                "  - {label: trained, policy: cadrl, params: {sensors: person}, weights: " +
                    weights.string() +
                    "}\n"
                    "  - {label: untrained, policy: cadrl, params: {sensors: person}}\n");
  PluginRegistry registry;
  SuiteLoadResult loaded = LoadSuite(suite_file, registry);
  EXPECT_TRUE(loaded.suite) << (loaded.errors.empty() ? "" : loaded.errors[0].Format());
  RunOptions options;
  options.out_dir = dir.path() / "eval";
  options.jobs = 2;
  options.progress = false;
  const RunSummary s = RunSuite(*loaded.suite, registry, options);
  EXPECT_EQ(s.rows.size(), 2u);
  return {s.rows[0].metrics.success_rate, s.rows[1].metrics.success_rate};
}

TEST(TrainingTest, ShortTrainingBeatsTheUntrainedNetwork) {
  TempDir dir;
  TrainFile f;
  f.training =
      "{il_episodes: 200, il_epochs: 20, rl_episodes: 300, epsilon_decay_episodes: 150, "
      "validation_interval: 0, checkpoint_interval: 1000, train_batches: 50}";
  const auto summary = Train(WriteTrainFile(dir, f), dir.path() / "out");
  ASSERT_TRUE(summary.finished);
  ASSERT_TRUE(fs::exists(summary.weights));
  EXPECT_TRUE(fs::exists(dir.path() / "out" / "il.pt"));
  const auto [trained, untrained] = Evaluate(dir, summary.weights);
  std::printf("greedy success on 100 test episodes: trained %.2f, untrained %.2f\n", trained,
              untrained);
  EXPECT_GE(trained, untrained + 0.3);
  EXPECT_GE(trained, 0.7);
}

TEST(TrainingTest, SameSeedSameWeights) {
  TempDir dir;
  TrainFile f;
  f.training = kTiny;
  const auto file = WriteTrainFile(dir, f);
  const auto a = Train(file, dir.path() / "a");
  const auto b = Train(file, dir.path() / "b");
  EXPECT_EQ(ValuesOfWeights(f, a.weights), ValuesOfWeights(f, b.weights));
  ASSERT_EQ(a.validations.size(), 3u);  // at 0, 6 and the end
  for (size_t i = 0; i < a.validations.size(); ++i) {
    EXPECT_EQ(a.validations[i].success, b.validations[i].success);
  }
  f.seed = 6;
  const auto c = Train(WriteTrainFile(dir, f, "other_seed.yaml"), dir.path() / "c");
  EXPECT_NE(ValuesOfWeights(f, a.weights), ValuesOfWeights(f, c.weights));
}

TEST(TrainingTest, ResumeContinuesExactly) {
  TempDir dir;
  TrainFile f;
  f.sensors_param = "lidar+person";
  f.sensors = "[person, {type: lidar2d, beams: 15}]";
  f.policy = "sarl";
  f.training = kTiny;
  const auto file = WriteTrainFile(dir, f);
  const auto whole = Train(file, dir.path() / "whole");
  // Stop in the demonstrations, then in RL, then finish.
  const auto part1 = Train(file, dir.path() / "parts", false, 7);
  EXPECT_FALSE(part1.finished);
  EXPECT_TRUE(fs::exists(dir.path() / "parts" / "checkpoint" / "state.txt"));
  const auto part2 = Train(file, dir.path() / "parts", true, 9);
  EXPECT_FALSE(part2.finished);
  const auto part3 = Train(file, dir.path() / "parts", true);
  ASSERT_TRUE(part3.finished);
  EXPECT_EQ(ValuesOfWeights(f, whole.weights), ValuesOfWeights(f, part3.weights));
  // The per-episode log is cut back to each checkpoint and so ends up as one uninterrupted run's.
  const std::string log = ReadText(dir.path() / "whole" / "training_episodes.csv");
  EXPECT_EQ(ReadText(dir.path() / "parts" / "training_episodes.csv"), log);
  EXPECT_NE(log.find("\ndemonstration,9,"), std::string::npos);
  EXPECT_NE(log.find("\nimitation,1,"), std::string::npos);
  EXPECT_NE(log.find("\nrl,11,"), std::string::npos);
  // Validations with the mean value of the fixed probe states, identical after resuming.
  const std::string validations = ReadText(dir.path() / "whole" / "training_log.csv");
  EXPECT_EQ(ReadText(dir.path() / "parts" / "training_log.csv"), validations);
  EXPECT_EQ(validations.rfind(
                "rl_episode,success_rate,collision_rate,timeout_rate,nav_time,probe_value\n", 0),
            0u);
  EXPECT_EQ(validations.find(",\n"), std::string::npos)
      << validations;  // every probe value present
  // Restarting over a finished training without --resume is refused.
  EXPECT_THROW(Train(file, dir.path() / "parts"), training::TrainError);
  // training.yaml says what it is: the canonical text of the configuration (it said "# copy of
  // FILE" over lines that are not the file's).
  const std::string record = ReadText(dir.path() / "whole" / "training.yaml");
  EXPECT_EQ(record.rfind("# the configuration of " + file.string() +
                             " as its config hash reads it (a record, not a training file: "
                             "train from the file)\nseed=5\n",
                         0),
            0u)
      << record;
}

// A policy that fails in the middle of a training is named once: the episode's error says
// whose policy it was, and the trainer put "the robot policy failed: " before it ("the robot
// policy failed: the robot's policy failed: ...", and a human's failure read as the robot's).
TEST(TrainingTest, APolicyFailingMidTrainingIsNamedOnce) {
  TempDir dir;
  TrainFile f;
  f.training = "{il_policy: " + (FixturePluginDir() / "crowdsim_throwing_policy.so").string() +
               ", il_params: {fail_after_steps: 2, good_episodes: 1}, il_episodes: 5, "
               "il_epochs: 1, rl_episodes: 2, epsilon_decay_episodes: 2, "
               "validation_interval: 1, validation_episodes: 1}";
  try {
    Train(WriteTrainFile(dir, f), dir.path() / "out");
    ADD_FAILURE() << "a teacher that throws trained";
  } catch (const training::TrainError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(": the robot's policy failed: deliberate failure (fixture)"),
              std::string::npos)
        << what;
    EXPECT_EQ(what.find("the robot policy failed"), std::string::npos) << what;
  }
}

// A learning rate of 10 blows the value network up in the first RL episode: training stops there,
// naming the episode, the cause and the fix, instead of training on with NaN weights.
TEST(TrainingTest, ADivergingNetworkStopsTrainingWithTheFix) {
  TempDir dir;
  TrainFile f;
  f.training =
      "{il_episodes: 4, il_epochs: 2, rl_episodes: 12, rl_learning_rate: 10, "
      "epsilon_decay_episodes: 6, train_batches: 5, validation_interval: 0}";
  try {
    Train(WriteTrainFile(dir, f), dir.path() / "out");
    ADD_FAILURE() << "a diverging network trained on";
  } catch (const training::TrainError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("RL episode 0: the loss is not finite: the network diverged"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("lower training.rl_learning_rate"), std::string::npos) << what;
  }
}

TEST(TrainingTest, ResumeRefusesAnotherConfiguration) {
  TempDir dir;
  TrainFile f;
  f.training = kTiny;
  Train(WriteTrainFile(dir, f), dir.path() / "out", false, 4);
  f.humans = "{count: 2}";
  // Without --resume the refusal says the folder holds another training (it said "pass
  // --resume", which then failed).
  try {
    Train(WriteTrainFile(dir, f, "changed.yaml"), dir.path() / "out");
    ADD_FAILURE() << "trained over another training's folder";
  } catch (const training::TrainRefused& e) {
    EXPECT_NE(std::string(e.what()).find("already holds another training (what differs: humans:"),
              std::string::npos)
        << e.what();
  }
  try {
    Train(WriteTrainFile(dir, f, "changed.yaml"), dir.path() / "out", true);
    ADD_FAILURE() << "resumed a checkpoint of another configuration";
  } catch (const training::TrainError& e) {
    EXPECT_NE(std::string(e.what()).find("another configuration"), std::string::npos) << e.what();
    // What differs, from the folder's copy of the configuration it started with.
    EXPECT_NE(std::string(e.what()).find("what differs: humans: 1-1,"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find(" -> 2-2,"), std::string::npos) << e.what();
  }
  // The training settings by name (the canonical line writes them without names), the first
  // and the last of them.
  f.humans = "{count: 1}";
  f.training = std::string(kTiny).replace(std::string(kTiny).find("validation_episodes: 3"), 22,
                                          "validation_episodes: 4");
  f.training.replace(f.training.find("il_episodes: 10"), 15, "il_episodes: 11");
  try {
    Train(WriteTrainFile(dir, f, "settings.yaml"), dir.path() / "out", true);
    ADD_FAILURE() << "resumed a checkpoint of other training settings";
  } catch (const training::TrainRefused& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "what differs: training: il_episodes 10 -> 11, validation_episodes 3 -> 4"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(Train(WriteTrainFile(dir, f, "fresh.yaml"), dir.path() / "none", true),
               training::TrainError);
}

// A model copied into the folder was answered "pass --resume", and --resume "no checkpoint".
TEST(TrainingTest, AFolderHoldingOnlyAModelIsNotSentInACircle) {
  TempDir dir;
  TrainFile f;
  f.training = kTiny;
  const auto file = WriteTrainFile(dir, f);
  fs::create_directories(dir.path() / "out");
  std::ofstream(dir.path() / "out" / "weights.pt") << "someone's model";
  std::string fresh, resumed;
  try {
    Train(file, dir.path() / "out");
  } catch (const training::TrainRefused& e) {
    fresh = e.what();
  }
  try {
    Train(file, dir.path() / "out", true);
  } catch (const training::TrainRefused& e) {
    resumed = e.what();
  }
  for (const std::string& what : {fresh, resumed}) {
    EXPECT_NE(what.find("train into another folder with --out"), std::string::npos) << what;
    EXPECT_EQ(what.find("pass --resume"), std::string::npos) << what;
  }
  EXPECT_NE(fresh.find("already holds a weights.pt with no checkpoint/"), std::string::npos)
      << fresh;
  EXPECT_NE(resumed.find("its weights.pt is a model without a training state"), std::string::npos)
      << resumed;
  EXPECT_EQ(ReadText(dir.path() / "out" / "weights.pt"), "someone's model");
}

// A teacher's weights in the output folder would be replaced by the training that reads them.
TEST(TrainingTest, AnOutputThatIsATeachersWeightsIsRefused) {
  TempDir dir;
  TrainFile f;
  f.training = kTiny;
  Train(WriteTrainFile(dir, f), dir.path() / "first");
  fs::create_directories(dir.path() / "out");
  const fs::path teacher = dir.path() / "out" / "best.pt";
  fs::copy_file(dir.path() / "first" / "weights.pt", teacher);
  f.training = std::string(kTiny).substr(0, std::string(kTiny).size() - 1) +
               ", il_policy: cadrl, il_params: {sensors: person, weights: " + teacher.string() +
               "}}";
  const std::string what = RefusalOf(dir, f);  // trains into dir/out
  EXPECT_NE(what.find("--out would write " + teacher.string() +
                      ", which is the teacher (training.il_policy)'s weights this command reads"),
            std::string::npos)
      << what;
  EXPECT_EQ(ReadText(teacher), ReadText(dir.path() / "first" / "weights.pt"));
}

TEST(TrainingTest, LengtheningTheRlPhaseContinuesLikeALongerTraining) {
  TempDir dir;
  TrainFile f;
  f.training = kTiny;  // 12 RL episodes, checkpoints every 5
  ASSERT_TRUE(Train(WriteTrainFile(dir, f), dir.path() / "grown").finished);
  std::string longer = kTiny;
  longer.replace(longer.find("rl_episodes: 12"), 15, "rl_episodes: 18");
  f.training = longer;
  const auto long_file = WriteTrainFile(dir, f, "longer.yaml");
  // The finished 12-episode training, resumed with 18: it goes on from its last checkpoint.
  const auto grown = Train(long_file, dir.path() / "grown", true);
  ASSERT_TRUE(grown.finished);
  const auto whole = Train(long_file, dir.path() / "whole");
  EXPECT_EQ(ValuesOfWeights(f, grown.weights), ValuesOfWeights(f, whole.weights));
  EXPECT_EQ(ReadText(dir.path() / "grown" / "training_episodes.csv"),
            ReadText(dir.path() / "whole" / "training_episodes.csv"));
  EXPECT_EQ(ReadText(dir.path() / "grown" / "training_log.csv"),
            ReadText(dir.path() / "whole" / "training_log.csv"));
  // Shortening below the episodes already done is refused, with the count.
  f.training = kTiny;
  try {
    Train(WriteTrainFile(dir, f, "shorter.yaml"), dir.path() / "grown", true);
    ADD_FAILURE() << "shortened the RL phase below the episodes done";
  } catch (const training::TrainError& e) {
    EXPECT_NE(std::string(e.what()).find("fewer than the 15 RL episodes"), std::string::npos)
        << e.what();
  }
}

// best.pt is the checkpoint's when a finished training resumes to a shorter RL phase: here the
// 3-episode training's best validation is its last (RL episode 3, after its last checkpoint at
// 2); shortened to 2, best.pt kept those episode-3 weights while summary.json named episode 0.
TEST(TrainingTest, ShorteningTheRlPhaseKeepsTheShorterTrainingsBestWeights) {
  TempDir dir;
  TrainFile f;
  f.sensors_param = "lidar+person";
  f.sensors = "[person, {type: lidar2d, beams: 15, fov_deg: 180, max_range: 5}]";
  f.world = "{source: random_rect, obstacles: 1}";
  f.humans = "{count: 5}";
  f.seed = 1;
  const std::string training =
      "{il_episodes: 40, il_epochs: 5, rl_episodes: 3, epsilon_start: 0.5, epsilon_end: 0.1, "
      "epsilon_decay_episodes: 6, validation_interval: 1, validation_episodes: 2, "
      "checkpoint_interval: 2}";
  f.training = training;
  ASSERT_TRUE(Train(WriteTrainFile(dir, f), dir.path() / "shortened").finished);
  f.training = std::string(training).replace(training.find("rl_episodes: 3"), 14, "rl_episodes: 2");
  const auto short_file = WriteTrainFile(dir, f, "shorter.yaml");
  const auto shortened = Train(short_file, dir.path() / "shortened", true);
  const auto whole = Train(short_file, dir.path() / "whole");
  ASSERT_TRUE(shortened.finished);
  EXPECT_EQ(ReadText(dir.path() / "shortened" / "training_log.csv"),
            ReadText(dir.path() / "whole" / "training_log.csv"));
  ASSERT_FALSE(shortened.best_weights.empty());
  EXPECT_EQ(ValuesOfWeights(f, shortened.best_weights), ValuesOfWeights(f, whole.best_weights));
}

TEST(TrainingTest, AnIncompleteOrDamagedCheckpointIsNamedNotAStackTrace) {
  TempDir dir;
  TrainFile f;
  f.training = kTiny;
  const auto file = WriteTrainFile(dir, f);
  Train(file, dir.path() / "out", false, 15);  // stops in RL, after a checkpoint
  const auto optimizer = dir.path() / "out" / "checkpoint" / "optimizer.pt";
  ASSERT_TRUE(fs::exists(optimizer));
  fs::remove(optimizer);
  auto message = [&]() -> std::string {
    try {
      Train(file, dir.path() / "out", true);
    } catch (const training::TrainError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message().find("lacks optimizer.pt (incomplete or damaged)"), std::string::npos)
      << message();
  std::ofstream(optimizer) << "not a torch archive";
  const std::string damaged = message();
  EXPECT_NE(damaged.find("cannot read"), std::string::npos) << damaged;
  EXPECT_EQ(damaged.find("frame #"), std::string::npos) << damaged;
}

/// What `task` throws in a forked child whose files may not grow past `limit` bytes (EFBIG, as a
/// full disk fails writes); "died of signal N" when it does not return.
std::string WhatUnderFileSizeLimit(rlim_t limit, const std::function<void()>& task) {
  int fds[2];
  if (pipe(fds) != 0) return "no pipe";
  const pid_t child = fork();
  if (child == 0) {
    close(fds[0]);
    signal(SIGXFSZ, SIG_IGN);
    const rlimit l{limit, limit};
    setrlimit(RLIMIT_FSIZE, &l);
    std::string what = "no error";
    try {
      task();
    } catch (const std::exception& e) {
      what = e.what();
    }
    (void)!write(fds[1], what.data(), what.size());
    _exit(0);
  }
  close(fds[1]);
  std::string what;
  char buf[4096];
  for (ssize_t n; (n = read(fds[0], buf, sizeof(buf))) > 0;) what.append(buf, std::size_t(n));
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  return WIFSIGNALED(status) ? "died of signal " + std::to_string(WTERMSIG(status)) : what;
}

// A full disk ended the process in libtorch's file writer (SIGABRT) and showed std::filesystem's
// "Input/output error" when best.pt was copied.
TEST(TrainingTest, AFullDiskIsSaidAsSuchAndKeepsThePreviousCheckpoint) {
  TempDir dir;
  TrainFile f;
  f.training = std::string(kTiny).replace(std::string(kTiny).find("validation_interval: 6"), 22,
                                          "validation_interval: 7");
  const auto file = WriteTrainFile(dir, f);
  Train(file, dir.path() / "out", false, 15);  // stops in RL, after a checkpoint
  const fs::path checkpoint = dir.path() / "out" / "checkpoint";
  // Weights writes fail, the process lives.
  value_rl::ValueRlConfig c;
  value_rl::ValuePolicy policy(c);
  const std::string weights =
      WhatUnderFileSizeLimit(4096, [&] { policy.SaveWeights(dir.path() / "w.pt"); });
  EXPECT_NE(weights.find("cannot write " + (dir.path() / "w.pt").string() + ": File too large"),
            std::string::npos)
      << weights;
  // Resuming copies best.pt: the copy's failure says why.
  const std::string resumed =
      WhatUnderFileSizeLimit(4096, [&] { Train(file, dir.path() / "out", true); });
  EXPECT_NE(resumed.find("best.pt: File too large"), std::string::npos) << resumed;
  // Without best.pt to copy (older checkpoints lack it) the resume goes on to the next
  // checkpoint (RL episode 20; validations at 14 and 21), whose first file fails.
  fs::remove(checkpoint / "best.pt");
  const std::string saved =
      WhatUnderFileSizeLimit(4096, [&] { Train(file, dir.path() / "out", true); });
  EXPECT_NE(saved.find("cannot save the checkpoint in"), std::string::npos) << saved;
  EXPECT_NE(saved.find("model.pt: File too large"), std::string::npos) << saved;
  EXPECT_NE(saved.find("The previous checkpoint/ is unchanged"), std::string::npos) << saved;
  EXPECT_FALSE(fs::exists(dir.path() / "out" / "checkpoint.tmp"));
  // The kept checkpoint still resumes to the end.
  EXPECT_NO_THROW(Train(file, dir.path() / "out", true));
}

/// The last line's replay-memory counts (imitation, success, collision, timeout).
std::vector<long> LastMemoryComposition(const fs::path& log_file) {
  const std::string log = ReadText(log_file);
  const std::size_t start = log.rfind('\n', log.size() - 2) + 1;
  std::vector<std::string> fields;
  std::stringstream line(log.substr(start));
  for (std::string f; std::getline(line, f, ',');) fields.push_back(f);
  std::vector<long> counts;
  for (std::size_t i = fields.size() - 4; i < fields.size(); ++i)
    counts.push_back(std::stol(fields[i]));
  return counts;
}

TEST(TrainingTest, TimeoutsReachTheMemoryOnlyWhenTheProcedureSaysSo) {
  // 3 s are too short to reach the goal: every episode times out.
  TrainFile f;
  f.sim = "{time_limit: 3}";
  std::map<std::string, std::vector<float>> weights;
  for (const char* mode : {"off", "terminal", "bootstrap"}) {
    SCOPED_TRACE(mode);
    TempDir dir;
    f.training = std::string(
                     "{il_episodes: 3, il_epochs: 1, rl_episodes: 6, epsilon_start: 0.5, "
                     "epsilon_end: 0.1, epsilon_decay_episodes: 4, batch_size: 8, "
                     "train_batches: 2, validation_interval: 0, store_timeouts: ") +
                 mode + "}";
    const auto s = Train(WriteTrainFile(dir, f), dir.path() / "out");
    ASSERT_TRUE(s.finished);
    const auto counts = LastMemoryComposition(dir.path() / "out" / "training_episodes.csv");
    EXPECT_EQ(counts[0], 0);  // the teacher timed out too: no demonstration is stored
    EXPECT_EQ(counts[1] + counts[2], 0);
    if (std::string(mode) == "off") {
      EXPECT_EQ(counts[3], 0);
    } else {
      EXPECT_EQ(counts[3], 6 * 12);  // six episodes of 12 steps
    }
    weights[mode] = ValuesOfWeights(f, s.weights);
  }
  // Terminal and bootstrapped targets differ, so do the weights trained on them.
  EXPECT_NE(weights["terminal"], weights["bootstrap"]);
}

struct Combination {
  const char* policy;
  const char* sensors_param;
  const char* sensors;
};

TEST(TrainingTest, EveryModelAndSensorSetTrains) {
  const Combination all[] = {
      {"cadrl", "person", "[person]"},
      {"cadrl", "lidar", "[{type: lidar2d, beams: 15}]"},
      {"cadrl", "lidar+person", "[person, {type: lidar2d, beams: 15}]"},
      {"sarl", "person", "[person]"},
      {"sarl", "lidar", "[{type: lidar2d, beams: 15}]"},
      {"sarl", "lidar+person", "[person, {type: lidar2d, beams: 15}]"},
  };
  for (const auto& c : all) {
    SCOPED_TRACE(std::string(c.policy) + " " + c.sensors_param);
    TempDir dir;
    TrainFile f;
    f.policy = c.policy;
    f.sensors_param = c.sensors_param;
    f.sensors = c.sensors;
    f.world = "{source: random_rect, obstacles: 1}";
    f.humans = "{count: [0, 3]}";  // includes nobody: the stand-in human row
    f.training =
        "{il_episodes: 4, il_epochs: 1, rl_episodes: 4, batch_size: 16, train_batches: 2, "
        "validation_interval: 0}";
    const auto s = Train(WriteTrainFile(dir, f), dir.path() / "out");
    EXPECT_TRUE(s.finished);
    EXPECT_EQ(ValuesOfWeights(f, s.weights).size(), 8u);
  }
}

// The learner's sensor needs are checked as a suite row's (RowInstance::UnmetSensorNeed), before
// the first episode, with the need and the fix named (the CLI names the file), as a refusal:
// nothing was trained.
TEST(TrainingTest, PolicyWithoutItsSensorIsRefused) {
  TempDir dir;
  TrainFile f;
  f.sensors_param = "lidar+person";
  f.training = kTiny;
  EXPECT_EQ(RefusalOf(dir, f), "policy 'cadrl' needs the sensor 'lidar2d'; add it to `sensors`");
}

// A humans' policy that needs what only the robot is given (a sensor, the lookahead) is refused
// as the learner's missing sensor is: before the first episode, nothing trained.
TEST(TrainingTest, HumansPolicyNeedingASensorIsRefused) {
  TempDir dir;
  TrainFile f;
  f.humans = "{count: 1, policy: cadrl, params: {sensors: person}}";
  f.training = kTiny;
  EXPECT_EQ(RefusalOf(dir, f),
            "the humans' policy 'cadrl' needs the sensor 'person', which only the robot is "
            "given; give the humans a policy that needs neither, e.g. humans: {policy: orca}");
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out" / "weights.pt"));
}

// A teacher whose weights are missing is named as the teacher: the learner's own missing
// weights gave the same message, and the user could not tell which one failed.
TEST(TrainingTest, AMissingTeacherIsNamedAsTheTeacher) {
  TempDir dir;
  TrainFile f;
  f.training = std::string(kTiny).substr(0, std::string(kTiny).size() - 1) +
               ", il_policy: cadrl, il_params: {sensors: person, weights: nope/missing.pt}}";
  const std::string refusal = RefusalOf(dir, f);
  EXPECT_EQ(refusal.rfind("the imitation teacher (training.il_policy 'cadrl' with "
                          "training.il_params): ",
                          0),
            0u)
      << refusal;
  EXPECT_NE(refusal.find("missing.pt"), std::string::npos) << refusal;
}

}  // namespace
}  // namespace crowdsim::testing
