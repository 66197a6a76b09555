// `crowdsim-bench merge`: checks a suite run's shards and joins them into one run's output.
#include <algorithm>
#include <cstdlib>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "crowdsim/bench/results.h"
#include "crowdsim/bench/row_instance.h"
#include "crowdsim/bench/runner.h"
#include "results/json_file.h"
#include "run/output_folder.h"

namespace crowdsim {
namespace fs = std::filesystem;

namespace {

/// Adds to the merged manifest the shards' commit ("mixed" under --allow-mixed-commits) and each
/// shard's, as "COMMIT SHARD".
void RecordShardCommits(const fs::path& manifest,
                        const std::vector<std::pair<std::string, std::string>>& shard_commits) {
  const nlohmann::ordered_json before = ReadJsonFile(manifest);
  if (!before.contains("git_commit")) {
    throw RunError("'" + manifest.string() + "' has no git_commit: a bug, please report");
  }
  bool mixed = false;
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& [commit, shard] : shard_commits) {
    mixed = mixed || commit != shard_commits.front().first;
    list.push_back(commit + " " + shard);
  }
  nlohmann::ordered_json after;
  for (const auto& [key, value] : before.items()) {
    after[key] = value;
    if (key != "git_commit") continue;
    after["shards_git_commit"] = mixed ? "mixed" : shard_commits.front().first;
    after["shard_commits"] = list;
  }
  WriteFileAtomically(manifest, FormatJson(after));
}

// "1/3" -> "3"; a whole run's folder (no shard) -> "".
std::string ShardCount(const std::string& shard) {
  const auto slash = shard.find('/');
  return slash == std::string::npos ? std::string() : shard.substr(slash + 1);
}

// The episodes the folders hold, by (row label, episode), each with the folder it came from.
using EpisodesByKey = std::map<std::pair<std::string, int>, std::pair<EpisodeLine, fs::path>>;

// For an episode no folder holds: its shard (row-major position mod N) and which shards are missing
// or unfinished; "" for non-shards.
std::string WhichShardLacks(const Suite& suite, int episodes, const std::string& count,
                            const std::map<std::string, fs::path>& shard_dirs,
                            const EpisodesByKey& lines, size_t row, int episode) {
  char* end = nullptr;
  const long n = std::strtol(count.c_str(), &end, 10);
  if (count.empty() || *end != '\0' || n < 1 || n > 1000000) return "";
  // Each shard's share of the (row, episode) pairs, as the runner slices them.
  std::vector<long> expected(static_cast<size_t>(n), 0);
  for (size_t r = 0; r < suite.rows.size(); ++r) {
    for (int k = 0; k < episodes; ++k) {
      ++expected[static_cast<size_t>(ShardOfEpisode(r, k, episodes, static_cast<int>(n)) - 1)];
    }
  }
  auto name = [&](long k) { return std::to_string(k) + "/" + count; };
  std::vector<std::string> missing, unfinished;
  for (long k = 1; k <= n; ++k) {
    const auto it = shard_dirs.find(name(k));
    if (it == shard_dirs.end()) {
      // A shard of no episode (more shards than episodes) is not missing.
      if (expected[static_cast<size_t>(k - 1)] > 0) missing.push_back(name(k));
      continue;
    }
    const long held = std::count_if(lines.begin(), lines.end(), [&](const auto& held_line) {
      return held_line.second.second == it->second;
    });
    if (held < expected[static_cast<size_t>(k - 1)]) {
      unfinished.push_back("'" + it->second.string() + "' (shard " + name(k) + ") holds " +
                           std::to_string(held) + " of its " +
                           std::to_string(expected[static_cast<size_t>(k - 1)]) + " episodes");
    }
  }
  const std::string owner = name(ShardOfEpisode(row, episode, episodes, static_cast<int>(n)));
  std::string msg = "it belongs to shard " + owner + ".";
  // At most ten names of a list, then how many more.
  const auto listed = [](const std::vector<std::string>& names) {
    constexpr size_t kShown = 10;
    std::string text;
    for (size_t i = 0; i < std::min(names.size(), kShown); ++i) text += (i ? ", " : "") + names[i];
    if (names.size() > kShown) text += " and " + std::to_string(names.size() - kShown) + " more";
    return text;
  };
  if (!missing.empty()) {
    msg += " Missing: shard";
    msg += missing.size() > 1 ? "s " : " ";
    msg += listed(missing);
    msg += missing.size() > 1
               ? " (no folder given holds them: add their folders, or run each with --shard K/" +
                     count + ")"
               : " (no folder given holds it: add its folder, or run it with --shard " +
                     missing.front() + ")";
    msg += unfinished.empty() ? "." : ";";
  }
  if (!unfinished.empty()) {
    msg += " Unfinished: ";
    msg += listed(unfinished);
    msg += " (rerun that shard's command: its finished episodes resume).";
  }
  return msg + " Then merge again";
}

// What the manifests of two folders of one suite record differently.
std::string HowTheyDiffer(const fs::path& a, const fs::path& b) {
  const fs::path ma = a / "manifest.json", mb = b / "manifest.json";
  return DescribeRunInputsDifference(
      ReadManifestField(ma, "suite_file"), ReadManifestStrings(ma, "overrides"),
      ReadManifestField(mb, "suite_file"), ReadManifestStrings(mb, "overrides"));
}

}  // namespace

