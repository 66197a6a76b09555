// Result files of a suite run: episodes.csv (one line per finished episode, appended as they
// finish, so a crash loses nothing; its columns are episode_columns.h's), table.md / table.csv
// (the paper's columns), manifest.json.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "crowdsim/bench/episode_columns.h"
#include "crowdsim/bench/metrics.h"
#include "crowdsim/bench/suite.h"

namespace crowdsim {

/// What reading an episodes.csv found.
struct EpisodesCsvRead {
  std::vector<EpisodeLine> lines;
  int damaged = 0;                         ///< complete lines that are no episode line (skipped)
  std::vector<std::string> damaged_lines;  ///< their text, as read
  std::string first_damage;    ///< "FILE:LINE: why" of the first of them; empty when none
  bool cut_last_line = false;  ///< the last line lacks its newline (a crash mid-write): skipped
};
/// Reads an episodes.csv. Throws std::runtime_error naming the file (and line) and the fix when
/// it cannot be read, when its first line is not EpisodeCsvHeader(), or when it has episode
/// lines and none of them can be read. Damaged lines among readable ones are skipped and
/// counted (on resume their episodes run again); a last line cut short by a crash is skipped.
EpisodesCsvRead ReadEpisodesCsvChecked(const std::filesystem::path& path);
/// ReadEpisodesCsvChecked's lines.
std::vector<EpisodeLine> ReadEpisodesCsv(const std::filesystem::path& path);

/// One finished line of the table: a suite row, or a summary line (spec null, summary set).
struct TableRow {
  const RowSpec* spec = nullptr;
  RowMetrics metrics;
  const SummarySpec* summary = nullptr;

  const std::string& Label() const { return spec ? spec->label : summary->label; }
  const std::vector<std::pair<std::string, std::string>>& Info() const {
    return spec ? spec->info : summary->info;
  }
  const std::optional<PublishedReference>& Reference() const {
    return spec ? spec->reference : summary->reference;
  }
};

/// Appends the suite's summary lines (the mean of their rows) to the finished rows.
void AddSummaryLines(const Suite& suite, std::vector<TableRow>* rows);

std::string FormatTableMarkdown(const Suite& suite, const std::vector<TableRow>& rows);
std::string FormatTableCsv(const Suite& suite, const std::vector<TableRow>& rows);

/// Facts recorded in manifest.json besides the suite.
struct RunFacts {
  std::string started_utc;
  std::string finished_utc;
  int jobs = 1;
  bool isolated = false;  ///< episodes ran in worker processes (Suite::isolation)
  int episodes = 0;
  double wall_seconds = 0.0;
  std::map<std::string, std::string> world_identities;  ///< per row label
  std::string shard;    ///< "K/N" for a shard of a run, empty for a whole run
  bool merged = false;  ///< written by `merge` (the only folder a later merge may replace)
};
std::string FormatManifestJson(const Suite& suite, const std::vector<TableRow>& rows,
                               const RunFacts& facts);

// Readers of a JSON file the harness wrote (manifest.json, a training's summary.json). `key` is
// a top-level key, or a JSON pointer when it starts with '/' ("/procedure/rl_episodes"). An
// absent, unreadable or malformed file, a missing key or a value of another type reads as absent.

/// A string field, e.g. "config_hash", "git_commit" ("" if absent).
std::string ReadManifestField(const std::filesystem::path& path, const std::string& key);
/// A run's overrides (the manifest's "overrides") as the command line gives them: "--set A
/// --set B", "" for none.
std::string SetOptionsText(const std::vector<std::string>& sets);
/// A list of strings, e.g. "overrides" (empty if absent; non-strings in it are skipped).
std::vector<std::string> ReadManifestStrings(const std::filesystem::path& path,
                                             const std::string& key);
/// A whole number, e.g. "episodes" (-1 if absent).
long ReadManifestInteger(const std::filesystem::path& path, const std::string& key);
/// A true/false field, e.g. a summary's "finished" (nullopt if absent).
std::optional<bool> ReadManifestBool(const std::filesystem::path& path, const std::string& key);

/// A manifest's "shard" field in words: "shard 2/3", or "a whole run" when empty.
std::string ShardName(const std::string& shard);

/// What two runs were given differently: their suite files, their --set overrides (as the
/// manifest records them), as "; suite files A and B; run with no --set and with --set x=1"
/// for the end of an error message; empty when both are the same.
std::string DescribeRunInputsDifference(const std::string& suite_a,
                                        const std::vector<std::string>& set_a,
                                        const std::string& suite_b,
                                        const std::vector<std::string>& set_b);

/// Writes text to `path` atomically (temporary file, then rename).
void WriteFileAtomically(const std::filesystem::path& path, const std::string& text);

/// Current UTC time as ISO 8601.
std::string NowUtc();

}  // namespace crowdsim
