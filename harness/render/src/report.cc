#include "crowdsim/render/report.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <vector>

#include "crowdsim/bench/episode_columns.h"
#include "crowdsim/render/bar_chart.h"
#include "crowdsim/render/palette.h"
#include "crowdsim/render/report_episodes.h"
#include "crowdsim/render/report_inputs.h"
#include "crowdsim/render/xml_escape.h"

namespace crowdsim::render {
namespace fs = std::filesystem;
namespace {

// A table field as a number; 0 when empty or not a number.
double Number(const std::string& s) {
  try {
    return s.empty() ? 0.0 : std::stod(s);
  } catch (const std::exception&) {
    return 0.0;
  }
}

// Whether a table field is a number as a whole (right-aligned in the table).
bool IsNumber(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end != nullptr && *end == '\0';
}

// The episodes the table counts: the sum of its `episodes` column.
std::size_t TableEpisodes(const ReportInputs& in) {
  const size_t column = in.table.Column("episodes");
  std::size_t total = 0;
  for (const auto& row : in.table.rows) {
    if (column < row.size())
      total += static_cast<std::size_t>(std::strtoull(row[column].c_str(), nullptr, 10));
  }
  return total;
}

// The document head, the suite's name and description, and where the results come from.
void WriteHeader(std::ostream& html, const ReportInputs& in) {
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>"
       << XmlEscape(in.suite.name) << " · crowdsim-bench report</title>\n<style>" << ReportCss()
       << "</style></head><body>\n";
  html << "<h1>" << XmlEscape(in.suite.name) << "</h1>\n";
  if (!in.suite.description.empty())
    html << "<p class=\"meta\">" << XmlEscape(in.suite.description) << "</p>\n";
  html << "<p class=\"meta\">results: " << XmlEscape(in.dir.string())
       << " · suite file: " << XmlEscape(in.suite_file.string()) << " · " << TableEpisodes(in)
       << " episodes in the table";
  // A shorter run into a folder of a longer one keeps the longer run's episodes for a resume.
  if (in.episodes.lines.size() > TableEpisodes(in)) {
    html << " (episodes.csv holds " << in.episodes.lines.size()
         << ", kept from a longer run for a resume)";
  }
  const std::string overrides = SetOptionsText(ReadManifestStrings(in.manifest, "overrides"));
  if (!overrides.empty()) html << " · run with " << XmlEscape(overrides);
  for (const char* key : {"git_commit", "finished_utc", "config_hash"}) {
    const std::string v = ReadManifestField(in.manifest, key);
    if (!v.empty()) html << " · " << key << " " << XmlEscape(v);
  }
  html << "</p>\n";
}

// Warnings: damaged episode lines skipped, a suite changed since the run; each also added to
// `text` when given (a page written without a word on the command line went unread).
void WriteWarnings(std::ostream& html, const ReportInputs& in, std::vector<std::string>* text) {
  std::vector<std::string> warnings;
  const EpisodesCsvRead& read = in.episodes;
  if (read.damaged > 0) {
    warnings.push_back(std::to_string(read.damaged) +
                       " damaged line(s) of episodes.csv were skipped (the first: " +
                       read.first_damage + "): the figures show the readable episodes only.");
  }
  const std::string recorded_hash = ReadManifestField(in.manifest, "config_hash");
  // evaluate()'s hash is of the suite with its Python row, which cannot be made here.
  if (!recorded_hash.empty() && !in.python_policy && recorded_hash != in.suite.ConfigHash()) {
    warnings.push_back("The suite file changed since this run (config hash " +
                       in.suite.ConfigHash() + " vs " + recorded_hash +
                       "): the figures replay the current suite and may differ from the table.");
  }
  for (const std::string& w : warnings) html << "<p class=\"warn\">" << XmlEscape(w) << "</p>\n";
  if (text != nullptr) text->insert(text->end(), warnings.begin(), warnings.end());
}

// table.csv as an HTML table, numbers right-aligned.
void WriteTable(std::ostream& html, const CsvTable& table) {
  html << "<h2>Table</h2>\n<table><tr>";
  for (const std::string& h : table.header) html << "<th>" << XmlEscape(h) << "</th>";
  html << "</tr>\n";
  for (const auto& row : table.rows) {
    html << "<tr>";
    for (const std::string& f : row)
      html << (IsNumber(f) ? "<td>" : "<td class=\"text\">") << XmlEscape(f) << "</td>";
    html << "</tr>\n";
  }
  html << "</table>\n";
}

// The bars of the three charts, one of each per table row.
struct ChartBars {
  std::vector<Bar> outcomes, nav, danger;
};

// Each table row's outcome rates, navigation time and danger frequency as bars.
ChartBars TableBars(const CsvTable& table, const TableColumns& col) {
  ChartBars bars;
  for (const auto& row : table.rows) {
    auto at = [&](size_t c) { return c < row.size() ? row[c] : std::string(); };
    const std::string label = at(col.label);
    const double s = Number(at(col.success)), c = Number(at(col.collision)),
                 t = Number(at(col.timeout));
    bars.outcomes.push_back(
        Bar{label,
            {{"success", s, palette::kSuccess},
             {"collision", c, palette::kCollision},
             {"timeout", t, palette::kTimeout},
             {"other", std::max(0.0, 1.0 - s - c - t), palette::kOther.WithAlpha(0.5)}}});
    bars.nav.push_back(Bar{label, {{"nav. time", Number(at(col.nav)), palette::kRobot}}});
    bars.danger.push_back(
        Bar{label, {{"danger freq.", Number(at(col.danger)), palette::kRobotCompare}}});
  }
  return bars;
}

// A chart per social navigation metric the suite names in `columns:`, a bar per table row.
void WriteSocialCharts(std::ostream& html, const ReportInputs& in) {
  const auto& header = in.table.header;
  std::vector<std::pair<const EpisodeColumn*, size_t>> charts;
  for (const std::string& name : in.suite.metric_columns) {
    for (const EpisodeColumn& c : kEpisodeColumns) {
      if (!Social(c) || c.name != name) continue;
      const auto at = std::find(header.begin(), header.end(), c.table_header);
      if (at != header.end()) charts.emplace_back(&c, static_cast<size_t>(at - header.begin()));
    }
  }
  if (charts.empty()) return;
  html << "<h2>Social navigation metrics</h2>\n<p class=\"meta\">Row means of the metrics "
          "the suite names (docs/metrics.md); table.csv has every one.</p>\n<div "
          "class=\"charts\">\n";
  for (const auto& [column, index] : charts) {
    std::vector<Bar> bars;
    for (const auto& row : in.table.rows) {
      const std::string value = index < row.size() ? row[index] : std::string();
      bars.push_back(Bar{row[in.columns.label], {{column->name, Number(value), palette::kRobot}}});
    }
    BarChartOptions options;
    options.title = column->table_header;
    options.decimals = 3;
    html << "<div class=\"chart\">" << BarChartSvg(bars, options) << "</div>\n";
  }
  html << "</div>\n";
}

// The bar charts of outcomes, navigation time and danger frequency.
void WriteCharts(std::ostream& html, const ReportInputs& in) {
  const ChartBars bars = TableBars(in.table, in.columns);
  html << "<h2>Charts</h2>\n<div class=\"charts\">\n";
  BarChartOptions outcomes;
  outcomes.title = "Outcomes (fraction of episodes)";
  outcomes.max_value = 1.0;
  outcomes.decimals = 3;
  outcomes.legend = true;
  BarChartOptions nav;
  nav.title = "Navigation time (successful episodes)";
  nav.unit = " s";
  BarChartOptions danger;
  danger.title = "Danger frequency";
  danger.decimals = 4;
  html << "<div class=\"chart\">" << BarChartSvg(bars.outcomes, outcomes) << "</div>\n";
  html << "<div class=\"chart\">" << BarChartSvg(bars.nav, nav) << "</div>\n";
  html << "<div class=\"chart\">" << BarChartSvg(bars.danger, danger) << "</div>\n";
  html << "</div>\n";
  WriteSocialCharts(html, in);
}

// Thumbnails per row, each linking to its full figure in the Figures section.
void WriteEpisodes(std::ostream& html, const ReportInputs& in, PluginRegistry& registry,
                   const ReportOptions& options) {
  const EpisodeSections sections = EpisodePictures(in, registry, options);
  html << "<h2>Episodes</h2>\n<p class=\"meta\">The first success, collision and timeout of each "
          "row, replayed "
          "exactly; click a picture for the full figure.</p>\n";
  html << sections.thumbnails;
  html << "<h2>Figures</h2>\n" << sections.figures;
}

// How to draw any other episode; closes the document.
void WriteFooter(std::ostream& html) {
  html << "<p class=\"meta\">Made by <code>crowdsim-bench report</code>; every episode can be "
          "drawn with "
          "<code>crowdsim-bench render SUITE --row R --episode K --out "
          "FILE.svg</code>.</p>\n</body></html>\n";
}

}  // namespace

const char* ReportCss() {
  static const char* const kCss = R"(
body{font-family:"DejaVu Sans",Helvetica,Arial,sans-serif;margin:24px 32px;color:#212121;background:#fafafa}
h1{font-size:22px;margin:0 0 4px} h2{font-size:18px;margin:28px 0 10px;border-bottom:1px solid #ddd;padding-bottom:4px}
h3{font-size:15px;margin:16px 0 8px} .meta{color:#666;font-size:13px;margin:2px 0}
table{border-collapse:collapse;font-size:12px;background:#fff} th,td{border:1px solid #ddd;padding:4px 7px;text-align:right}
th{background:#f0f0f0} td.text,th.text{text-align:left}
.charts{display:flex;flex-wrap:wrap;gap:18px} .chart{background:#fff;border:1px solid #e2e2e2;padding:8px}
.thumbs{display:flex;flex-wrap:wrap;gap:14px} .thumb{background:#fff;border:1px solid #e2e2e2;padding:6px;width:260px;font-size:12px}
.thumb img{width:100%;height:auto;display:block} .thumb a{color:inherit;text-decoration:none}
.none{color:#999;font-style:italic;padding:40px 0;text-align:center} .warn{color:#b35c00}
.figure{background:#fff;border:1px solid #e2e2e2;padding:8px;margin:12px 0} .figure svg{max-width:100%;height:auto}
)";
  return kCss;
}

std::string BuildReport(const fs::path& dir, PluginRegistry& registry,
                        const ReportOptions& options) {
  const ReportInputs in = ReadReportInputs(dir, registry, options);
  std::ostringstream html;
  WriteHeader(html, in);
  WriteWarnings(html, in, options.warnings);
  WriteTable(html, in.table);
  WriteCharts(html, in);
  WriteEpisodes(html, in, registry, options);
  WriteFooter(html);
  return html.str();
}

}  // namespace crowdsim::render
