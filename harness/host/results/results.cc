#include "crowdsim/bench/results.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string_view>
#include <type_traits>
#include <variant>

#include "atomic_file.h"
#include "crowdsim/bench/csv.h"
#include "crowdsim/version.h"

namespace crowdsim {
namespace fs = std::filesystem;

namespace {

std::string Fixed(double x, int digits) {
  if (!std::isfinite(x)) return "";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, x);
  return buf;
}

/// The statuses an episode can end with, as episodes.csv names them.
constexpr EpisodeStatus kEndStatuses[] = {
    EpisodeStatus::kSuccess,      EpisodeStatus::kCollisionHuman, EpisodeStatus::kCollisionObstacle,
    EpisodeStatus::kTimeout,      EpisodeStatus::kPolicyError,    EpisodeStatus::kPolicyCrash,
    EpisodeStatus::kPolicyTimeout};

EpisodeStatus ParseStatus(const std::string& s) {
  for (auto st : kEndStatuses) {
    if (s == EpisodeStatusName(st)) return st;
  }
  return EpisodeStatus::kRunning;
}

/// "success, collision_human, ... or policy_error".
std::string EndStatusNames() {
  std::string names;
  const size_t n = std::size(kEndStatuses);
  for (size_t i = 0; i < n; ++i) {
    names += (i == 0      ? ""
              : i + 1 < n ? ", "
                          : " or ") +
             std::string(EpisodeStatusName(kEndStatuses[i]));
  }
  return names;
}

std::string SensorsLabel(const TableRow& row) {
  if (!row.spec) return "";
  std::string s;
  for (size_t i = 0; i < row.spec->sensors.size(); ++i)
    s += (i ? "+" : "") + (row.spec->sensors[i].loaded
                               ? row.spec->sensors[i].loaded->descriptor->name
                               : row.spec->sensors[i].plugin);
  return s.empty() ? "-" : s;
}

std::string Signed(double x, int digits) {
  const std::string s = Fixed(x, digits);
  return s.empty() || s[0] == '-' ? s : "+" + s;
}

/// The quantities a table compares with published values, in column order.
constexpr std::array<const char*, 5> kCompared = {"success", "collision", "timeout", "nav. time",
                                                  "danger freq."};

/// One compared quantity: our value with its interval, and the published value if any.
struct Compared {
  const char* name;
  double ours;
  Interval interval;  ///< 95%: Wilson for rates, +-1.96 s.e. for nav. time
  bool has_interval;
  std::optional<double> paper;
};

std::vector<Compared> Comparisons(const TableRow& r) {
  const RowMetrics& m = r.metrics;
  const auto& ref = r.Reference();
  auto paper = [&](std::optional<double> PublishedReference::*field) {
    return ref ? (*ref).*field : std::nullopt;
  };
  const bool se = std::isfinite(m.nav_time_se);
  return {
      {kCompared[0], m.success_rate, WilsonInterval95(m.successes, m.episodes), true,
       paper(&PublishedReference::success)},
      {kCompared[1], m.collision_rate, WilsonInterval95(m.collisions, m.episodes), true,
       paper(&PublishedReference::collision)},
      {kCompared[2], m.timeout_rate, WilsonInterval95(m.timeouts, m.episodes), true,
       paper(&PublishedReference::timeout)},
      {kCompared[3],
       m.nav_time,
       {m.nav_time - 1.96 * m.nav_time_se, m.nav_time + 1.96 * m.nav_time_se},
       se,
       paper(&PublishedReference::nav_time)},
      {kCompared[4], m.danger_frequency, {}, false, paper(&PublishedReference::danger)},
  };
}

bool AnyReference(const std::vector<TableRow>& rows) {
  return std::any_of(rows.begin(), rows.end(),
                     [](const TableRow& r) { return r.Reference().has_value(); });
}

struct Column {
  std::string header;
  std::function<std::string(const TableRow&)> value;
  bool user_text = false;  ///< the suite's words (label, info): a spreadsheet may read a formula
};

// A user's cell for table.csv: one a spreadsheet would run as a formula (=, +, -, @, a tab or
// a carriage return first, and not a number) starts with a quote, which shows it as text.
std::string SpreadsheetText(const std::string& s) {
  if (s.size() < 2 || std::string_view("=+-@\t\r").find(s[0]) == std::string_view::npos) return s;
  double number = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), number);
  if (ec == std::errc() && end == s.data() + s.size()) return s;
  return "'" + s;
}

