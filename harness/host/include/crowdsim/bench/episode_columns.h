// episodes.csv's columns, listed once: header, writer, reader, wire format and table means follow
// kEpisodeColumns. A new metric: an EpisodeOutcome field, its computation, a line here.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
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
                 std::string EpisodeOutcome::*, double SocialMetrics::*>;

/// The member a column names: in a line's identity or its outcome.
template <typename T>
const T& ColumnValue(const EpisodeLine& e, T EpisodeLine::*member) {
  return e.*member;
}
template <typename T>
const T& ColumnValue(const EpisodeLine& e, T EpisodeOutcome::*member) {
  return e.outcome.*member;
}
inline const double& ColumnValue(const EpisodeLine& e, double SocialMetrics::*member) {
  return e.outcome.social.*member;
}
inline double& ColumnValue(EpisodeLine& e, double SocialMetrics::*member) {
  return e.outcome.social.*member;
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
  bool empty_is_nan = false;       ///< an empty cell reads back as NaN: not applicable
  bool timing = false;  ///< wall-clock: differs between runs and machines, left out of comparisons
  RowMean mean = RowMean::kNone;
  int family = 0;  ///< social metrics: the MetricFamilies bit (1 << family) that turns it on
  /// Where the row mean goes (mean != kNone); a social column's goes to RowMetrics::social.
  double RowMetrics::*row_mean = nullptr;
  const char* table_header = nullptr;  ///< the row mean's column in table.md / table.csv
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
    // The social navigation metrics: only in the files of a suite that asks for them (Social()).
    {.name = "shortest_path",
     .field = &SocialMetrics::shortest_path,
     .decimals = 6,
     .mean = RowMean::kAll,
     .table_header = "shortest_path",
     .table_decimals = 3},
    {.name = "spl",
     .field = &SocialMetrics::spl,
     .decimals = 6,
     .mean = RowMean::kAll,
     .table_header = "SPL",
     .table_decimals = 3},
    {.name = "accel_mean",
     .field = &SocialMetrics::accel_mean,
     .decimals = 6,
     .mean = RowMean::kAll,
     .table_header = "accel. mean",
     .table_decimals = 3},
    {.name = "accel_max",
     .field = &SocialMetrics::accel_max,
     .decimals = 6,
     .mean = RowMean::kAll,
     .table_header = "accel. max",
     .table_decimals = 3},
    {.name = "jerk_mean",
     .field = &SocialMetrics::jerk_mean,
     .decimals = 6,
     .mean = RowMean::kAll,
     .table_header = "jerk mean",
     .table_decimals = 3},
    {.name = "jerk_max",
     .field = &SocialMetrics::jerk_max,
     .decimals = 6,
     .mean = RowMean::kAll,
     .table_header = "jerk max",
     .table_decimals = 3},
    {.name = "angular_accel_mean",
     .field = &SocialMetrics::angular_accel_mean,
     .decimals = 6,
     .empty_is_nan = true,
     .mean = RowMean::kFinite,
     .table_header = "ang. accel. mean",
     .table_decimals = 3},
    {.name = "angular_accel_max",
     .field = &SocialMetrics::angular_accel_max,
     .decimals = 6,
     .empty_is_nan = true,
     .mean = RowMean::kFinite,
     .table_header = "ang. accel. max",
     .table_decimals = 3},
    {.name = "angular_jerk_mean",
     .field = &SocialMetrics::angular_jerk_mean,
     .decimals = 6,
     .empty_is_nan = true,
     .mean = RowMean::kFinite,
     .table_header = "ang. jerk mean",
     .table_decimals = 3},
    {.name = "angular_jerk_max",
     .field = &SocialMetrics::angular_jerk_max,
     .decimals = 6,
     .empty_is_nan = true,
     .mean = RowMean::kFinite,
     .table_header = "ang. jerk max",
     .table_decimals = 3},
    {.name = "path_irregularity",
     .field = &SocialMetrics::path_irregularity,
     .decimals = 6,
     .mean = RowMean::kAll,
     .table_header = "path irregularity",
     .table_decimals = 3},
    {.name = "freezing_time",
     .field = &SocialMetrics::freezing_time,
     .decimals = 2,
     .mean = RowMean::kAll,
     .table_header = "freezing time",
     .table_decimals = 3},
    {.name = "intimate_share",
     .field = &SocialMetrics::intimate_share,
     .decimals = 6,
     .mean = RowMean::kAll,
     .table_header = "intimate share",
     .table_decimals = 3},
    {.name = "personal_share",
     .field = &SocialMetrics::personal_share,
     .decimals = 6,
     .mean = RowMean::kAll,
     .table_header = "personal share",
     .table_decimals = 3},
    {.name = "personal_intrusions",
     .field = &SocialMetrics::personal_intrusions,
     .decimals = 0,
     .mean = RowMean::kAll,
     .table_header = "personal intrusions",
     .table_decimals = 3},
    {.name = "min_ttc",
     .field = &SocialMetrics::min_ttc,
     .decimals = 6,
     .mean = RowMean::kAll,
     .table_header = "min. TTC",
     .table_decimals = 3},
    // Walking groups' metrics: their own family, so suites naming only the above keep their files.
    {.name = "group_intrusions",
     .field = &SocialMetrics::group_intrusions,
     .decimals = 0,
     .empty_is_nan = true,
     .mean = RowMean::kFinite,
     .family = 1,
     .table_header = "group intrusions",
     .table_decimals = 3},
    {.name = "group_share",
     .field = &SocialMetrics::group_share,
     .decimals = 6,
     .empty_is_nan = true,
     .mean = RowMean::kFinite,
     .family = 1,
     .table_header = "group share",
     .table_decimals = 3},
    // The robot's effect on the people: its own family, as it replays every episode.
    {.name = "people_lost_progress",
     .field = &SocialMetrics::people_lost_progress,
     .decimals = 6,
     .empty_is_nan = true,
     .mean = RowMean::kFinite,
     .family = 2,
     .table_header = "people lost progress",
     .table_decimals = 3},
    {.name = "people_path_added",
     .field = &SocialMetrics::people_path_added,
     .decimals = 6,
     .empty_is_nan = true,
     .mean = RowMean::kFinite,
     .family = 2,
     .table_header = "people path added",
     .table_decimals = 3},
    {.name = "people_accel_added",
     .field = &SocialMetrics::people_accel_added,
     .decimals = 6,
     .empty_is_nan = true,
     .mean = RowMean::kFinite,
     .family = 2,
     .table_header = "people accel. added",
     .table_decimals = 3},
    {.name = "error", .field = &EpisodeOutcome::error},
};

