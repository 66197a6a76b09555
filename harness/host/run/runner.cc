#include "crowdsim/bench/runner.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <system_error>
#include <thread>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/input_files.h"
#include "crowdsim/bench/row_instance.h"
#include "crowdsim/version.h"
#include "run/episode_appender.h"
#include "run/episode_wire.h"
#include "run/output_folder.h"
#include "run/run_progress.h"
#include "run/slow_episode_watch.h"
#include "run/stored_episodes.h"
#include "run/suite_row.h"
#include "run/worker_process.h"
#include "spec/config_text.h"

namespace crowdsim {
namespace fs = std::filesystem;

std::vector<std::string> PreflightSuite(const Suite& suite, PluginRegistry& registry) {
  std::vector<std::string> errors;
  std::set<std::string> checked;
  for (size_t r = 0; r < suite.rows.size(); ++r) {
    SuiteRow row(suite, r);
    try {
      row.Preflight(registry, suite.episodes, suite.isolation, &checked);
    } catch (const RunError& e) {
      errors.push_back(e.what());
    } catch (const std::exception& e) {
      errors.push_back(row.Place() + ": episode 0 cannot start: " + e.what());
    }
  }
  return errors;
}

RowsRefused::RowsRefused(std::vector<std::string> errors)
    : RunRefused([&errors] {
        std::string joined;
        for (const std::string& e : errors) joined += (joined.empty() ? "" : "\n") + e;
        return joined;
      }()),
      errors_(std::move(errors)) {}

fs::path DefaultRunDir(const Suite& suite) { return fs::path("runs") / suite.name; }

int ShardOfEpisode(std::size_t row, int episode, int episodes, int shards) {
  return static_cast<int>(
             (row * static_cast<std::size_t>(episodes) + static_cast<std::size_t>(episode)) %
             static_cast<std::size_t>(shards)) +
         1;
}

std::string PolicyErrorNote::Format() const {
  return "row '" + row + "': " + std::to_string(errors) + " of " + std::to_string(episodes) +
         " episodes ended in policy_error; " + First();
}

std::string PolicyErrorNote::First() const {
  return "episode " + std::to_string(first_episode) + ": " + first_error;
}

namespace {

/// The (row, episode) pairs a run covers: each row's first `episodes`, or the shard's slice.
struct RunScope {
  int episodes = 0;
  int shard_index = 1;
  int shards = 1;

  bool Covers(size_t row, int k) const {
    return ShardOfEpisode(row, k, episodes, shards) == shard_index;
  }
};

RunScope MakeScope(const Suite& suite, const RunOptions& options) {
  RunScope scope;
  scope.episodes = options.episodes > 0 ? options.episodes : suite.episodes;
  scope.shards = std::max(1, options.shard_count);
  scope.shard_index = options.shard_index;
  if (scope.shard_index < 1 || scope.shard_index > scope.shards) {
    throw RunError("shard " + std::to_string(scope.shard_index) + "/" +
                   std::to_string(scope.shards) + " does not exist (shards are numbered 1.." +
                   std::to_string(scope.shards) + ")");
  }
  return scope;
}

fs::path PrepareOutDir(const Suite& suite, const RunOptions& options) {
  const fs::path dir = options.out_dir.empty() ? DefaultRunDir(suite) : options.out_dir;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw RunError("cannot create the output folder '" + dir.string() + "': " + ec.message() +
                   ". Choose another with --out.");
  }
  // A file of its own tests the folder before any table (access() lets root pass where the disk
  // refuses), so the error names --out.
  const fs::path probe = dir / ".crowdsim-bench.write-test";
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw RunError("cannot write in the output folder '" + dir.string() +
                   "': " + std::strerror(errno) + ". Choose another with --out.");
  }
  ::close(fd);
  fs::remove(probe, ec);
  return dir;
}

/// Preflights every row, so bad parameters stop the run before any episode, naming each row at
/// fault; records the worlds' identities.
std::vector<SuiteRow> PreflightRows(const Suite& suite, PluginRegistry& registry, RunFacts* facts,
                                    IsolationMode mode, double slow_note_s) {
  std::vector<SuiteRow> rows;
  std::vector<std::string> errors;
  std::set<std::string> checked;
  for (size_t r = 0; r < suite.rows.size(); ++r) {
    rows.emplace_back(suite, r);
    try {
      rows.back().Preflight(registry, facts->episodes, mode, &checked, slow_note_s);
      facts->world_identities[suite.rows[r].label] = rows.back().world()->Identity();
    } catch (const RunError& e) {
      errors.push_back(e.what());
    }
  }
  if (!errors.empty()) throw RowsRefused(std::move(errors));
  return rows;
}