/// Table columns: the paper's and ours, then (CSV) 95% intervals, nav. time's standard error, and
/// published values with differences.
std::vector<Column> Columns(const Suite& suite, const std::vector<TableRow>& rows,
                            bool with_uncertainty) {
  std::vector<Column> cols;
  cols.push_back({"row", nullptr});
  cols.push_back({"label", [](const TableRow& r) { return r.Label(); }, true});
  for (const auto& name : suite.info_columns) {
    cols.push_back({name,
                    [name](const TableRow& r) {
                      for (const auto& [k, v] : r.Info()) {
                        if (k == name) return v;
                      }
                      return std::string("");
                    },
                    true});
  }
  cols.push_back({"sensors", [](const TableRow& r) { return SensorsLabel(r); }});
  auto metric = [](const char* h, double RowMetrics::*field, int digits) {
    return Column{h,
                  [field, digits](const TableRow& r) { return Fixed(r.metrics.*field, digits); }};
  };
  cols.push_back(metric("success rate", &RowMetrics::success_rate, 4));
  cols.push_back(metric("collision rate", &RowMetrics::collision_rate, 4));
  cols.push_back(metric("timeout rate", &RowMetrics::timeout_rate, 4));
  cols.push_back(metric("nav. time", &RowMetrics::nav_time, 4));
  cols.push_back(metric("danger freq.", &RowMetrics::danger_frequency, 4));
  cols.push_back(metric("coll. human", &RowMetrics::collision_human_rate, 4));
  cols.push_back(metric("coll. obstacle", &RowMetrics::collision_obstacle_rate, 4));
  for (const EpisodeColumn& c : kEpisodeColumns) {
    if (c.mean != RowMean::kNone && !Social(c))
      cols.push_back(metric(c.table_header, c.row_mean, c.table_decimals));
  }
  // Social metrics: those the suite names in table.md, all of them in table.csv.
  for (const EpisodeColumn& c : kEpisodeColumns) {
    if (!Social(c) || !(suite.social_metrics & FamilyOf(c))) continue;
    const auto& named = suite.metric_columns;
    if (!with_uncertainty && std::find(named.begin(), named.end(), c.name) == named.end()) continue;
    cols.push_back({c.table_header, [&c](const TableRow& r) {
                      return Fixed(RowMeanField(r.metrics, c), c.table_decimals);
                    }});
  }
  cols.push_back(
      {"errors", [](const TableRow& r) { return Fixed(r.metrics.policy_error_rate, 4); }});
  // Crash and hang columns appear only when used, so other tables keep their columns.
  const auto any = [&](double RowMetrics::*field) {
    return std::any_of(rows.begin(), rows.end(),
                       [field](const TableRow& r) { return r.metrics.*field > 0; });
  };
  if (any(&RowMetrics::policy_crash_rate) || any(&RowMetrics::policy_timeout_rate)) {
    cols.push_back(metric("crashes", &RowMetrics::policy_crash_rate, 4));
    cols.push_back(metric("hangs", &RowMetrics::policy_timeout_rate, 4));
  }
  cols.push_back(
      {"episodes", [](const TableRow& r) { return std::to_string(r.metrics.episodes); }});
  if (!with_uncertainty) return cols;
  for (size_t i = 0; i < kCompared.size(); ++i) {
    const std::string name = kCompared[i];
    if (i < 3) {
      cols.push_back({name + " 95% low",
                      [i](const TableRow& r) { return Fixed(Comparisons(r)[i].interval.low, 4); }});
      cols.push_back({name + " 95% high", [i](const TableRow& r) {
                        return Fixed(Comparisons(r)[i].interval.high, 4);
                      }});
    }
  }
  cols.push_back(
      {"nav. time s.e.", [](const TableRow& r) { return Fixed(r.metrics.nav_time_se, 4); }});
  // Every social metric's mean with its standard error (table.csv).
  for (const EpisodeColumn& c : kEpisodeColumns) {
    if (!Social(c) || !(suite.social_metrics & FamilyOf(c))) continue;
    cols.push_back({std::string(c.table_header) + " s.e.", [&c](const TableRow& r) {
                      return Fixed(SocialSeField(r.metrics, c), c.table_decimals + 1);
                    }});
  }
  if (!AnyReference(rows)) return cols;
  for (size_t i = 0; i < kCompared.size(); ++i) {
    const std::string name = kCompared[i];
    cols.push_back({"paper " + name, [i](const TableRow& r) {
                      const auto paper = Comparisons(r)[i].paper;
                      return paper ? Fixed(*paper, 4) : std::string();
                    }});
    cols.push_back({"Δ " + name, [i](const TableRow& r) {
                      const Compared c = Comparisons(r)[i];
                      return c.paper ? Signed(c.ours - *c.paper, 4) : std::string();
                    }});
  }
  cols.push_back({"paper source", [](const TableRow& r) {
                    return r.Reference() ? r.Reference()->source : std::string();
                  }});
  return cols;
}

}  // namespace

