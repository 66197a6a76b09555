// run, validate and list-plugins.
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include "commands.h"
#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/bench/runner.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/bench/training/train_spec.h"
#include "crowdsim/bench/training/trainer.h"
#include "crowdsim/cli/args.h"
#include "process_group.h"

namespace crowdsim::cli {

std::optional<Suite> LoadOrReport(const std::string& file, PluginRegistry& registry,
                                  const std::vector<std::string>& overrides,
                                  const std::string& command) {
  SuiteLoadResult r = LoadSuite(file, registry, overrides);
  if (!r.suite) {
    // A training file read as a suite gives an unknown key for each of its own keys (policy,
    // params, sensors, training): what it is says more, as validate tells the two apart.
    const SpecFileKind kind = KindOfSpecFile(file);
    if (kind == SpecFileKind::kTraining) {
      std::cerr << "error: " << file << " is a training file: train it with `crowdsim-bench train "
                << file << "` (" << command
                << " takes a suite, whose rows: list the policies to compare)\n";
      return std::nullopt;
    }
    // A world just imported (floorplan import --out WORLD.yaml) or written by hand.
    if (kind == SpecFileKind::kWorld || kind == SpecFileKind::kWorldSet) {
      std::cerr << "error: " << file << " is a world"
                << (kind == SpecFileKind::kWorldSet ? " set" : "")
                << " file: a suite's world: block names it, e.g. `world: {source: "
                << (kind == SpecFileKind::kWorldSet ? "random_rect" : "floorplan")
                << ", file: " << file << "}` (a path relative to the suite's folder); " << command
                << " takes a suite\n";
      return std::nullopt;
    }
    for (const auto& e : r.errors) std::cerr << "error: " << e.Format() << "\n";
    std::cerr << r.errors.size() << " error" << (r.errors.size() == 1 ? "" : "s") << " in " << file
              << "\n";
  }
  return std::move(r.suite);
}

namespace {

/// The rows of `file` that cannot run, as run and validate say it.
void ReportRowErrors(const std::string& file, const std::vector<std::string>& errors) {
  for (const auto& e : errors) std::cerr << "error: " << file << ": " << e << "\n";
  std::cerr << errors.size() << " row" << (errors.size() == 1 ? "" : "s") << " of " << file
            << " cannot run\n";
}

/// Ctrl-C during a run: write the finished episodes still in memory, say that a rerun resumes,
/// then die of the signal as before (exit status 130 from the shell).
char g_interrupt_message[1024];

extern "C" void OnRunInterrupted(int sig) {
  FlushPendingEpisodesForSignal();
  const ssize_t n = ::write(STDERR_FILENO, g_interrupt_message, std::strlen(g_interrupt_message));
  (void)n;
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

/// `kept`: where the finished episodes are (OUT/episodes.csv; under MPI each rank's folder).
void ExplainInterruption(const std::string& kept) {
  std::snprintf(g_interrupt_message, sizeof(g_interrupt_message),
                "\ninterrupted: the finished episodes are kept in %s; run the command again "
                "without --fresh to resume\n",
                kept.c_str());
  std::signal(SIGINT, OnRunInterrupted);
  std::signal(SIGTERM, OnRunInterrupted);
  std::signal(SIGHUP, OnRunInterrupted);  // a closed terminal or ssh session
}

/// Joins shard folders into `out` (MergeShards), prints the table and what was written; the
/// exit code. `from` says where the episodes came from ("3 folders", "2 MPI ranks").
int MergeAndReport(const std::vector<std::filesystem::path>& dirs, const std::filesystem::path& out,
                   const std::filesystem::path& suite_file, PluginRegistry& registry,
                   const std::string& from, bool allow_mixed_commits = false) {
  try {
    const RunSummary s = MergeShards(dirs, out, suite_file, registry, allow_mixed_commits);
    std::cout << s.table_markdown << "\n";
    std::cerr << "wrote " << (s.out_dir / "table.md").string()
              << ", table.csv, episodes.csv, manifest.json (" << s.episodes_resumed
              << " episodes from " << from << ")\n";
  } catch (const RunRefused& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;  // nothing was merged
  } catch (const RunError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

/// The suite's title on stdout; `this_run`: what the command line changed (--episodes,
/// --set), said beside the description, which the file wrote for its own settings.
void PrintTitle(const Suite& suite, const std::string& this_run) {
  std::cout << "## " << suite.name;
  if (!suite.description.empty()) std::cout << ": " << suite.description;
  if (!this_run.empty()) std::cout << " (this run: " << this_run << ")";
  std::cout << "\n\n";
}

/// What the command line changed in the suite, as it was given.
std::string ThisRun(const Args& a) {
  std::string text;
  if (auto episodes = a.Get("--episodes")) text = "--episodes " + *episodes;
  const std::string sets = SetOptionsText(a.All("--set"));
  if (!sets.empty() && !text.empty()) text += ' ';
  text += sets;
  return text;
}

/// `mpirun -n R crowdsim-bench run`: rank K runs shard K+1 of R into OUT/ranks/<K+1>of<R>/ (its
/// own resumable folder) with its own --jobs threads; once every rank has finished, rank 0
/// merges the shards into OUT exactly as `merge` does, so the tables equal a single run's.
int RunOverRanks(const Suite& suite, PluginRegistry& registry, RunOptions opt,
                 const ProcessGroup& group, const std::string& this_run) {
  const std::filesystem::path out = opt.out_dir.empty() ? DefaultRunDir(suite) : opt.out_dir;
  auto rank_dir = [&](int rank) {
    return out / "ranks" / (std::to_string(rank + 1) + "of" + std::to_string(group.size()));
  };
  opt.out_dir = rank_dir(group.rank());
  opt.shard_index = group.rank() + 1;
  opt.shard_count = group.size();
  opt.progress = opt.progress && group.rank() == 0;
  if (group.rank() == 0) {
    ExplainInterruption(
        (out / "ranks" / ("*of" + std::to_string(group.size())) / "episodes.csv").string());
  }
  bool ok = true, refused = false;
  // One write per message: the ranks share stderr, and std::cerr writes each << at once, so
  // pieces of two ranks' lines interleaved.
  auto say = [&](const std::string& what) {
    const std::string line = "error: rank " + std::to_string(group.rank()) + ": " + what + "\n";
    std::cerr.write(line.data(), static_cast<std::streamsize>(line.size()));
  };
  try {
    RunSuite(suite, registry, opt);
  } catch (const RunRefused& e) {
    say(e.what());
    ok = false;
    refused = true;
  } catch (const std::exception& e) {  // RunError, or a write that failed: never leave early,
    say(e.what());
    ok = false;  // the other ranks wait in the collective calls below
  } catch (...) {
    say("a non-standard exception");
    ok = false;
  }
  // Three collective calls, made by every rank in this order.
  const bool all_ok = group.AllOk(ok);
  const bool none_refused = group.AllOk(!refused);
  const bool all_refused = group.AllOk(refused);
  if (!all_ok) {
    if (group.rank() == 0) {
      const std::string line =
          all_refused ? std::string("error: the run was refused (see above); nothing was run\n")
                      : "error: not every rank finished" +
                            std::string(none_refused ? "" : " (some were refused)") +
                            "; the episodes that ran are kept in " + (out / "ranks").string() +
                            "; fix what is said above and run the same command again to resume\n";
      std::cerr.write(line.data(), static_cast<std::streamsize>(line.size()));
    }
    return all_refused ? 2 : 1;
  }
  if (group.rank() != 0) return 0;
  std::vector<std::filesystem::path> dirs;
  for (int r = 0; r < group.size(); ++r) dirs.push_back(rank_dir(r));
  PrintTitle(suite, this_run);
  return MergeAndReport(dirs, out, suite.file, registry,
                        std::to_string(group.size()) + " MPI ranks");
}

}  // namespace

int RunCommand(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--out", "--jobs", "--episodes", "--shard", "--set"},
                             {"--fresh", "--quiet", "--record"});
  if (a.positional.size() != 1) throw UsageError("run needs exactly one suite file");
  int shard_index = 1, shard_count = 1;
  if (auto shard = a.Get("--shard")) {
    char slash = 0, extra = 0;
    if (std::sscanf(shard->c_str(), "%d%c%d%c", &shard_index, &slash, &shard_count, &extra) != 3 ||
        slash != '/' || shard_count < 1 || shard_count > 1'000'000 || shard_index < 1 ||
        shard_index > shard_count) {
      throw UsageError(
          "--shard needs K/N with 1 <= K <= N (e.g. --shard 2/8, or "
          "--shard $SLURM_ARRAY_TASK_ID/$SLURM_ARRAY_TASK_COUNT with ids from 1), got '" +
          *shard + "'");
    }
  }
  PluginRegistry registry;
  auto suite = LoadOrReport(a.positional[0], registry, a.All("--set"), "run");
  if (!suite) return 2;
  RunOptions opt;
  if (auto out = a.Get("--out")) opt.out_dir = *out;
  const int hw = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  opt.jobs = a.GetInt("--jobs", hw, 1, kMaxJobs);
  opt.episodes = a.GetInt("--episodes", -1, 1, kMaxEpisodes);
  opt.fresh = a.Has("--fresh");
  opt.record = a.Has("--record");
  opt.progress = !a.Has("--quiet");
  opt.shard_index = shard_index;
  opt.shard_count = shard_count;
  const ProcessGroup group;
  if (group.size() > 1) {
    if (a.Has("--shard"))
      throw UsageError("--shard and an MPI launch both split the suite: give one of them");
    return RunOverRanks(*suite, registry, opt, group, ThisRun(a));
  }
  ExplainInterruption(
      ((opt.out_dir.empty() ? DefaultRunDir(*suite) : opt.out_dir) / "episodes.csv").string());
  try {
    RunSummary s = RunSuite(*suite, registry, opt);
    if (shard_count > 1) {
      std::cout << s.table_markdown;  // a shard has no table: what it holds, how to join it
    } else {
      PrintTitle(*suite, ThisRun(a));
      std::cout << s.table_markdown << "\n";
    }
    for (const PolicyErrorNote& note : s.policy_errors) {
      std::cerr << "note: " << note.Format() << "\n";
    }
    if (!s.policy_errors.empty()) {
      std::cerr << "note: every episode's message is in the error column of "
                << (s.out_dir / "episodes.csv").string() << "\n";
    }
    std::cerr << "wrote " << (s.out_dir / (shard_count > 1 ? "episodes.csv" : "table.md")).string()
              << (shard_count > 1 ? ", manifest.json ("
                                  : ", table.csv, episodes.csv, manifest.json (")
              << s.episodes_run << " episodes run, " << s.episodes_resumed << " resumed)\n";
  } catch (const RowsRefused& e) {
    ReportRowErrors(suite->file.string(), e.errors());
    return 2;  // nothing was run
  } catch (const RunRefused& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 2;  // nothing was run
  } catch (const RunError& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

int MergeCommand(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--out", "--suite"}, {"--allow-mixed-commits"});
  if (a.positional.empty()) throw UsageError("merge needs the output folders of the shards");
  const auto out = a.Get("--out");
  if (!out) throw UsageError("merge needs --out DIR (the folder of the joined results)");
  std::vector<std::filesystem::path> dirs(a.positional.begin(), a.positional.end());
  // Every option read before the ranks part: a usage error is then every rank's, not rank 0's
  // alone while the others wait for it.
  const std::string suite_file = a.Get("--suite").value_or("");
  const bool allow_mixed_commits = a.Has("--allow-mixed-commits");
  // Started by mpirun or srun with several ranks (a merge step in an MPI job script): rank 0
  // merges and its exit status is the launch's; the others wait for it and exit 0. (Each rank
  // merging, all but one refused by the output folder's lock, failed the launch.)
  const ProcessGroup group;
  int code = 0;
  if (group.rank() == 0) {
    // Whatever rank 0 meets, it reaches the collective call below: the others wait in it.
    try {
      PluginRegistry registry;
      code = MergeAndReport(dirs, *out, suite_file, registry,
                            std::to_string(dirs.size()) + " folders", allow_mixed_commits);
    } catch (const std::exception& e) {
      std::cerr << "error: " << e.what() << "\n";
      code = 1;
    } catch (...) {
      std::cerr << "error: merge failed with a non-standard exception\n";
      code = 1;
    }
  }
  group.AllOk(code == 0);  // the others leave once rank 0 has finished
  return code;
}

int ValidateCommand(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--set"}, {});
  if (a.positional.empty()) throw UsageError("validate needs at least one suite or training file");
  int status = 0;
  for (const auto& file : a.positional) {
    PluginRegistry registry;
    if (KindOfSpecFile(file) == SpecFileKind::kTraining) {
      training::TrainSpecLoadResult loaded =
          training::LoadTrainSpec(file, registry, a.All("--set"));
      if (!loaded.spec) {
        for (const auto& e : loaded.errors) std::cerr << "error: " << e.Format() << "\n";
        std::cerr << loaded.errors.size() << " error" << (loaded.errors.size() == 1 ? "" : "s")
                  << " in " << file << "\n";
        status = 2;
        continue;
      }
      try {
        training::PreflightTraining(*loaded.spec, registry);
      } catch (const training::TrainError& e) {
        std::cerr << "error: " << file << ": " << e.what() << "\n";
        status = 2;
        continue;
      }
      for (const auto& w : training::TrainSpecWarnings(*loaded.spec)) {
        std::cerr << "warning: " << SpecSource(file, a.All("--set")) << ": " << w << "\n";
      }
      std::cout << file << ": ok (training file: " << loaded.spec->row.policy.plugin << ")\n";
      continue;
    }
    auto suite = LoadOrReport(file, registry, a.All("--set"), "validate");
    if (!suite) {
      status = 2;
      continue;
    }
    // The plugins as `run` builds them: weights, world files, sensors the policies need.
    const std::vector<std::string> errors = PreflightSuite(*suite, registry);
    if (!errors.empty()) {
      ReportRowErrors(file, errors);
      status = 2;
      continue;
    }
    std::cout << file << ": ok (" << suite->rows.size() << " rows x " << suite->episodes
              << " episodes, config hash " << suite->ConfigHash() << ")\n";
  }
  return status;
}

int ListPluginsCommand(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {}, {});
  PluginRegistry registry;
  for (const auto& p : a.positional) {
    try {
      registry.LoadAny(p);
    } catch (const PluginError& e) {
      std::cerr << "error: " << e.what() << "\n";
      return 1;
    }
  }
  std::cout << "plugin folders:";
  for (const auto& d : registry.search_dirs()) std::cout << " " << d.string();
  std::cout << "\n";
  auto found = registry.Discover();
  // A file given that is also found in a plugin folder (its own on CROWDSIM_PLUGIN_PATH) is the
  // same loaded plugin: listed once.
  for (const auto& p : a.positional) {
    const LoadedPlugin* given = &registry.LoadAny(p);
    if (std::find(found.plugins.begin(), found.plugins.end(), given) == found.plugins.end()) {
      found.plugins.push_back(given);
    }
  }
  for (PluginKind kind : {PluginKind::kPolicy, PluginKind::kSensor, PluginKind::kWorld}) {
    std::cout << "\n" << PluginKindName(kind) << " plugins:\n";
    for (const auto* p : found.plugins) {
      if (p->descriptor->kind != kind) continue;
      std::cout << "  " << p->descriptor->name << " - " << p->descriptor->description << "\n"
                << "      file: " << p->path.string() << "\n";
      if (const auto it = found.hidden.find(p); it != found.hidden.end()) {
        for (const auto& f : it->second) std::cout << "      hides: " << f.string() << "\n";
      }
      for (const auto& s : p->schema) {
        // An empty string default is shown as "" (it printed as "default )").
        const auto* text = std::get_if<std::string>(&s.default_value);
        std::cout << "      " << s.name << " (" << ParamTypeName(s.type) << ", default "
                  << (text != nullptr && text->empty() ? "\"\""
                                                       : FormatParamValue(s.default_value));
        if (s.type == ParamType::kInt || s.type == ParamType::kDouble ||
            s.type == ParamType::kDoubleList) {
          if (std::isfinite(s.min) || std::isfinite(s.max)) {
            std::cout << ", range " << (std::isinf(s.min) ? "(" : "[") << s.min << ", " << s.max
                      << (std::isinf(s.max) ? ")" : "]");
          }
        }
        if (!s.choices.empty()) {
          std::cout << ", one of";
          for (const auto& c : s.choices) std::cout << " " << c;
        }
        std::cout << "): " << s.doc << "\n";
      }
    }
  }
  if (!found.problems.empty()) {
    std::cout << "\nfiles that failed to load:\n";
    for (const auto& p : found.problems) std::cout << "  " << p << "\n";
  }
  return 0;
}

}  // namespace crowdsim::cli