/// Which social metric families a file carries, a bit each: kCoreMetrics (SPL ... min_ttc),
/// kGroupMetrics (walking groups), kEffectMetrics (the robot's effect on the people). A suite
/// turns on the families of the metrics it names.
using MetricFamilies = unsigned;
inline constexpr MetricFamilies kCoreMetrics = 1u;
inline constexpr MetricFamilies kGroupMetrics = 2u;
inline constexpr MetricFamilies kEffectMetrics = 4u;  ///< the people effect: replays each episode
inline constexpr MetricFamilies kAllMetrics = kCoreMetrics | kGroupMetrics | kEffectMetrics;
/// What an episode log holds enough for (the people effect needs a replay without the robot).
inline constexpr MetricFamilies kLogMetrics = kCoreMetrics | kGroupMetrics;

/// A social navigation metric's column: in the files of a suite with social metrics only.
inline bool Social(const EpisodeColumn& c) {
  return std::holds_alternative<double SocialMetrics::*>(c.field);
}
/// The family bit of a social metric's column.
inline MetricFamilies FamilyOf(const EpisodeColumn& c) { return 1u << c.family; }
/// True for the name of a social metric's column (suites name them in `columns:`).
bool IsSocialMetric(std::string_view name);
/// The family bit of the social metric `name` (0 when it is none).
MetricFamilies MetricFamilyOf(std::string_view name);
/// The columns of episodes.csv with the social metrics of `families`, in file order.
std::vector<const EpisodeColumn*> EpisodeColumnsOf(MetricFamilies families);
/// A column's row mean in `m`.
double& RowMeanField(RowMetrics& m, const EpisodeColumn& c);
double RowMeanField(const RowMetrics& m, const EpisodeColumn& c);
/// A social column's standard error of its row mean in `m`.
double& SocialSeField(RowMetrics& m, const EpisodeColumn& c);
double SocialSeField(const RowMetrics& m, const EpisodeColumn& c);

/// Header line of episodes.csv (the column names, comma-separated).
std::string EpisodeCsvHeader(MetricFamilies social);
/// One cell as episodes.csv writes it.
std::string FormatEpisodeCell(const EpisodeColumn& c, const EpisodeLine& e);
/// One CSV line (no newline).
std::string FormatEpisodeLine(const EpisodeLine& e, MetricFamilies social);
/// Reads one line's fields (from SplitCsvLine) into `e`; returns why they are no episode line, or
/// "".
std::string ParseEpisodeFields(const std::vector<std::string>& fields, EpisodeLine* e,
                               MetricFamilies social);
/// episodes.csv without timing columns: what two runs of one configuration must agree on, anywhere.
std::string WithoutTimingColumns(const std::string& episodes_csv);

}  // namespace crowdsim