bool IsSocialMetric(std::string_view name) {
  return std::any_of(std::begin(kEpisodeColumns), std::end(kEpisodeColumns),
                     [&](const EpisodeColumn& c) { return Social(c) && c.name == name; });
}

MetricFamilies MetricFamilyOf(std::string_view name) {
  for (const EpisodeColumn& c : kEpisodeColumns) {
    if (Social(c) && c.name == name) return FamilyOf(c);
  }
  return 0;
}

std::vector<const EpisodeColumn*> EpisodeColumnsOf(MetricFamilies families) {
  std::vector<const EpisodeColumn*> columns;
  for (const EpisodeColumn& c : kEpisodeColumns) {
    if (!Social(c) || (families & FamilyOf(c))) columns.push_back(&c);
  }
  return columns;
}

std::string EpisodeCsvHeader(MetricFamilies social) {
  std::string header;
  for (const EpisodeColumn* c : EpisodeColumnsOf(social)) {
    if (!header.empty()) header += ',';
    header += c->name;
  }
  return header;
}

std::string FormatEpisodeCell(const EpisodeColumn& c, const EpisodeLine& e) {
  return std::visit(
      [&](auto member) -> std::string {
        const auto& v = ColumnValue(e, member);
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>)
          return CsvField(v);
        else if constexpr (std::is_same_v<T, EpisodeStatus>)
          return EpisodeStatusName(v);
        else if constexpr (std::is_same_v<T, double>)
          return Fixed(v, c.decimals);
        else
          return std::to_string(v);
      },
      c.field);
}

std::string FormatEpisodeLine(const EpisodeLine& e, MetricFamilies social) {
  std::string line;
  for (const EpisodeColumn* c : EpisodeColumnsOf(social)) {
    if (c != kEpisodeColumns) line += ',';
    line += FormatEpisodeCell(*c, e);
  }
  return line;
}

std::string WithoutTimingColumns(const std::string& episodes_csv) {
  std::istringstream in(episodes_csv);
  std::string line, out;
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = SplitCsvLine(line);
    bool first = true;
    // A line of neither width keeps every field (it differs anyway).
    const auto base = EpisodeColumnsOf(false), all = EpisodeColumnsOf(true);
    const auto* columns = fields.size() == base.size()  ? &base
                          : fields.size() == all.size() ? &all
                                                        : nullptr;
    for (size_t k = 0; k < fields.size(); ++k) {
      if (columns && (*columns)[k]->timing) continue;
      if (!first) out += ',';
      out += CsvField(fields[k]);
      first = false;
    }
    out += "\n";
  }
  return out;
}

