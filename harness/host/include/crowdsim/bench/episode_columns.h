// episodes.csv's columns, listed once: header, writer, reader, wire format and table means follow
// kEpisodeColumns. A new metric: an EpisodeOutcome field, its computation, a line here.
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "crowdsim/bench/episode.h"
#include "crowdsim/bench/metrics.h"

namespace crowdsim {

/// One episodes.csv line: which episode (row, index, seed, layout) and how it ended.
struct EpisodeLine {
  std::string row;  ///< row label
  int episode = 0;
  std::uint64_t seed = 0;
  std::string layout;
  EpisodeOutcome outcome;
};

/// Where a column's value lives: in the line's identity or in its outcome.
using EpisodeField =
    std::variant<std::string EpisodeLine::*, int EpisodeLine::*, std::uint64_t EpisodeLine::*,
                 EpisodeStatus EpisodeOutcome::*, int EpisodeOutcome::*, double EpisodeOutcome::*,
                 std::string EpisodeOutcome::*>;

/// The member a column names: in a line's identity or its outcome.
template <typename T>
const T& ColumnValue(const EpisodeLine& e, T EpisodeLine::*member) {
  return e.*member;
}
template <typename T>
const T& ColumnValue(const EpisodeLine& e, T EpisodeOutcome::*member) {
  return e.outcome.*member;
}
template <typename T>
T& ColumnValue(EpisodeLine& e, T EpisodeLine::*member) {
  return e.*member;
}
template <typename T>
T& ColumnValue(EpisodeLine& e, T EpisodeOutcome::*member) {
  return e.outcome.*member;
}

/// How a table row averages a column over its episodes.
enum class RowMean {
  kNone,       ///< no row mean
  kAll,        ///< mean over all episodes
  kSuccesses,  ///< mean over the successful episodes (0 when none)
  kFinite,     ///< mean over the episodes where it is finite (0 when none)
};

/// One column of episodes.csv.
struct EpisodeColumn {
  const char* name;  ///< header in episodes.csv; the manifest's key of its row mean
  EpisodeField field;
  int decimals = 0;  ///< real numbers: digits after the point (a non-finite value is written empty)
  bool empty_is_infinity = false;  ///< an empty cell reads back as infinity (else it is damage)
  bool timing = false;  ///< wall-clock: differs between runs and machines, left out of comparisons
  RowMean mean = RowMean::kNone;
  double RowMetrics::*row_mean = nullptr;  ///< where the row mean goes (mean != kNone)
  const char* table_header = nullptr;      ///< the row mean's column in table.md / table.csv
  int table_decimals = 0;
};

/// The columns in file order, kept by table means and manifest.json.
inline constexpr EpisodeColumn kEpisodeColumns[] = {
    {.name = "row", .field = &EpisodeLine::row},
    {.name = "episode", .field = &EpisodeLine::episode},
    {.name = "seed", .field = &EpisodeLine::seed},
    {.name = "layout", .field = &EpisodeLine::layout},
    {.name = "status", .field = &EpisodeOutcome::status},
    {.name = "time", .field = &EpisodeOutcome::time, .decimals = 2},
    {.name = "steps", .field = &EpisodeOutcome::steps},
    {.name = "danger_steps", .field = &EpisodeOutcome::danger_steps},
    {.name = "path_length",
     .field = &EpisodeOutcome::path_length,
     .decimals = 6,
     .mean = RowMean::kSuccesses,
     .row_mean = &RowMetrics::path_length,
     .table_header = "path length",
     .table_decimals = 3},
    {.name = "min_human_distance",
     .field = &EpisodeOutcome::min_human_distance,
     .decimals = 6,
     .empty_is_infinity = true,
     .mean = RowMean::kFinite,
     .row_mean = &RowMetrics::min_human_distance,
     .table_header = "min. dist.",
     .table_decimals = 3},
    {.name = "discounted_return",
     .field = &EpisodeOutcome::discounted_return,
     .decimals = 8,
     .mean = RowMean::kAll,
     .row_mean = &RowMetrics::discounted_return,
     .table_header = "return",
     .table_decimals = 4},
    {.name = "decision_time_us",
     .field = &EpisodeOutcome::decision_time_us,
     .decimals = 3,
     .timing = true,
     .mean = RowMean::kAll,
     .row_mean = &RowMetrics::decision_time_us,
     .table_header = "decision µs",
     .table_decimals = 1},
    {.name = "humans_at_goal", .field = &EpisodeOutcome::humans_at_goal},
    {.name = "max_speed", .field = &EpisodeOutcome::max_speed, .decimals = 6},
    {.name = "error", .field = &EpisodeOutcome::error},
};

/// Header line of episodes.csv (the column names, comma-separated).
std::string EpisodeCsvHeader();
/// One CSV line (no newline).
std::string FormatEpisodeLine(const EpisodeLine& e);
/// Reads one line's fields (from SplitCsvLine) into `e`; returns why they are no episode line, or
/// "".
std::string ParseEpisodeFields(const std::vector<std::string>& fields, EpisodeLine* e);
/// episodes.csv without timing columns: what two runs of one configuration must agree on, anywhere.
std::string WithoutTimingColumns(const std::string& episodes_csv);

}  // namespace crowdsim