std::string EpisodesCsvText(const std::vector<const EpisodeLine*>& lines, MetricFamilies social) {
  std::string text = EpisodeCsvHeader(social) + "\n";
  for (const EpisodeLine* line : lines) text += FormatEpisodeLine(*line, social) + "\n";
  return text;
}

struct Task {
  int row;
  int episode;
};

/// The episodes of the scope still to run; `resumed` counts those already stored.
std::vector<Task> PendingTasks(const Suite& suite, const RunScope& scope, const EpisodeLines& done,
                               int* resumed) {
  std::vector<Task> tasks;
  *resumed = 0;
  for (size_t r = 0; r < suite.rows.size(); ++r) {
    for (int k = 0; k < scope.episodes; ++k) {
      if (!scope.Covers(r, k)) continue;
      if (done.count({suite.rows[r].label, k})) {
        ++*resumed;
      } else {
        tasks.push_back({static_cast<int>(r), k});
      }
    }
  }
  return tasks;
}

/// Per row with policy_error episodes among `done`: their count and the first one's message.
std::vector<PolicyErrorNote> PolicyErrorNotes(const Suite& suite, const EpisodeLines& done) {
  std::vector<PolicyErrorNote> notes;
  for (const RowSpec& row : suite.rows) {
    PolicyErrorNote note;
    note.row = row.label;
    const EpisodeLine* first = nullptr;
    for (auto it = done.lower_bound({row.label, 0});
         it != done.end() && it->first.first == row.label; ++it) {
      ++note.episodes;
      if (it->second.outcome.status != EpisodeStatus::kPolicyError) continue;
      ++note.errors;
      if (first == nullptr) first = &it->second;
    }
    if (first == nullptr) continue;
    note.first_episode = first->episode;
    note.first_error = first->outcome.error;
    notes.push_back(std::move(note));
  }
  return notes;
}

/// Finished episodes go to episodes.csv (within `max_delay`), the progress line and `done`. Not
/// thread-safe.
class EpisodeSink {
 public:
  EpisodeSink(const fs::path& episodes_csv, MetricFamilies social,
              std::chrono::milliseconds max_delay, Progress& progress, EpisodeLines* done)
      : path_(episodes_csv),
        social_(social),
        out_(episodes_csv, max_delay),
        progress_(progress),
        done_(done) {}

  /// False when the append fails (full disk, lost mount), the cause in *why; written lines stay,
  /// and resume skips a cut last line.
  bool Add(EpisodeLine line, std::string* why) {
    if (!out_.Append(FormatEpisodeLine(line, social_), why)) return false;
    progress_.Episode(line.outcome.status == EpisodeStatus::kSuccess);
    (*done_)[{line.row, line.episode}] = std::move(line);
    return true;
  }

  /// Writes pending lines, ends the progress line; throws RunError with `failure` (or the failed
  /// write) if stopped early.
  void Finish(std::string failure) {
    std::string why;
    if (!out_.Finish(&why) && failure.empty()) failure = why;
    progress_.Finish();
    if (!failure.empty()) {
      throw RunError(failure + " (finished episodes are kept in " + path_.string() +
                     "; rerun to resume)");
    }
  }

 private:
  fs::path path_;
  MetricFamilies social_;
  EpisodeAppender out_;
  Progress& progress_;
  EpisodeLines* done_;
};

// The failure of a run whose RunOptions::stop_requested said stop.
constexpr const char* kStopped = "stopped on request";