namespace {

// How to get a readable episodes.csv back, for every error about one.
constexpr const char* kEpisodesCsvFix =
    "restore it from a copy, or run the suite again with --fresh to rewrite it";

// `s` for a message: control characters as '?', at most 60 characters.
std::string Quote(const std::string& s) {
  std::string out;
  for (char c : s.substr(0, 60)) out += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
  return "'" + out + (s.size() > 60 ? "...'" : "'");
}

bool ParseReal(const std::string& s, double* out) {
  try {
    size_t used = 0;
    *out = std::stod(s, &used);
    return used == s.size();
  } catch (const std::exception&) {
    return false;
  }
}

template <typename Int>
bool ParseWhole(const std::string& s, Int* out) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), *out);
  return ec == std::errc() && end == s.data() + s.size();
}

// Reads one cell into `e`; returns what it should have been, or "".
std::string ParseCell(const EpisodeColumn& c, const std::string& text, EpisodeLine* e) {
  return std::visit(
      [&](auto member) -> std::string {
        auto& v = ColumnValue(*e, member);
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>) {
          v = text;
          return "";
        } else if constexpr (std::is_same_v<T, EpisodeStatus>) {
          v = ParseStatus(text);
          return v == EpisodeStatus::kRunning ? EndStatusNames() : "";
        } else if constexpr (std::is_same_v<T, double>) {
          if (text.empty() && (c.empty_is_infinity || c.empty_is_nan)) {
            v = c.empty_is_nan ? std::numeric_limits<double>::quiet_NaN() : kInfinity;
            return "";
          }
          // The writer leaves a non-finite value empty: "nan" or "inf" is no line of ours.
          if (!ParseReal(text, &v) || !std::isfinite(v)) return "a finite number";
          return "";
        } else {
          // Counts, indices and seeds: every whole number an episode writes is >= 0.
          return ParseWhole(text, &v) && v >= 0 ? "" : "a whole number >= 0";
        }
      },
      c.field);
}

}  // namespace

std::string ParseEpisodeFields(const std::vector<std::string>& v, EpisodeLine* e,
                               MetricFamilies social) {
  const auto columns = EpisodeColumnsOf(social);
  const size_t n = columns.size();
  if (v.size() != n) {
    return "it has " + std::to_string(v.size()) + " field(s), expected " + std::to_string(n);
  }
  for (size_t k = 0; k < n; ++k) {
    const std::string expected = ParseCell(*columns[k], v[k], e);
    if (!expected.empty())
      return "its " + std::string(columns[k]->name) + " " + Quote(v[k]) + " is not " + expected;
  }
  return "";
}

EpisodesCsvRead ReadEpisodesCsvChecked(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot open " + path.string() + ": " + std::strerror(errno));
  EpisodesCsvRead read;
  std::string line;
  if (!std::getline(f, line)) line.clear();
  if (!line.empty() && line.back() == '\r') line.pop_back();
  // A suite with social metrics writes their families' columns too.
  bool known = false;
  for (MetricFamilies f = 0; f <= kAllMetrics && !known; ++f) {
    known = line == EpisodeCsvHeader(f);
    if (known) read.social = f;
  }
  if (!known) {
    throw std::runtime_error(
        path.string() +
        ":1: " + (line.empty() ? "the first line is empty" : "the header is " + Quote(line)) +
        ", expected '" + EpisodeCsvHeader(false) +
        "' (or with the social metrics' columns): this is not an episodes.csv written by "
        "`crowdsim-bench run`; " +
        kEpisodesCsvFix);
  }
  int number = 1, episode_lines = 0;
  while (std::getline(f, line)) {
    ++number;
    if (f.eof()) {
      // A last line without its newline is cut short by a crash: skipped, rerun on resume.
      read.cut_last_line = !line.empty();
      break;
    }
    if (line.empty() || line == "\r") continue;
    ++episode_lines;
    EpisodeLine e;
    const std::string why = ParseEpisodeFields(SplitCsvLine(line), &e, read.social);
    if (why.empty()) {
      read.lines.push_back(std::move(e));
    } else {
      if (read.damaged++ == 0) {
        read.first_damage = path.string() + ":" + std::to_string(number) + ": " + why;
      }
      read.damaged_lines.push_back(line);
    }
  }
  if (f.bad())
    throw std::runtime_error("cannot read " + path.string() + ": " + std::strerror(errno));
  if (read.lines.empty() && read.damaged > 0) {
    throw std::runtime_error(path.string() + ": none of its " + std::to_string(episode_lines) +
                             " episode line(s) can be read (the first: " + read.first_damage +
                             "); " + kEpisodesCsvFix);
  }
  return read;
}

