// train: imitation + reinforcement learning of a learned policy from a training file;
// train-all: a campaign of them, one training per MPI rank (or one after another).
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>

#include "commands.h"
#include "crowdsim/bench/training/train_spec.h"
#include "crowdsim/bench/training/trainer.h"
#include "crowdsim/cli/args.h"
#include "crowdsim/render/learning_curve.h"
#include "process_group.h"

namespace crowdsim::cli {
namespace {

// A training's seed: the range of the training file's `seed:` key.
constexpr const char* kSeedRange = "a whole number from 0 to 9223372036854775807";
std::optional<std::uint64_t> ParseSeed(const std::string& text) {
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos) {
    return std::nullopt;
  }
  errno = 0;
  const unsigned long long v = std::strtoull(text.c_str(), nullptr, 10);
  if (errno == ERANGE || v > static_cast<unsigned long long>(INT64_MAX)) return std::nullopt;
  return static_cast<std::uint64_t>(v);
}

/// One training as `train` runs it.
struct TrainJob {
  std::string file;
  std::optional<std::string> seed;  ///< another seed: folder <name>_seed<N>
  std::optional<std::string> out;
  std::vector<std::string> sets;
  bool resume = false;
  bool quiet = false;
  /// train-all: resume when the folder has a checkpoint, skip a finished training of the same
  /// configuration.
  bool campaign = false;
};

/// The errors of a training file that did not load. A suite read as a training file gives an
/// unknown key for each of its own keys (episodes, robot, rows): that it is a suite is said
/// instead, as validate tells the two apart.
void ReportTrainSpecErrors(const std::string& file, const std::string& command,
                           const std::vector<SuiteError>& errors, bool count) {
  if (KindOfSpecFile(file) == SpecFileKind::kSuite) {
    std::cerr << "error: " << file << " is a suite: run it with `crowdsim-bench run " << file
              << "` (" << command
              << (command == "train" ? " takes a training file" : " takes training files")
              << ", see suites/train/)\n";
    return;
  }
  for (const auto& e : errors) std::cerr << "error: " << e.Format() << "\n";
  if (count) {
    std::cerr << errors.size() << " error" << (errors.size() == 1 ? "" : "s") << " in " << file
              << "\n";
  }
}

/// Where a job trains: --out, else results/train/<name>/ (with a seed, <name>_seed<N>/).
std::filesystem::path OutDir(const TrainJob& job, const training::TrainSpec& spec) {
  if (job.out) return *job.out;
  return std::filesystem::path("results") / "train" /
         (job.seed ? spec.name + "_seed" + *job.seed : spec.name);
}

/// The job's --seed or @SEED in place of the file's own seed (train-all checked its seeds when
/// it read the command line; train's is checked here).
void ApplySeed(const TrainJob& job, training::TrainSpec* spec) {
  if (!job.seed) return;
  const auto v = ParseSeed(*job.seed);
  if (!v) {
    throw UsageError("--seed must be " + std::string(kSeedRange) + ", got '" + *job.seed +
                     "' (the seed that replaces " + job.file + "'s own)");
  }
  training::OverrideSeed(*spec, *v);
}

int Train(const TrainJob& job) {
  PluginRegistry registry;
  training::TrainSpecLoadResult loaded = training::LoadTrainSpec(job.file, registry, job.sets);
  if (!loaded.spec) {
    ReportTrainSpecErrors(job.file, job.campaign ? "train-all" : "train", loaded.errors, true);
    return 2;
  }
  training::TrainOptions options;
  ApplySeed(job, &*loaded.spec);
  options.out_dir = OutDir(job, *loaded.spec);
  if (job.campaign && training::IsFinishedTraining(options.out_dir, *loaded.spec)) {
    std::cout << "finished already: " << options.out_dir.string() << " (skipped)\n";
    return 0;
  }
  for (const auto& w : training::TrainSpecWarnings(*loaded.spec)) {
    std::cerr << "warning: " << SpecSource(job.file, job.sets) << ": " << w << "\n";
  }
  options.resume = job.resume || (job.campaign && training::HasCheckpoint(options.out_dir));
  options.progress = !job.quiet;
  options.on_files_flushed = [](const std::filesystem::path& dir, const std::string& name) {
    try {
      render::WriteLearningCurve(dir, name);
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string("learning curve not drawn: ") + e.what());
    }
  };
  try {
    const training::TrainSummary s = training::RunTraining(*loaded.spec, registry, options);
    std::cout << "trained " << loaded.spec->name << " in " << s.wall_seconds
              << " s: " << s.weights.string();
    if (!s.best_weights.empty())
      std::cout << " (best validation: " << s.best_weights.string() << ")";
    std::cout << "\n";
    if (!s.validations.empty()) {
      const auto& v = s.validations.back();
      std::cout << "last validation: success " << v.success << ", collision " << v.collision
                << ", timeout " << v.timeout << ", nav time " << v.nav_time << "\n";
    }
  } catch (const training::TrainingInterrupted& e) {
    std::cerr << "\n"
              << e.what()
              << (job.campaign ? "; rerun the same train-all command to continue (it resumes "
                                 "each training from its checkpoint)"
                               : "; rerun with --resume to continue")
              << "\n";
    return 130;
  } catch (const training::TrainRefused& e) {
    std::cerr << "error: " << job.file << ": " << e.what() << "\n";
    return 2;  // nothing was trained
  } catch (const training::TrainError& e) {
    std::cerr << "error: " << job.file << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int TrainCommand(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--out", "--seed", "--set"}, {"--resume", "--quiet"});
  if (a.positional.size() != 1) throw UsageError("train needs exactly one training file");
  TrainJob job;
  job.file = a.positional[0];
  job.seed = a.Get("--seed");
  job.out = a.Get("--out");
  job.sets = a.All("--set");
  job.resume = a.Has("--resume");
  job.quiet = a.Has("--quiet");
  return Train(job);
}

int TrainAllCommand(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--set"}, {"--quiet"});
  if (a.positional.empty())
    throw UsageError("train-all needs training files (FILE.yaml or FILE.yaml@SEED)");
  std::vector<TrainJob> jobs;
  for (const std::string& entry : a.positional) {
    TrainJob job;
    const auto at = entry.rfind('@');
    job.file = entry.substr(0, at);
    if (at != std::string::npos) {
      job.seed = entry.substr(at + 1);
      // Checked before any rank starts, so a typo stops the whole campaign at once.
      if (!ParseSeed(*job.seed)) {
        throw UsageError("'" + entry + "': the seed after '@' must be " + kSeedRange);
      }
    }
    job.sets = a.All("--set");
    job.quiet = a.Has("--quiet");
    job.campaign = true;
    jobs.push_back(job);
  }
  // Every file is read and its training built (as validate does) before any training starts:
  // a typo, a missing weights or world file in the fifth file stopped the campaign only after
  // four trainings (hours) had run.
  int bad_files = 0;
  std::map<std::filesystem::path, std::string> entry_of_folder;
  for (size_t i = 0; i < jobs.size(); ++i) {
    const TrainJob& job = jobs[i];
    PluginRegistry registry;
    training::TrainSpecLoadResult loaded = training::LoadTrainSpec(job.file, registry, job.sets);
    if (!loaded.spec) {
      ReportTrainSpecErrors(job.file, "train-all", loaded.errors, false);
      ++bad_files;
      continue;
    }
    ApplySeed(job, &*loaded.spec);  // the seed the training will run with
    // Two entries of one folder: the second failed after the first had trained (hours), or,
    // on two ranks, at the folder's lock.
    const std::filesystem::path out = OutDir(job, *loaded.spec).lexically_normal();
    const auto [it, inserted] = entry_of_folder.emplace(out, a.positional[i]);
    if (!inserted) {
      std::cerr << "error: " << a.positional[i] << ": its folder '" << out.string()
                << "' is also that of " << it->second
                << "; give each training its own name: (or another @SEED)\n";
      ++bad_files;
      continue;
    }
    try {
      training::PreflightTraining(*loaded.spec, registry);
    } catch (const training::TrainError& e) {
      std::cerr << "error: " << job.file << ": " << e.what() << "\n";
      ++bad_files;
    }
  }
  if (bad_files > 0) {
    std::cerr << "train-all: " << bad_files << " of " << jobs.size()
              << " training file(s) have errors; nothing was trained\n";
    return 2;
  }
  // Rank r takes trainings r, r + R, r + 2R, ... of the list (every rank derives the same split).
  const ProcessGroup group;
  int failed = 0;
  for (size_t i = static_cast<size_t>(group.rank()); i < jobs.size();
       i += static_cast<size_t>(group.size())) {
    std::cout << "train-all: rank " << group.rank() << " of " << group.size() << ": "
              << a.positional[i] << std::endl;
    const int code = Train(jobs[i]);
    if (code == 130) return 130;  // interrupted: the checkpoint is written, a relaunch resumes
    if (code != 0) ++failed;
  }
  const bool all_ok = group.AllOk(failed == 0);
  if (group.rank() == 0) {
    std::cout << "train-all: " << jobs.size() << " training(s) over " << group.size()
              << " process(es): " << (all_ok ? "all finished" : "some failed (see above)") << "\n";
  }
  return all_ok ? 0 : 1;
}

}  // namespace crowdsim::cli
