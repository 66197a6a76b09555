// A suite run's result files: episodes.csv (appended per episode), table.md, table.csv,
// manifest.json.
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
  MetricFamilies social = 0;   ///< the social metric families whose columns it has
};
/// Reads an episodes.csv. Throws std::runtime_error (file, line, fix) when unreadable, when the
/// header is neither EpisodeCsvHeader(false) nor (true), or when no episode line reads. Damaged
/// lines are skipped and counted; a crash-cut last line is skipped.
EpisodesCsvRead ReadEpisodesCsvChecked(const std::filesystem::path& path);
/// ReadEpisodesCsvChecked's lines.
std::vector<EpisodeLine> ReadEpisodesCsv(const std::filesystem::path& path);

/// One finished table line: a suite row, or a summary (spec null, summary set).
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

// Readers of JSON files the harness wrote: `key` is top-level or a '/' JSON pointer; anything
// missing or mistyped reads as absent.

/// A string field, e.g. "config_hash", "git_commit" ("" if absent).
std::string ReadManifestField(const std::filesystem::path& path, const std::string& key);
/// The manifest's "overrides" as a command line: "--set A --set B", "" for none.
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

/// How two runs' suite files and --set overrides differ, as an error's tail ("; suite files A and
/// B; ..."); "" if the same.
std::string DescribeRunInputsDifference(const std::string& suite_a,
                                        const std::vector<std::string>& set_a,
                                        const std::string& suite_b,
                                        const std::vector<std::string>& set_b);

/// Writes text to `path` atomically (temporary file, then rename).
void WriteFileAtomically(const std::filesystem::path& path, const std::string& text);

/// Current UTC time as ISO 8601.
std::string NowUtc();

}  // namespace crowdsim