std::vector<EpisodeLine> ReadEpisodesCsv(const fs::path& path) {
  return ReadEpisodesCsvChecked(path).lines;
}

namespace {

/// A Markdown cell's text: '|' escaped, line breaks as spaces.
std::string MarkdownCell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c == '\n' || c == '\r' ? ' ' : c;
  }
  return out;
}

}  // namespace

namespace {

/// The "row" cell: the suite row's number (1..), empty for a summary line.
std::string RowNumber(const std::vector<TableRow>& rows, size_t r) {
  return rows[r].spec ? std::to_string(r + 1) : std::string();
}

void WriteMarkdownTable(const std::vector<std::string>& header, size_t text_columns,
                        const std::vector<std::vector<std::string>>& body, std::ostream& os) {
  os << "| ";
  for (const auto& h : header) os << MarkdownCell(h) << " | ";
  os << "\n|";
  for (size_t i = 0; i < header.size(); ++i) os << (i < text_columns ? "---|" : "---:|");
  os << "\n";
  for (const auto& line : body) {
    os << "| ";
    for (const auto& cell : line) os << MarkdownCell(cell) << " | ";
    os << "\n";
  }
}

/// "min–max" of a summary's success rates: the spread the pooled interval hides.
std::string SuccessRange(const std::vector<TableRow>& rows, const SummarySpec& summary) {
  double lo = 1.0, hi = 0.0;
  for (const TableRow& row : rows) {
    if (!row.spec ||
        std::find(summary.rows.begin(), summary.rows.end(), row.spec->label) == summary.rows.end())
      continue;
    lo = std::min(lo, row.metrics.success_rate);
    hi = std::max(hi, row.metrics.success_rate);
  }
  return Fixed(lo, 4) + "–" + Fixed(hi, 4);
}

/// table.md's second table: Wilson intervals, nav. time +- SE, published values and differences
/// ('*' outside our interval).
void WriteUncertaintyMarkdown(const std::vector<TableRow>& rows, std::ostream& os) {
  const bool papers = AnyReference(rows);
  os << "\nOurs with 95% intervals (Wilson for the rates, nav. time ± its standard error)";
  if (papers) {
    os << "; paper: the published value, Δ: ours - paper, * where the published value lies "
          "outside our 95% interval";
  }
  if (std::any_of(rows.begin(), rows.end(),
                  [](const TableRow& r) { return r.summary != nullptr; })) {
    os << ". Summary lines (no row number) are the mean of their rows; their intervals count the "
          "pooled episodes, so they show evaluation noise only: \"rows\" gives the range of the "
          "rows' success rates (e.g. between training seeds)";
  }
  os << ".\n\n";
  std::vector<std::string> header = {"row", "label"};
  for (size_t i = 0; i < kCompared.size(); ++i) {
    if (i == 4 && !papers) break;
    header.push_back(i < 3    ? std::string(kCompared[i]) + " [95% CI]"
                     : i == 3 ? std::string("nav. time ± s.e.")
                              : std::string(kCompared[i]));
    if (papers) {
      header.push_back("paper");
      header.push_back("Δ");
    }
  }
  if (papers) header.push_back("source");
  std::vector<std::vector<std::string>> body;
  for (size_t r = 0; r < rows.size(); ++r) {
    std::vector<std::string> line = {RowNumber(rows, r), rows[r].Label()};
    const std::vector<Compared> compared = Comparisons(rows[r]);
    for (size_t i = 0; i < compared.size(); ++i) {
      if (i == 4 && !papers) break;
      const Compared& c = compared[i];
      if (i < 3) {
        std::string cell = Fixed(c.ours, 4) + " [" + Fixed(c.interval.low, 4) + ", " +
                           Fixed(c.interval.high, 4) + "]";
        if (i == 0 && rows[r].summary) cell += " rows " + SuccessRange(rows, *rows[r].summary);
        line.push_back(cell);
      } else if (i == 3) {
        line.push_back(Fixed(c.ours, 2) +
                       (c.has_interval ? " ± " + Fixed(rows[r].metrics.nav_time_se, 2) : ""));
      } else {
        line.push_back(Fixed(c.ours, 4));
      }
      if (!papers) continue;
      const int digits = i == 3 ? 2 : 4;
      line.push_back(c.paper ? Fixed(*c.paper, digits) : "");
      std::string delta = c.paper ? Signed(c.ours - *c.paper, digits) : "";
      if (c.paper && c.has_interval && !c.interval.Contains(*c.paper)) delta += " *";
      line.push_back(delta);
    }
    if (papers) line.push_back(rows[r].Reference() ? rows[r].Reference()->source : "");
    body.push_back(std::move(line));
  }
  WriteMarkdownTable(header, 2, body, os);
}

}  // namespace