/// Runs the tasks on `jobs` threads with their own plugin instances. Throws RunError naming the
/// first failing episode or append.
void RunTasksInThreads(const std::vector<SuiteRow>& rows, PluginRegistry& registry,
                       const std::vector<Task>& tasks, int jobs, const RunOptions& options,
                       EpisodeSink& sink) {
  const std::function<bool()>& stop_requested = options.stop_requested;
  // No more threads than episodes; a thread the system refuses stops the run, named.
  const int workers = static_cast<int>(std::min<size_t>(std::max(jobs, 1), tasks.size()));
  SlowEpisodeWatch watch(workers, options.slow_episode_note_s);
  std::mutex mutex;
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::string failure;
  auto worker = [&](int index) {
    std::vector<std::unique_ptr<RowInstance>> instances(rows.size());
    while (!failed) {
      if (stop_requested && stop_requested()) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failed) failure = kStopped;
        failed = true;
        break;
      }
      const size_t t = next.fetch_add(1);
      if (t >= tasks.size()) break;
      const Task task = tasks[t];
      const SuiteRow& row = rows[task.row];
      EpisodeLine line;
      watch.Began(index, row.Where(task.episode));
      try {
        auto& inst = instances[task.row];
        if (!inst) inst = std::make_unique<RowInstance>(row.spec(), registry);
        line = row.Run(*inst, task.episode);
        watch.Ended(index);
      } catch (const std::exception& e) {
        watch.Ended(index);
        std::lock_guard<std::mutex> lock(mutex);
        if (!failed) failure = row.Where(task.episode) + ": " + e.what();
        failed = true;
        break;
      }
      std::lock_guard<std::mutex> lock(mutex);
      std::string why;
      if (!sink.Add(std::move(line), &why)) {
        if (!failed) failure = why;
        failed = true;
        break;
      }
    }
  };
  std::vector<std::thread> threads;
  for (int j = 1; j < workers && !failed; ++j) {
    try {
      threads.emplace_back(worker, j);
    } catch (const std::system_error& e) {
      std::lock_guard<std::mutex> lock(mutex);
      failure = "cannot start worker thread " + std::to_string(j + 1) + " of " +
                std::to_string(workers) + " (" + e.what() + "); rerun with fewer --jobs";
      failed = true;
    }
  }
  if (!failed) worker(0);
  for (auto& th : threads) th.join();
  sink.Finish(failure);
}

/// Runs the tasks in `jobs` worker processes: an episode whose worker dies or exceeds
/// episode_timeout_s is policy_crash / policy_timeout, named on stderr, and the run goes on.
/// Throws as RunTasksInThreads, and when a worker is stopped from outside (SIGINT, SIGTERM,
/// SIGHUP).
void RunTasksInProcesses(const Suite& suite, const std::vector<SuiteRow>& rows,
                         PluginRegistry& registry, const std::vector<Task>& tasks, int jobs,
                         const RunOptions& run, EpisodeSink& sink) {
  const std::function<bool()>& stop_requested = run.stop_requested;
  std::vector<std::unique_ptr<RowInstance>> instances(rows.size());  // a worker's own
  std::string failure;
  WorkerPoolCallbacks callbacks;
  callbacks.run = [&](size_t t) -> std::string {
    const Task task = tasks[t];
    const SuiteRow& row = rows[task.row];
    try {
      auto& inst = instances[task.row];
      if (!inst) inst = std::make_unique<RowInstance>(row.spec(), registry);
      std::string bytes = "L";
      bytes += EncodeEpisodeLine(row.Run(*inst, task.episode));
      return bytes;
    } catch (const std::exception& e) {
      return "E" + row.Where(task.episode) + ": " + e.what();
    }
  };
  callbacks.done = [&](size_t, const std::string& bytes) {
    if (bytes.starts_with("E")) {
      failure = bytes.substr(1);
      return false;
    }
    if (!sink.Add(DecodeEpisodeLine(std::string_view(bytes).substr(1)), &failure)) return false;
    if (stop_requested && stop_requested()) {
      failure = kStopped;
      return false;
    }
    return true;
  };
  callbacks.lost = [&](size_t t, const WorkerLoss& loss) {
    const Task task = tasks[t];
    const SuiteRow& row = rows[task.row];
    if (loss.Interrupted()) {
      failure = row.Where(task.episode) + ": its worker process was " + loss.Describe() +
                " from outside the run";
      return false;
    }
    EpisodeLine line = row.Lost(task.episode, loss);
    std::fprintf(stderr, "%s (rows[%d]): %s; recorded as %s, the run goes on\n",
                 row.Where(task.episode).c_str(), task.row, line.outcome.error.c_str(),
                 EpisodeStatusName(line.outcome.status));
    return sink.Add(std::move(line), &failure);
  };
  WorkerPoolOptions options;
  options.workers = jobs;  // RunInWorkerProcesses starts no more than the tasks
  // The suite's bound, else a default one: a hung plugin costs an episode, never the run.
  options.task_timeout_s =
      suite.episode_timeout_s > 0 ? suite.episode_timeout_s : run.default_episode_timeout_s;
  try {
    RunInWorkerProcesses(tasks.size(), options, callbacks);
  } catch (const std::runtime_error& e) {
    failure = e.what();
  }
  sink.Finish(failure);
}

