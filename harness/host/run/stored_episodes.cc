#include "run/stored_episodes.h"

#include <cstdio>
#include <fstream>
#include <map>
#include <set>

#include "crowdsim/bench/row_instance.h"
#include "crowdsim/bench/runner.h"
#include "crowdsim/version.h"
#include "results/json_file.h"
#include "spec/config_text.h"

namespace crowdsim {
namespace {

namespace fs = std::filesystem;

/// User plugin files whose content differs from `manifest`'s, as "; plugin files rebuilt since
/// those results: PATH"; "" when none.
std::string DescribeRebuiltPlugins(const fs::path& manifest, const Suite& suite) {
  using Json = nlohmann::ordered_json;
  std::map<std::string, std::string> stored;  // file -> content hash, as recorded
  auto record = [&stored](const Json& use) {
    if (!use.is_object()) return;
    const auto file = use.find("file"), content = use.find("file_content_fnv1a");
    if (file != use.end() && content != use.end() && file->is_string() && content->is_string()) {
      stored[file->get<std::string>()] = content->get<std::string>();
    }
  };
  // A member of an object, null when absent or not an object (a damaged manifest).
  auto member = [](const Json& j, const char* key) {
    return j.is_object() && j.contains(key) ? j.at(key) : Json();
  };
  const Json rows = member(ReadJsonFile(manifest), "rows");
  for (const Json& row : rows.is_array() ? rows : Json::array()) {
    record(member(row, "policy"));
    record(member(row, "world"));
    const Json sensors = member(row, "sensors");
    for (const Json& sensor : sensors.is_array() ? sensors : Json::array()) record(sensor);
    record(member(member(row, "humans"), "policy"));
  }
  std::set<std::string> rebuilt;
  for (const RowSpec& row : suite.rows) {
    for (const auto& [role, use] : RowPlugins(row)) {
      const std::string now = suite_internal::PluginFileContent(*use);
      if (now.empty()) continue;  // the harness's own: covered by its commit
      const auto it = stored.find(use->loaded->path.string());
      if (it != stored.end() && it->second != now) rebuilt.insert(it->first);
    }
  }
  std::string text;
  for (const std::string& file : rebuilt) text += (text.empty() ? "" : ", ") + file;
  return text.empty() ? "" : "; plugin files rebuilt since those results: " + text;
}

/// Rows whose stored episodes match this configuration: all if the suite hash is unchanged, else
/// those with unchanged row hashes. Throws RunError if none.
std::set<std::string> ResumableRows(const Suite& suite, const fs::path& out_dir) {
  const fs::path manifest = out_dir / "manifest.json";
  const std::string stored = ReadManifestField(manifest, "config_hash");
  std::set<std::string> kept;
  if (stored == suite.ConfigHash()) {
    for (const RowSpec& row : suite.rows) kept.insert(row.label);
    return kept;
  }
  if (stored.empty()) {
    std::error_code ec;
    throw RunRefused("'" + out_dir.string() + "' holds episodes, but its manifest.json is " +
                     (fs::exists(manifest, ec) ? "unreadable or has no config_hash" : "missing") +
                     ", so which configuration made them is unknown. Pass --fresh to replace "
                     "them, or --out to write elsewhere.");
  }
  // Another suite's folder: shared rows would resume and the rest move aside, its tables replaced.
  if (const std::string other = ReadManifestField(manifest, "suite");
      !other.empty() && other != suite.name) {
    const std::string other_file = ReadManifestField(manifest, "suite_file");
    throw RunRefused("'" + out_dir.string() + "' holds the results of another suite, '" + other +
                     "'" + (other_file.empty() ? "" : " (" + other_file + ")") +
                     ", not of this suite '" + suite.name + "' (" + suite.file.string() +
                     "). Give this run its own --out folder, or pass --fresh to replace them.");
  }
  const std::vector<std::string> row_hashes = ReadManifestStrings(manifest, "row_hashes");
  const std::set<std::string> stored_rows(row_hashes.begin(), row_hashes.end());
  for (const RowSpec& row : suite.rows) {
    if (stored_rows.count(row.ConfigHash() + " " + row.label)) kept.insert(row.label);
  }
  if (kept.empty()) {
    throw RunRefused("'" + out_dir.string() +
                     "' holds results of a different configuration "
                     "of this suite (config hash " +
                     stored + ", now " + suite.ConfigHash() + ", and no row is unchanged" +
                     DescribeRunInputsDifference(ReadManifestField(manifest, "suite_file"),
                                                 ReadManifestStrings(manifest, "overrides"),
                                                 suite.file.string(), suite.overrides) +
                     DescribeRebuiltPlugins(manifest, suite) +
                     "). Pass --fresh to replace them, or --out to write elsewhere.");
  }
  return kept;
}

/// A shard resumes only its own shard's folder; elsewhere it would drop all episodes outside its
/// slice.
void CheckShard(const ResumeTarget& target) {
  if (target.shard.empty()) return;
  const fs::path manifest = target.out_dir / "manifest.json";
  const std::string stored = ReadManifestField(manifest, "shard");
  const long episodes = ReadManifestInteger(manifest, "episodes");
  if (stored == target.shard && episodes != target.episodes && episodes > 0) {
    // Which episodes a shard holds depends on the count: another count is another slice.
    throw RunRefused("'" + target.out_dir.string() + "' holds shard " + stored + " of " +
                     std::to_string(episodes) + " episodes per row; this run asks for " +
                     std::to_string(target.episodes) +
                     ", another slice of the suite. Rerun it "
                     "with --episodes " +
                     std::to_string(episodes) +
                     ", or give it another --out folder (or pass --fresh to replace it).");
  }
  if (stored == target.shard) return;
  throw RunRefused("'" + target.out_dir.string() + "' holds " + ShardName(stored) +
                   " of this suite, and shard " + target.shard +
                   " would keep only its own episodes there. Give each shard its own --out "
                   "folder (and join them with `crowdsim-bench merge`), or pass --fresh to replace "
                   "the folder's results.");
}

/// Appends `lines` and `damaged` (as read) to episodes.dropped.csv, with a header when new.
fs::path SetAside(const fs::path& out_dir, const std::vector<const EpisodeLine*>& lines,
                  const std::vector<std::string>& damaged, MetricFamilies social) {
  const fs::path path = out_dir / "episodes.dropped.csv";
  const bool fresh = !fs::exists(path);
  std::ofstream out(path, std::ios::app);
  if (fresh) out << EpisodeCsvHeader(social) << "\n";
  for (const EpisodeLine* line : lines) out << FormatEpisodeLine(*line, social) << "\n";
  for (const std::string& line : damaged) out << line << "\n";
  out.flush();
  if (!out) {
    throw RunError("cannot write " + path.string() +
                   " (where the stored episodes this run no longer uses are kept): check the "
                   "disk, or pass --fresh to discard them");
  }
  return path;
}

std::string Quoted(const std::set<std::string>& labels) {
  std::string text;
  for (const std::string& label : labels) text += (text.empty() ? "'" : ", '") + label + "'";
  return text;
}

}  // namespace

EpisodeLines StoredEpisodes(const Suite& suite,
                            const std::vector<std::shared_ptr<WorldSource>>& worlds,
                            const ResumeTarget& target, bool note) {
  EpisodeLines done;
  const fs::path& out_dir = target.out_dir;
  const fs::path episodes_csv = out_dir / "episodes.csv";
  if (!fs::exists(episodes_csv)) return done;
  EpisodesCsvRead stored_lines;
  try {
    stored_lines = ReadEpisodesCsvChecked(episodes_csv);
  } catch (const std::runtime_error& e) {
    throw RunRefused(e.what());  // nothing has run: exit 2, as for other folders that do not fit
  }
  if (stored_lines.lines.empty()) return done;
  const std::set<std::string> kept = ResumableRows(suite, out_dir);
  CheckShard(target);

  std::map<std::string, std::size_t> row_of;  // label -> index in the suite
  for (std::size_t r = 0; r < suite.rows.size(); ++r) row_of[suite.rows[r].label] = r;
  std::vector<const EpisodeLine*> aside;
  std::set<std::string> removed, changed;
  int foreign = 0;
  std::string first_foreign;
  // Episodes stored twice with different outcomes: neither is trusted, both move aside.
  std::map<std::pair<std::string, int>, const EpisodeLine*> kept_line;
  std::set<std::pair<std::string, int>> conflicting;
  int copies = 0;
  for (const EpisodeLine& line : stored_lines.lines) {
    const auto row = row_of.find(line.row);
    if (row == row_of.end() || !kept.count(line.row)) {
      (row == row_of.end() ? removed : changed).insert(line.row);
      aside.push_back(&line);
      continue;
    }
    // A seed other than the suite's for this episode marks a foreign line.
    const std::uint64_t seed =
        MakeEpisodeRequest(suite, suite.rows[row->second], *worlds[row->second], line.episode).seed;
    if (line.episode < 0 || line.seed != seed) {
      if (foreign++ == 0) {
        first_foreign = "row '" + line.row + "', episode " + std::to_string(line.episode) +
                        ", seed " + std::to_string(line.seed) + " where the suite's is " +
                        std::to_string(seed);
      }
      aside.push_back(&line);
      continue;
    }
    const std::pair<std::string, int> key{line.row, line.episode};
    if (conflicting.count(key)) {
      aside.push_back(&line);
    } else if (const auto other = kept_line.find(key); other == kept_line.end()) {
      kept_line[key] = &line;
      done[key] = line;
    } else if (WithoutTimingColumns(FormatEpisodeLine(*other->second, kAllMetrics)) ==
               WithoutTimingColumns(FormatEpisodeLine(line, kAllMetrics))) {
      aside.push_back(&line);  // a second copy of the same result
      ++copies;
    } else {
      conflicting.insert(key);
      aside.push_back(other->second);
      aside.push_back(&line);
      done.erase(key);
    }
  }
  if (note && (kept.size() < suite.rows.size() || !removed.empty())) {
    std::string rerun;
    for (const RowSpec& row : suite.rows) {
      if (!kept.count(row.label)) rerun += (rerun.empty() ? "" : ", ") + row.label;
    }
    std::fprintf(stderr,
                 "note: the configuration changed since '%s' was written (the suite, a --set, "
                 "or a file a row reads: weights, a world, a plugin of yours): %zu unchanged "
                 "row(s) resume; new or changed rows run from scratch: %s\n",
                 out_dir.string().c_str(), kept.size(), rerun.empty() ? "none" : rerun.c_str());
  }
  if (!aside.empty() || !stored_lines.damaged_lines.empty()) {
    // Said even by a quiet run: stored results leave episodes.csv.
    const fs::path path = SetAside(out_dir, aside, stored_lines.damaged_lines, stored_lines.social);
    if (!stored_lines.damaged_lines.empty()) {
      std::fprintf(stderr,
                   "note: %d damaged line(s) of %s moved to %s, their episodes run again (the "
                   "first: %s)\n",
                   stored_lines.damaged, episodes_csv.string().c_str(), path.string().c_str(),
                   stored_lines.first_damage.c_str());
    }
    if (!aside.empty()) {
      std::string why;
      if (!removed.empty()) why += "of row(s) " + Quoted(removed) + ", no longer in the suite";
      if (!changed.empty()) {
        why += std::string(why.empty() ? "" : "; ") + "of row(s) " + Quoted(changed) +
               ", whose configuration changed";
      }
      if (foreign > 0) {
        why += std::string(why.empty() ? "" : "; ") + std::to_string(foreign) +
               " not this suite's episodes (the first: " + first_foreign + ")";
      }
      if (!conflicting.empty()) {
        const auto& [row, episode] = *conflicting.begin();
        why += std::string(why.empty() ? "" : "; ") + std::to_string(conflicting.size()) +
               " episode(s) stored twice with different results, run again (the first: row '" +
               row + "', episode " + std::to_string(episode) + ")";
      }
      if (copies > 0) {
        why += std::string(why.empty() ? "" : "; ") + std::to_string(copies) +
               " second copies of stored episodes";
      }
      std::fprintf(stderr, "note: %zu stored episode line(s) moved to %s: %s\n", aside.size(),
                   path.string().c_str(), why.c_str());
    }
  }
  const std::string commit = ReadManifestField(out_dir / "manifest.json", "git_commit");
  if (!done.empty() && note && commit != GitCommit()) {
    std::fprintf(stderr,
                 "note: resuming %zu stored episodes made by commit %s; this is %s. Pass --fresh "
                 "to rerun them with this build.\n",
                 done.size(), commit.empty() ? "unknown" : commit.c_str(), GitCommit());
  }
  return done;
}

}  // namespace crowdsim