void AddSummaryLines(const Suite& suite, std::vector<TableRow>* rows) {
  for (const SummarySpec& summary : suite.summaries) {
    std::vector<RowMetrics> members;
    for (const std::string& label : summary.rows) {
      for (const TableRow& row : *rows) {
        if (row.spec && row.spec->label == label) members.push_back(row.metrics);
      }
    }
    rows->push_back(TableRow{nullptr, SummarizeRows(members), &summary});
  }
}

std::string FormatTableMarkdown(const Suite& suite, const std::vector<TableRow>& rows) {
  const auto cols = Columns(suite, rows, false);
  std::vector<std::string> header;
  for (const auto& c : cols) header.push_back(c.header);
  std::vector<std::vector<std::string>> body;
  for (size_t r = 0; r < rows.size(); ++r) {
    std::vector<std::string> line;
    for (const auto& c : cols) line.push_back(c.value ? c.value(rows[r]) : RowNumber(rows, r));
    body.push_back(std::move(line));
  }
  std::ostringstream os;
  WriteMarkdownTable(header, 2 + suite.info_columns.size() + 1, body, os);
  WriteUncertaintyMarkdown(rows, os);
  return os.str();
}

std::string FormatTableCsv(const Suite& suite, const std::vector<TableRow>& rows) {
  const auto cols = Columns(suite, rows, true);
  std::ostringstream os;
  for (size_t i = 0; i < cols.size(); ++i) {
    os << (i ? "," : "")
       << CsvField(cols[i].user_text ? SpreadsheetText(cols[i].header) : cols[i].header);
  }
  os << "\n";
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t i = 0; i < cols.size(); ++i) {
      const std::string v = cols[i].value ? cols[i].value(rows[r]) : RowNumber(rows, r);
      os << (i ? "," : "") << CsvField(cols[i].user_text ? SpreadsheetText(v) : v);
    }
    os << "\n";
  }
  return os.str();
}

void WriteFileAtomically(const fs::path& path, const std::string& text) {
  common::WriteFileAtomically(path, text);
}

std::string NowUtc() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof(buf), "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace crowdsim