/// Whether episodes run in worker processes: `isolation` (suite's or the run's override); auto
/// means a timeout or a foreign plugin.
bool Isolated(const Suite& suite, const RunOptions& options) {
  const IsolationMode mode = options.isolation.value_or(suite.isolation);
  if (mode == IsolationMode::kOff && suite.episode_timeout_s > 0) {
    char seconds[32];
    std::snprintf(seconds, sizeof(seconds), "%g", suite.episode_timeout_s);
    throw RunError("suite '" + suite.name + "' (" + suite.file.string() +
                   ") sets episode_timeout_s " + seconds +
                   " but the run's isolation is off; a timeout needs isolated episodes: drop the "
                   "isolation override or the timeout");
  }
  return std::any_of(suite.rows.begin(), suite.rows.end(),
                     [&](const RowSpec& row) { return RowNeedsIsolation(suite, row, mode); });
}

/// Result files without episodes.csv are no resumable run, and a run would replace them: refused
/// unless --fresh.
void RefuseForeignResults(const fs::path& dir) {
  std::error_code ec;
  if (fs::exists(fs::symlink_status(dir / "episodes.csv", ec))) return;
  std::string held;
  for (const char* name : {"table.md", "table.csv", "manifest.json"}) {
    if (fs::exists(fs::symlink_status(dir / name, ec)))
      held += (held.empty() ? "" : ", ") + std::string(name);
  }
  if (held.empty()) return;
  throw RunRefused("'" + dir.string() + "' holds " + held +
                   " but no episodes.csv: no run's episodes to resume, and this run would replace "
                   "them; give --fresh to replace them, or choose another --out");
}

/// A shard's files: its episodes in (row, episode) order and its manifest; `merge` writes the
/// tables.
void WriteShardFiles(const Suite& suite, const RunScope& scope, const EpisodeLines& done,
                     const RunFacts& facts, RunSummary* summary) {
  std::vector<const EpisodeLine*> lines;
  for (size_t r = 0; r < suite.rows.size(); ++r) {
    for (int k = 0; k < scope.episodes; ++k) {
      if (scope.Covers(r, k)) lines.push_back(&done.at({suite.rows[r].label, k}));
    }
  }
  WriteFileAtomically(summary->out_dir / "episodes.csv",
                      EpisodesCsvText(lines, suite.social_metrics));
  WriteFileAtomically(summary->out_dir / "manifest.json", FormatManifestJson(suite, {}, facts));
  summary->table_markdown = "shard " + facts.shard + " of suite " + suite.name + ": " +
                            std::to_string(summary->episodes_resumed + summary->episodes_run) +
                            " episodes; join the shards with `crowdsim-bench merge`\n";
}

/// A run's files: episodes in (row, episode) order for any job count (extra stored episodes kept),
/// tables and manifest.
void WriteRunFiles(const Suite& suite, const RunScope& scope, const EpisodeLines& done,
                   const RunFacts& facts, RunSummary* summary) {
  std::vector<const EpisodeLine*> lines;
  std::set<std::string> labels;
  for (const auto& row : suite.rows) {
    std::vector<EpisodeOutcome> records;
    for (int k = 0; k < scope.episodes; ++k) {
      const EpisodeLine& line = done.at({row.label, k});
      lines.push_back(&line);
      records.push_back(line.outcome);
    }
    labels.insert(row.label);
    summary->rows.push_back(TableRow{&row, Aggregate(records, suite.sim.time_limit)});
  }
  for (const auto& [key, line] : done) {
    if (labels.count(key.first) && key.second >= scope.episodes) lines.push_back(&line);
  }
  WriteFileAtomically(summary->out_dir / "episodes.csv",
                      EpisodesCsvText(lines, suite.social_metrics));
  AddSummaryLines(suite, &summary->rows);
  summary->table_markdown = FormatTableMarkdown(suite, summary->rows);
  WriteFileAtomically(summary->out_dir / "table.md", summary->table_markdown);
  WriteFileAtomically(summary->out_dir / "table.csv", FormatTableCsv(suite, summary->rows));
  WriteFileAtomically(summary->out_dir / "manifest.json",
                      FormatManifestJson(suite, summary->rows, facts));
}

}  // namespace