RunSummary MergeShards(const std::vector<fs::path>& shard_dirs, const fs::path& out_dir,
                       const fs::path& suite_file, PluginRegistry& registry,
                       bool allow_mixed_commits) {
  if (shard_dirs.empty()) throw RunRefused("merge needs the output folders of the shards");
  std::string hash, episodes_text, manifest_suite;
  EpisodesByKey lines;
  std::map<std::string, fs::path> shard_dir;  // "K/N" -> its folder
  // The build of each shard: episodes of different code are not one run, even with one
  // configuration.
  std::vector<std::pair<std::string, std::string>> shard_commits;
  for (const fs::path& dir : shard_dirs) {
    const fs::path manifest = dir / "manifest.json";
    if (!fs::exists(manifest) || !fs::exists(dir / "episodes.csv")) {
      throw RunRefused("'" + dir.string() +
                       "' is not the output folder of a run (no manifest.json "
                       "and episodes.csv)");
    }
    const std::string h = ReadManifestField(manifest, "config_hash");
    const std::string shard = ReadManifestField(manifest, "shard");
    if (hash.empty()) {
      hash = h;
      manifest_suite = ReadManifestField(manifest, "suite_file");
    } else if (h != hash) {
      throw RunRefused("'" + dir.string() + "' holds another configuration (config hash " + h +
                       ", the first folder " + hash + "): shards of one run only" +
                       HowTheyDiffer(shard_dirs.front(), dir));
    }
    if (const std::string first = ReadManifestField(shard_dirs.front() / "manifest.json", "shard");
        ShardCount(shard) != ShardCount(first)) {
      throw RunRefused("'" + shard_dirs.front().string() + "' is " + ShardName(first) + " and '" +
                       dir.string() + "' " + ShardName(shard) +
                       ": the shards of one run are K/N with one N");
    }
    if (!shard.empty() && !shard_dir.emplace(shard, dir).second) {
      throw RunRefused("shard " + shard + " is given twice ('" + dir.string() + "')");
    }
    // A shard's slice depends on the episode count (--episodes): other counts, other slices.
    if (const long n = ReadManifestInteger(manifest, "episodes"),
        first = ReadManifestInteger(shard_dirs.front() / "manifest.json", "episodes");
        n != first) {
      throw RunRefused("'" + shard_dirs.front().string() + "' ran " + std::to_string(first) +
                       " episodes per row and '" + dir.string() + "' " + std::to_string(n) +
                       ": the shards of one run use one --episodes; rerun the odd ones with it");
    }
    std::string commit = ReadManifestField(manifest, "git_commit");
    if (commit.empty()) commit = "unknown";
    if (!shard_commits.empty() && commit != shard_commits.front().first && !allow_mixed_commits) {
      throw RunRefused(
          "'" + shard_dirs.front().string() + "' was made by commit " +
          shard_commits.front().first + ", '" + dir.string() + "' by commit " + commit +
          ": shards of different code do not "
          "make one run. Rerun the shards with one build, or pass --allow-mixed-commits to "
          "join them anyway (the merged manifest.json records each shard's commit)");
    }
    shard_commits.emplace_back(commit, shard.empty() ? dir.string() : shard);
    EpisodesCsvRead read;
    try {
      read = ReadEpisodesCsvChecked(dir / "episodes.csv");
    } catch (const std::runtime_error& e) {
      throw RunRefused(e.what());
    }
    if (read.damaged > 0 || read.cut_last_line) {
      // Their episodes would be reported missing: say what is wrong with the shard instead.
      throw RunRefused(
          "'" + (dir / "episodes.csv").string() + "' has " +
          (read.damaged > 0 ? std::to_string(read.damaged) +
                                  " damaged line(s) (the first: " + read.first_damage + ")"
                            : std::string("a last line cut short (the shard did not finish)")) +
          ": rerun that shard's command (it sets them aside and runs their episodes again), "
          "then merge");
    }
    for (auto& line : read.lines) {
      const auto key = std::make_pair(line.row, line.episode);
      if (auto it = lines.find(key); it != lines.end()) {
        throw RunRefused(
            "episode " + std::to_string(line.episode) + " of row '" + line.row + "' is " +
            (it->second.second == dir
                 ? "twice in '" + dir.string() + "' (a line copied by hand?)"
                 : "in both '" + it->second.second.string() + "' and '" + dir.string() + "'"));
      }
      lines.emplace(key, std::make_pair(std::move(line), dir));
    }
  }
  const fs::path file = suite_file.empty() ? fs::path(manifest_suite) : suite_file;
  SuiteLoadResult loaded = LoadSuite(
      file, registry, ReadManifestStrings(shard_dirs.front() / "manifest.json", "overrides"));
  if (!loaded.suite) {
    std::string msg = "cannot load the suite '" + file.string() + "' of the shards:";
    for (const auto& e : loaded.errors) msg += "\n  " + e.Format();
    if (suite_file.empty()) {
      msg +=
          "\n(the path the shards' manifest.json records, relative to the folder they ran "
          "from: merge from there, or give the suite with --suite FILE)";
    }
    throw RunRefused(msg);
  }
  const Suite& suite = *loaded.suite;
  if (const std::string ran = ReadManifestField(shard_dirs.front() / "manifest.json", "suite");
      !ran.empty() && ran != suite.name) {
    throw RunRefused(file.string() + " is the suite '" + suite.name + "', but the shards ran '" +
                     ran + "': give that suite's file with --suite, or leave --suite out");
  }
  if (suite.ConfigHash() != hash) {
    throw RunRefused("the suite '" + file.string() +
                     "' is now another configuration (config hash " + suite.ConfigHash() +
                     ") than the shards' (" + hash + "): restore it, or rerun");
  }
  const long episodes = ReadManifestInteger(shard_dirs.front() / "manifest.json", "episodes");
  if (episodes < 1) {
    throw RunError("'" + (shard_dirs.front() / "manifest.json").string() +
                   "' names no episode count");
  }
  // Every (row, episode) exactly once, with the seed the suite gives it, nothing else.
  std::set<std::string> labels;
  const std::string shard_count =
      ShardCount(ReadManifestField(shard_dirs.front() / "manifest.json", "shard"));
  for (size_t r = 0; r < suite.rows.size(); ++r) {
    const RowSpec& row = suite.rows[r];
    labels.insert(row.label);
    std::shared_ptr<WorldSource> world;
    try {
      world = registry.MakeWorld(*row.world.loaded, row.world.params);
    } catch (const std::exception& e) {
      throw RunRefused("row '" + row.label + "' of the suite: " + e.what());
    }
    for (int k = 0; k < episodes; ++k) {
      if (const auto it = lines.find({row.label, k}); it != lines.end()) {
        const std::uint64_t seed = MakeEpisodeRequest(suite, row, *world, k).seed;
        if (it->second.first.seed != seed) {
          throw RunRefused("'" + it->second.second.string() + "' holds episode " +
                           std::to_string(k) + " of row '" + row.label + "' with seed " +
                           std::to_string(it->second.first.seed) + ", not the suite's " +
                           std::to_string(seed) +
                           ": a line edited or copied from another run; rerun that shard "
                           "(delete the line first, and it runs again)");
        }
      }
      if (!lines.count({row.label, k})) {
        const std::string which =
            WhichShardLacks(suite, static_cast<int>(episodes), shard_count, shard_dir, lines, r, k);
        throw RunRefused("episode " + std::to_string(k) + " of row '" + row.label +
                         "' is in none of the " + std::to_string(shard_dirs.size()) + " folders: " +
                         (which.empty() ? "a shard is missing or unfinished "
                                          "(rerun it; finished episodes resume)"
                                        : which));
      }
    }
  }
  for (const auto& [key, value] : lines) {
    if (!labels.count(key.first) || key.second >= episodes) {
      throw RunRefused("'" + value.second.string() + "' holds episode " +
                       std::to_string(key.second) + " of row '" + key.first +
                       "', which the suite's " + std::to_string(episodes) +
                       " episodes do not have");
    }
  }
  // The runner resumes all joined episodes and writes tables and manifest as after a single run.
  std::error_code ec;
  // merge replaces what --out holds: only an earlier merge of these shards' configuration.
  for (const fs::path& dir : shard_dirs) {
    if (fs::exists(out_dir, ec) && fs::equivalent(dir, out_dir, ec)) {
      throw RunRefused("--out '" + out_dir.string() +
                       "' is one of the shards; merge into a folder of its own");
    }
  }
  if (OutputFolderKind(out_dir) == "a suite run") {
    // Merge replaces only an earlier merge of this configuration and count (even one cut short:
    // "merged" is written first).
    const fs::path held = out_dir / "manifest.json";
    const std::string held_hash = ReadManifestField(held, "config_hash");
    const long held_episodes = ReadManifestInteger(held, "episodes");
    const bool held_shard = !ReadManifestField(held, "shard").empty();
    // (A merge by an older build lacks the marker: its manifest lists the shards' commits.)
    const bool held_merge = ReadManifestBool(held, "merged").value_or(false) ||
                            !ReadManifestStrings(held, "shard_commits").empty();
    if (held_hash != hash || held_shard || !held_merge ||
        (held_episodes >= 0 && held_episodes != episodes)) {
      throw RunRefused("'" + out_dir.string() + "' holds " +
                       (held_shard          ? std::string("a shard")
                        : held_hash.empty() ? "results without a readable manifest.json"
                        : held_hash != hash ? "a run of another configuration"
                        : !held_merge       ? "a run of this configuration (not a merge)"
                                            : "a merge of another episode count") +
                       ", which merge would replace; merge into a folder of its own (choose "
                       "another --out)");
    }
  }
  fs::create_directories(out_dir, ec);
  if (ec || !fs::is_directory(out_dir)) {
    throw RunError("cannot create the output folder '" + out_dir.string() + "': " + ec.message());
  }
  // Held from the first write to the last (the runner below shares it: same process).
  std::string refused;
  const auto lock = ClaimOutputFolder(out_dir, "a suite run", &refused);
  if (!lock) throw RunRefused(refused);
  std::string text = EpisodeCsvHeader(suite.social_metrics) + "\n";
  for (const auto& [key, value] : lines)
    text += FormatEpisodeLine(value.first, suite.social_metrics) + "\n";
  // The manifest first: a merge cut short between the two writes is still seen as a merge.
  WriteFileAtomically(out_dir / "manifest.json",
                      FormatJson(nlohmann::ordered_json{{"config_hash", hash}, {"merged", true}}));
  WriteFileAtomically(out_dir / "episodes.csv", text);
  RunOptions options;
  options.out_dir = out_dir;
  options.episodes = static_cast<int>(episodes);
  options.progress = false;
  options.out_dir_claimed = true;  // held above, until the shards' commits are recorded
  options.merge = true;
  RunSummary summary = RunSuite(suite, registry, options);
  if (summary.episodes_run != 0) {
    throw RunError("merge ran " + std::to_string(summary.episodes_run) +
                   " episodes: a bug, please report");
  }
  RecordShardCommits(out_dir / "manifest.json", shard_commits);
  return summary;
}

}  // namespace crowdsim
