#include "crowdsim/render/report.h"

#include <cstdio>
#include <map>
#include <optional>
#include <sstream>

#include "crowdsim/render/bar_chart.h"
#include "crowdsim/render/base64.h"
#include "crowdsim/render/cairo_backend.h"
#include "crowdsim/render/episode_replay.h"
#include "crowdsim/render/palette.h"
#include "crowdsim/render/results_folder.h"
#include "crowdsim/render/svg_writer.h"
#include "crowdsim/render/xml_escape.h"
#include "crowdsim/results.h"
#include "crowdsim/suite.h"

namespace crowdsim::render {
namespace fs = std::filesystem;
namespace {



double Number(const std::string& s) {
  try {
    return s.empty() ? 0.0 : std::stod(s);
  } catch (const std::exception&) {
    return 0.0;
  }
}

bool IsNumber(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end != nullptr && *end == '\0';
}

// What a thumbnail shows: the first episode of a row with a given outcome.
struct Pick {
  std::string outcome;  // "success", "collision", "timeout"
  std::optional<EpisodeLine> line;
};

std::vector<Pick> PickEpisodes(const std::vector<EpisodeLine>& lines, const std::string& label) {
  std::vector<Pick> picks = {{"success", {}}, {"collision", {}}, {"timeout", {}}};
  for (const EpisodeLine& l : lines) {
    if (l.row != label) continue;
    const EpisodeStatus s = l.outcome.status;
    Pick* p = s == EpisodeStatus::kSuccess ? &picks[0]
              : (s == EpisodeStatus::kCollisionHuman || s == EpisodeStatus::kCollisionObstacle)
                  ? &picks[1]
              : s == EpisodeStatus::kTimeout ? &picks[2]
                                             : nullptr;
    if (p && (!p->line || l.episode < p->line->episode)) p->line = l;
  }
  return picks;
}

fs::path FindSuiteFile(const fs::path& dir, const fs::path& manifest,
                       const ReportOptions& options) {
  if (!options.suite_file.empty()) {
    if (!fs::exists(options.suite_file))
      throw ReportError("suite file '" + options.suite_file.string() + "' does not exist");
    return options.suite_file;
  }
  const std::string recorded = ReadManifestField(manifest, "suite_file");
  if (recorded.empty()) {
    throw ReportError((dir / "manifest.json").string() +
                      " names no suite_file: pass the suite with --suite FILE");
  }
  const fs::path p(recorded);
  if (fs::exists(p)) return p;
  throw ReportError(
      "the suite file '" + recorded + "' named in " + (dir / "manifest.json").string() +
      " was not found from " + fs::current_path().string() +
      " (run the report from the folder the suite was run from, or pass --suite FILE)");
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
  if (!fs::is_directory(dir)) {
    throw ReportError("results folder '" + dir.string() +
                      "' does not exist (give the --out folder of `crowdsim-bench run`)");
  }
  for (const char* f : {"manifest.json", "table.csv", "episodes.csv"}) {
    if (!fs::exists(dir / f)) {
      throw ReportError("'" + dir.string() + "' has no " + f +
                        ": give the folder `crowdsim-bench run` wrote (it holds manifest.json, "
                        "table.csv, episodes.csv)");
    }
  }
  const fs::path manifest = dir / "manifest.json";
  const fs::path suite_file = FindSuiteFile(dir, manifest, options);
  SuiteLoadResult loaded = LoadSuite(suite_file, registry, ReadManifestStrings(manifest, "overrides"));
  if (!loaded.suite) {
    std::string msg = "cannot load the suite " + suite_file.string() + ":";
    for (const SuiteError& e : loaded.errors) msg += "\n  " + e.Format();
    throw ReportError(msg);
  }
  const Suite& suite = *loaded.suite;
  CsvTable table;
  std::vector<EpisodeLine> episodes;
  size_t c_label = 0, c_success = 0, c_collision = 0, c_timeout = 0, c_nav = 0, c_danger = 0;
  try {
    table = ReadCsv(dir / "table.csv");
    c_label = table.Column("label");
    c_success = table.Column("success rate");
    c_collision = table.Column("collision rate");
    c_timeout = table.Column("timeout rate");
    c_nav = table.Column("nav. time");
    c_danger = table.Column("danger freq.");
  } catch (const std::runtime_error& e) {
    throw ReportError((dir / "table.csv").string() + ": " + e.what());
  }
  EpisodesCsvRead read;
  try {
    read = ReadEpisodesCsvChecked(dir / "episodes.csv");
  } catch (const std::runtime_error& e) {
    throw ReportError(e.what());
  }
  episodes = std::move(read.lines);
  const std::string recorded_hash = ReadManifestField(manifest, "config_hash");

  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>"
       << XmlEscape(suite.name) << " · crowdsim-bench report</title>\n<style>" << ReportCss()
       << "</style></head><body>\n";
  html << "<h1>" << XmlEscape(suite.name) << "</h1>\n";
  if (!suite.description.empty())
    html << "<p class=\"meta\">" << XmlEscape(suite.description) << "</p>\n";
  html << "<p class=\"meta\">results: " << XmlEscape(dir.string())
       << " · suite file: " << XmlEscape(suite_file.string()) << " · " << episodes.size()
       << " episodes recorded";
  for (const char* key : {"git_commit", "finished_utc", "config_hash"}) {
    const std::string v = ReadManifestField(manifest, key);
    if (!v.empty()) html << " · " << key << " " << XmlEscape(v);
  }
  html << "</p>\n";
  if (read.damaged > 0) {
    html << "<p class=\"warn\">" << read.damaged << " damaged line(s) of episodes.csv were skipped (the first: "
         << XmlEscape(read.first_damage) << "): the figures show the readable episodes only.</p>\n";
  }
  if (!recorded_hash.empty() && recorded_hash != suite.ConfigHash()) {
    html << "<p class=\"warn\">The suite file changed since this run (config hash "
         << XmlEscape(suite.ConfigHash()) << " vs " << XmlEscape(recorded_hash)
         << "): the figures replay the current suite and may differ from the table.</p>\n";
  }

  // Table.
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

  // Charts.
  std::vector<Bar> outcome_bars, nav_bars, danger_bars;
  for (const auto& row : table.rows) {
    auto at = [&](size_t c) { return c < row.size() ? row[c] : std::string(); };
    const std::string label = at(c_label);
    const double s = Number(at(c_success)), c = Number(at(c_collision)), t = Number(at(c_timeout));
    outcome_bars.push_back(
        Bar{label,
            {{"success", s, palette::kSuccess},
             {"collision", c, palette::kCollision},
             {"timeout", t, palette::kTimeout},
             {"other", std::max(0.0, 1.0 - s - c - t), palette::kOther.WithAlpha(0.5)}}});
    nav_bars.push_back(Bar{label, {{"nav. time", Number(at(c_nav)), palette::kRobot}}});
    danger_bars.push_back(
        Bar{label, {{"danger freq.", Number(at(c_danger)), palette::kRobotCompare}}});
  }
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
  html << "<div class=\"chart\">" << BarChartSvg(outcome_bars, outcomes) << "</div>\n";
  html << "<div class=\"chart\">" << BarChartSvg(nav_bars, nav) << "</div>\n";
  html << "<div class=\"chart\">" << BarChartSvg(danger_bars, danger) << "</div>\n";
  html << "</div>\n";

  // Episodes: thumbnails per row, each linking to its full figure further down.
  std::ostringstream figures;
  html << "<h2>Episodes</h2>\n<p class=\"meta\">The first success, collision and timeout of each "
          "row, replayed "
          "exactly; click a picture for the full figure.</p>\n";
  for (size_t r = 0; r < table.rows.size(); ++r) {
    const auto& row = table.rows[r];
    const std::string label = c_label < row.size() ? row[c_label] : "";
    html << "<h3>row " << r + 1 << ": " << XmlEscape(label) << "</h3>\n<div class=\"thumbs\">\n";
    std::optional<size_t> suite_row;
    for (size_t i = 0; i < suite.rows.size(); ++i) {
      if (suite.rows[i].label == label) suite_row = i;
    }
    for (const Pick& pick : PickEpisodes(episodes, label)) {
      html << "<div class=\"thumb\"><b>first " << pick.outcome << "</b>";
      if (!pick.line) {
        html << "<div class=\"none\">no " << pick.outcome << " in this run</div></div>\n";
        continue;
      }
      if (!suite_row) {
        html << "<div class=\"none\">row not in the suite file any more</div></div>\n";
        continue;
      }
      const ReplayedEpisode replay =
          ReplayForFigure(suite, *suite_row, pick.line->episode, registry);
      const EpisodeFigure fig = MakeFigure(suite, replay);
      const Drawing drawing = DrawEpisode(fig);
      const std::string anchor =
          "fig-r" + std::to_string(*suite_row + 1) + "-e" + std::to_string(pick.line->episode);
      const std::string recorded = EpisodeStatusName(pick.line->outcome.status);
      const bool differs = replay.result.status != pick.line->outcome.status;
      html << " · episode " << pick.line->episode << "<a href=\"#" << anchor << "\"><img alt=\""
           << XmlEscape(label) << " episode " << pick.line->episode << "\" src=\"data:image/png;base64,"
           << Base64(PngBytes(drawing, options.thumbnail_scale)) << "\"></a>";
      if (differs)
        html << "<div class=\"warn\">replay: " << EpisodeStatusName(replay.result.status)
             << ", recorded: " << recorded << "</div>";
      html << "</div>\n";
      figures << "<div class=\"figure\" id=\"" << anchor << "\"><h3>row " << *suite_row + 1 << " "
              << XmlEscape(label) << ", episode " << pick.line->episode << " (first " << pick.outcome
              << ")</h3>\n"
              << ToSvg(drawing, SvgOptions{.standalone = false}) << "</div>\n";
    }
    html << "</div>\n";
  }
  html << "<h2>Figures</h2>\n" << figures.str();
  html << "<p class=\"meta\">Made by <code>crowdsim-bench report</code>; every episode can be "
          "drawn with "
          "<code>crowdsim-bench render SUITE --row R --episode K --out "
          "FILE.svg</code>.</p>\n</body></html>\n";
  return html.str();
}

}  // namespace crowdsim::render