RunSummary RunSuite(const Suite& suite, PluginRegistry& registry, const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  const RunScope scope = MakeScope(suite, options);
  RunFacts facts;
  facts.started_utc = NowUtc();
  facts.jobs = std::max(1, options.jobs);
  facts.episodes = scope.episodes;
  facts.isolated = Isolated(suite, options);
  facts.merged = options.merge;
  if (scope.shards > 1)
    facts.shard = std::to_string(scope.shard_index) + "/" + std::to_string(scope.shards);

  RunSummary summary;
  // Before the folder is made.
  std::vector<SuiteRow> rows =
      PreflightRows(suite, registry, &facts, options.isolation.value_or(suite.isolation),
                    options.slow_episode_note_s);
  std::vector<std::shared_ptr<WorldSource>> worlds;
  for (const SuiteRow& row : rows) worlds.push_back(row.world());
  summary.out_dir = PrepareOutDir(suite, options);
  if (options.record) {
    for (SuiteRow& row : rows) row.RecordTo(summary.out_dir / "logs");
  }
  std::vector<fs::path> outputs;
  for (const char* name :
       {"episodes.csv", "manifest.json", "table.md", "table.csv", "episodes.dropped.csv"})
    outputs.push_back(summary.out_dir / name);
  if (const std::string over = OutputOverAnInput(outputs, SuiteInputFiles(suite)); !over.empty())
    throw RunRefused(over);
  std::string refused;
  const auto lock = options.out_dir_claimed
                        ? nullptr
                        : ClaimOutputFolder(summary.out_dir, "a suite run", &refused);
  if (!lock && !options.out_dir_claimed) throw RunRefused(refused);
  if (!options.fresh) RefuseForeignResults(summary.out_dir);
  if (options.fresh) {
    // --fresh discards the stored results, those set aside by earlier reruns with them.
    std::error_code ec;
    fs::remove(summary.out_dir / "episodes.dropped.csv", ec);
  }
  EpisodeLines done =
      options.fresh ? EpisodeLines{}
                    : StoredEpisodes(suite, worlds, {summary.out_dir, facts.shard, scope.episodes},
                                     options.progress);
  // Rewrite the stored lines cleanly (drops a line cut short by a crash), then append.
  std::vector<const EpisodeLine*> stored;
  for (const auto& [key, line] : done) stored.push_back(&line);
  WriteFileAtomically(summary.out_dir / "episodes.csv",
                      EpisodesCsvText(stored, suite.social_metrics));
  WriteFileAtomically(summary.out_dir / "manifest.json", FormatManifestJson(suite, {}, facts));
  // No table until the run finishes: an older one would pass for this run's result if it is cut
  // short. Shards write none.
  std::error_code ec;
  fs::remove(summary.out_dir / "table.md", ec);
  fs::remove(summary.out_dir / "table.csv", ec);

  const std::vector<Task> tasks = PendingTasks(suite, scope, done, &summary.episodes_resumed);
  // A shard's counts are its slice's: the line says whose (an MPI rank's line, rank 0's).
  Progress progress(scope.shards > 1 ? suite.name + " shard " + facts.shard : suite.name,
                    static_cast<int>(tasks.size()) + summary.episodes_resumed,
                    summary.episodes_resumed, options.progress);
  // Threads write lines within 200 ms (a crash loses at most that). Workers already pay a pipe
  // round trip per episode, and no thread of ours may live across fork: write at once.
  EpisodeSink sink(
      summary.out_dir / "episodes.csv", suite.social_metrics,
      facts.isolated ? std::chrono::milliseconds(0) : EpisodeAppender::kThreadedRunDelay, progress,
      &done);
  if (facts.isolated) {
    RunTasksInProcesses(suite, rows, registry, tasks, facts.jobs, options, sink);
  } else {
    RunTasksInThreads(rows, registry, tasks, facts.jobs, options, sink);
  }
  summary.episodes_run = static_cast<int>(tasks.size());
  summary.policy_errors = PolicyErrorNotes(suite, done);

  facts.finished_utc = NowUtc();
  facts.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  if (scope.shards > 1) {
    WriteShardFiles(suite, scope, done, facts, &summary);
  } else {
    WriteRunFiles(suite, scope, done, facts, &summary);
  }
  return summary;
}

void FlushPendingEpisodesForSignal() noexcept { EpisodeAppender::FlushForSignal(); }

}  // namespace crowdsim
