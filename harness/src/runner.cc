#include "crowdsim/runner.h"

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
#include <thread>

#include "crowdsim/episode.h"
#include "crowdsim/row_instance.h"
#include "crowdsim/version.h"

namespace crowdsim {
namespace fs = std::filesystem;

namespace {

/// Progress on stderr: rewritten in place on a terminal, a line every 10% otherwise.
class Progress {
 public:
  Progress(std::string name, int total, int already, bool enabled)
      : name_(std::move(name)), total_(total), done_(already), start_done_(already),
        enabled_(enabled), tty_(isatty(STDERR_FILENO)), start_(Clock::now()) {}

  void Episode(bool success) {
    ++done_;
    ++run_;
    if (success) ++success_;
    if (!enabled_) return;
    const auto now = Clock::now();
    const int decile = total_ > 0 ? done_ * 10 / total_ : 10;
    if (tty_ ? (now - last_ > std::chrono::milliseconds(200) || done_ == total_)
             : (decile != last_decile_)) {
      last_ = now;
      last_decile_ = decile;
      Print(now);
    }
  }

  void Finish() {
    if (enabled_ && tty_) std::fprintf(stderr, "\n");
  }

 private:
  using Clock = std::chrono::steady_clock;
  void Print(Clock::time_point now) {
    const double secs = std::chrono::duration<double>(now - start_).count();
    const double rate = secs > 0 ? run_ / secs : 0.0;
    const double eta = rate > 0 ? (total_ - done_) / rate : 0.0;
    std::fprintf(stderr, "%s[%s] %d/%d episodes  %.1f ep/s  ETA %.0fs  success so far %.3f%s",
                 tty_ ? "\r" : "", name_.c_str(), done_, total_, rate, eta,
                 run_ > 0 ? static_cast<double>(success_) / run_ : 0.0, tty_ ? "   " : "\n");
    std::fflush(stderr);
  }

  std::string name_;
  int total_, done_, start_done_, run_ = 0, success_ = 0;
  bool enabled_, tty_;
  Clock::time_point start_, last_{};
  int last_decile_ = -1;
};

/// Builds row `r`'s world, sensors and policies once, checks that the robot has the sensors
/// it needs, and makes and checks episode 0's scenario as the run does (a world too small for
/// the row's humans fails here, in `validate` too); returns the world. Throws RunError naming
/// the row.
std::shared_ptr<WorldSource> PreflightRow(const Suite& suite, size_t r, PluginRegistry& registry) {
  const RowSpec& row = suite.rows[r];
  const std::string where = "row '" + row.label + "' (rows[" + std::to_string(r) + "])";
  try {
    auto world = registry.MakeWorld(*row.world.loaded, row.world.params);
    RowInstance probe(row, registry);
    probe.Agents(1);
    const PolicyNeeds needs = probe.robot().Needs();
    for (const auto& needed : needs.sensors) {
      const bool have = std::any_of(row.sensors.begin(), row.sensors.end(), [&](const PluginUse& s) {
        return s.loaded->descriptor->name == needed;
      });
      if (!have) {
        throw RunError(where + ": policy '" + row.policy.plugin + "' needs the sensor '" + needed +
                       "'; add it to the row's sensors list");
      }
    }
    try {
      CheckScenario(world->Make(MakeEpisodeRequest(suite, row, *world, 0)), suite.sim);
    } catch (const std::exception& e) {
      throw RunError(where + ": the scenario of episode 0 cannot be made: " + e.what());
    }
    return world;
  } catch (const PluginError& e) {
    throw RunError(where + ": " + e.what());
  }
}

}  // namespace

std::vector<std::string> PreflightSuite(const Suite& suite, PluginRegistry& registry) {
  std::vector<std::string> errors;
  for (size_t r = 0; r < suite.rows.size(); ++r) {
    try {
      PreflightRow(suite, r, registry);
    } catch (const RunError& e) {
      errors.push_back(e.what());
    }
  }
  return errors;
}

fs::path DefaultRunDir(const Suite& suite) { return fs::path("runs") / suite.name; }

RunSummary RunSuite(const Suite& suite, PluginRegistry& registry, const RunOptions& options) {
  const auto wall_start = std::chrono::steady_clock::now();
  RunFacts facts;
  facts.started_utc = NowUtc();
  facts.jobs = std::max(1, options.jobs);
  const int episodes = options.episodes > 0 ? options.episodes : suite.episodes;
  facts.episodes = episodes;
  const int shards = std::max(1, options.shard_count);
  if (options.shard_index < 1 || options.shard_index > shards) {
    throw RunError("shard " + std::to_string(options.shard_index) + "/" + std::to_string(shards) +
                   " does not exist (shards are numbered 1.." + std::to_string(shards) + ")");
  }
  if (shards > 1) facts.shard = std::to_string(options.shard_index) + "/" + std::to_string(shards);
  auto in_shard = [&](size_t row, int k) {
    return (row * static_cast<size_t>(episodes) + static_cast<size_t>(k)) % static_cast<size_t>(shards) ==
           static_cast<size_t>(options.shard_index - 1);
  };

  RunSummary summary;
  summary.out_dir = options.out_dir.empty() ? DefaultRunDir(suite) : options.out_dir;
  std::error_code ec;
  fs::create_directories(summary.out_dir, ec);
  if (ec || !fs::is_directory(summary.out_dir)) {
    throw RunError("cannot create the output folder '" + summary.out_dir.string() + "': " +
                   ec.message() + ". Choose another with --out.");
  }
  const fs::path episodes_csv = summary.out_dir / "episodes.csv";
  const fs::path manifest = summary.out_dir / "manifest.json";

  // Preflight: build every row's objects once, so a bad parameter stops the run before any
  // episode, with the plugin's own message.
  std::vector<std::shared_ptr<WorldSource>> worlds;
  for (size_t r = 0; r < suite.rows.size(); ++r) {
    worlds.push_back(PreflightRow(suite, r, registry));
    facts.world_identities[suite.rows[r].label] = worlds.back()->Identity();
  }

  // Resume: keep the finished episodes of the same configuration.
  std::map<std::pair<std::string, int>, EpisodeLine> done;
  if (fs::exists(episodes_csv) && !options.fresh) {
    const std::string stored = ReadManifestField(manifest, "config_hash");
    // Rows can be resumed one by one: those whose own hash is unchanged keep their episodes
    // when others were added or changed (a table that grows row by row).
    std::set<std::string> kept;
    if (stored == suite.ConfigHash()) {
      for (const RowSpec& row : suite.rows) kept.insert(row.label);
    } else {
      const std::vector<std::string> row_hashes = ReadManifestStrings(manifest, "row_hashes");
      const std::set<std::string> stored_rows(row_hashes.begin(), row_hashes.end());
      for (const RowSpec& row : suite.rows) {
        if (stored_rows.count(row.ConfigHash() + " " + row.label)) kept.insert(row.label);
      }
      if (kept.empty()) {
        throw RunError("'" + summary.out_dir.string() + "' holds results of a different configuration "
                       "of this suite (config hash " + (stored.empty() ? "unknown" : stored) +
                       ", now " + suite.ConfigHash() + ", and no row is unchanged). Pass --fresh to "
                       "replace them, or --out to write elsewhere.");
      }
      if (options.progress) {
        std::string rerun;
        for (const RowSpec& row : suite.rows) {
          if (!kept.count(row.label)) rerun += (rerun.empty() ? "" : ", ") + row.label;
        }
        std::fprintf(stderr, "note: the suite changed since '%s' was written: %zu unchanged row(s) "
                     "resume, new or changed rows run from scratch: %s\n",
                     summary.out_dir.string().c_str(), kept.size(), rerun.c_str());
      }
    }
    EpisodesCsvRead stored_lines;
    try {
      stored_lines = ReadEpisodesCsvChecked(episodes_csv);
    } catch (const std::runtime_error& e) {
      throw RunError(e.what());
    }
    if (stored_lines.damaged > 0 && options.progress) {
      std::fprintf(stderr, "note: %d damaged line(s) of %s skipped, their episodes run again (the first: %s)\n",
                   stored_lines.damaged, episodes_csv.string().c_str(), stored_lines.first_damage.c_str());
    }
    for (auto& line : stored_lines.lines) {
      if (kept.count(line.row)) done[{line.row, line.episode}] = std::move(line);
    }
    const std::string commit = ReadManifestField(manifest, "git_commit");
    if (!done.empty() && options.progress && commit != GitCommit()) {
      std::fprintf(stderr,
                   "note: resuming %zu stored episodes made by commit %s; this is %s. Pass --fresh "
                   "to rerun them with this build.\n",
                   done.size(), commit.empty() ? "unknown" : commit.c_str(), GitCommit());
    }
  }
  // Rewrite the stored lines cleanly (drops a line cut short by a crash), then append.
  {
    std::string text = EpisodeCsvHeader() + "\n";
    for (const auto& [key, line] : done) text += FormatEpisodeLine(line) + "\n";
    WriteFileAtomically(episodes_csv, text);
    WriteFileAtomically(manifest, FormatManifestJson(suite, {}, facts));
  }

  struct Task {
    int row;
    int episode;
  };
  std::vector<Task> tasks;
  int resumed = 0;
  for (size_t r = 0; r < suite.rows.size(); ++r) {
    for (int k = 0; k < episodes; ++k) {
      if (!in_shard(r, k)) continue;
      if (done.count({suite.rows[r].label, k})) {
        ++resumed;
      } else {
        tasks.push_back({static_cast<int>(r), k});
      }
    }
  }
  summary.episodes_resumed = resumed;

  std::ofstream out(episodes_csv, std::ios::app);
  if (!out) throw RunError("cannot append to " + episodes_csv.string());
  std::mutex mutex;
  std::atomic<size_t> next{0};
  std::atomic<bool> failed{false};
  std::string failure;
  Progress progress(suite.name, static_cast<int>(tasks.size()) + resumed, resumed, options.progress);

  auto worker = [&]() {
    std::vector<std::unique_ptr<RowInstance>> instances(suite.rows.size());
    while (!failed) {
      const size_t t = next.fetch_add(1);
      if (t >= tasks.size()) break;
      const Task task = tasks[t];
      const RowSpec& row = suite.rows[task.row];
      EpisodeLine line;
      line.row = row.label;
      line.episode = task.episode;
      try {
        auto& inst = instances[task.row];
        if (!inst) inst = std::make_unique<RowInstance>(row, registry);
        const WorldSource& world = *worlds[task.row];
        const ScenarioRequest req = MakeEpisodeRequest(suite, row, world, task.episode);
        const Scenario scenario = world.Make(req);
        Episode episode(scenario, suite.sim, inst->Agents(scenario.humans.size()));
        const EpisodeResult& result = episode.Run();
        line.seed = req.seed;
        line.layout = scenario.layout;
        line.record = ToRecord(result);
        line.humans_at_goal = result.humans_at_goal;
        line.error = result.error;
      } catch (const std::exception& e) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failed) failure = "row '" + row.label + "', episode " + std::to_string(task.episode) + ": " + e.what();
        failed = true;
        break;
      }
      std::lock_guard<std::mutex> lock(mutex);
      out << FormatEpisodeLine(line) << "\n";
      out.flush();
      if (!out) {
        // A full disk or a lost mount: stop at once, naming the cause (the lines written so
        // far stay; a cut last line is skipped when the run resumes).
        if (!failed) failure = "cannot append to " + episodes_csv.string() + ": " + std::strerror(errno);
        failed = true;
        break;
      }
      progress.Episode(line.record.status == EpisodeStatus::kSuccess);
      done[{line.row, line.episode}] = std::move(line);
    }
  };
  std::vector<std::thread> threads;
  for (int j = 1; j < facts.jobs; ++j) threads.emplace_back(worker);
  worker();
  for (auto& th : threads) th.join();
  progress.Finish();
  out.close();
  if (failed) throw RunError(failure + " (finished episodes are kept in " + episodes_csv.string() + "; rerun to resume)");
  summary.episodes_run = static_cast<int>(tasks.size());

  if (shards > 1) {
    // A shard: its episodes in (row, episode) order and a manifest saying which shard; the
    // tables come from `merge`.
    std::string text = EpisodeCsvHeader() + "\n";
    for (size_t r = 0; r < suite.rows.size(); ++r) {
      for (int k = 0; k < episodes; ++k) {
        if (in_shard(r, k)) text += FormatEpisodeLine(done.at({suite.rows[r].label, k})) + "\n";
      }
    }
    WriteFileAtomically(episodes_csv, text);
    fs::remove(summary.out_dir / "table.md", ec);
    fs::remove(summary.out_dir / "table.csv", ec);
    facts.finished_utc = NowUtc();
    facts.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    WriteFileAtomically(manifest, FormatManifestJson(suite, {}, facts));
    summary.table_markdown = "shard " + facts.shard + " of suite " + suite.name + ": " +
                             std::to_string(resumed + summary.episodes_run) +
                             " episodes; join the shards with `crowdsim-bench merge`\n";
    return summary;
  }

  // Final files: episodes in (row, episode) order, so any job count gives the same file.
  std::string text = EpisodeCsvHeader() + "\n";
  std::set<std::string> labels;
  for (const auto& row : suite.rows) {
    std::vector<EpisodeRecord> records;
    for (int k = 0; k < episodes; ++k) {
      const EpisodeLine& line = done.at({row.label, k});
      text += FormatEpisodeLine(line) + "\n";
      records.push_back(line.record);
    }
    labels.insert(row.label);
    summary.rows.push_back(TableRow{&row, Aggregate(records, suite.sim.time_limit)});
  }
  // Keep stored episodes of this configuration beyond the requested count (a later, longer
  // run resumes from them).
  for (const auto& [key, line] : done) {
    if (labels.count(key.first) && key.second >= episodes) text += FormatEpisodeLine(line) + "\n";
  }
  WriteFileAtomically(episodes_csv, text);
  AddSummaryLines(suite, &summary.rows);
  summary.table_markdown = FormatTableMarkdown(suite, summary.rows);
  WriteFileAtomically(summary.out_dir / "table.md", summary.table_markdown);
  WriteFileAtomically(summary.out_dir / "table.csv", FormatTableCsv(suite, summary.rows));
  facts.finished_utc = NowUtc();
  facts.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  WriteFileAtomically(manifest, FormatManifestJson(suite, summary.rows, facts));
  return summary;
}

}  // namespace crowdsim
