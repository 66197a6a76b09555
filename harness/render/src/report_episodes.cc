#include "crowdsim/render/report_episodes.h"

#include <optional>
#include <sstream>
#include <vector>

#include "crowdsim/render/base64.h"
#include "crowdsim/render/cairo_backend.h"
#include "crowdsim/render/episode_replay.h"
#include "crowdsim/render/svg_writer.h"
#include "crowdsim/render/xml_escape.h"

namespace crowdsim::render {
namespace {

// What a thumbnail shows: the first episode of a row with a given outcome.
struct Pick {
  std::string outcome;  // "success", "collision", "timeout"
  std::optional<EpisodeLine> line;
};

// The first success, collision and timeout of the row labelled `label`.
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

// The suite row labelled `label` (the last of that label), if the suite still has it.
std::optional<size_t> SuiteRow(const Suite& suite, const std::string& label) {
  std::optional<size_t> suite_row;
  for (size_t i = 0; i < suite.rows.size(); ++i) {
    if (suite.rows[i].label == label) suite_row = i;
  }
  return suite_row;
}

// One picked episode, replayed: its thumbnail (closing the thumbnail's box) and its full figure.
void WritePicture(std::ostream& thumbs, std::ostream& figures, const ReportInputs& in,
                  size_t suite_row, const std::string& label, const Pick& pick,
                  PluginRegistry& registry, const ReportOptions& options) {
  const ReplayedEpisode replay = ReplayForFigure(in.suite, suite_row, pick.line->episode, registry);
  const EpisodeFigure fig = MakeFigure(in.suite, replay);
  const Drawing drawing = DrawEpisode(fig);
  const std::string anchor =
      "fig-r" + std::to_string(suite_row + 1) + "-e" + std::to_string(pick.line->episode);
  const std::string recorded = EpisodeStatusName(pick.line->outcome.status);
  const bool differs = replay.result.status != pick.line->outcome.status;
  thumbs << " · episode " << pick.line->episode << "<a href=\"#" << anchor << "\"><img alt=\""
         << XmlEscape(label) << " episode " << pick.line->episode
         << "\" src=\"data:image/png;base64," << Base64(PngBytes(drawing, options.thumbnail_scale))
         << "\"></a>";
  if (differs)
    thumbs << "<div class=\"warn\">replay: " << EpisodeStatusName(replay.result.status)
           << ", recorded: " << recorded << "</div>";
  thumbs << "</div>\n";
  figures << "<div class=\"figure\" id=\"" << anchor << "\"><h3>row " << suite_row + 1 << " "
          << XmlEscape(label) << ", episode " << pick.line->episode << " (first " << pick.outcome
          << ")</h3>\n"
          << ToSvg(drawing, SvgOptions{.standalone = false}) << "</div>\n";
}

// Table row `r`: its heading and three thumbnails; their full figures go to `figures`.
void WriteRow(std::ostream& thumbs, std::ostream& figures, const ReportInputs& in, size_t r,
              PluginRegistry& registry, const ReportOptions& options) {
  const auto& row = in.table.rows[r];
  const std::string label = in.columns.label < row.size() ? row[in.columns.label] : "";
  thumbs << "<h3>row " << r + 1 << ": " << XmlEscape(label) << "</h3>\n<div class=\"thumbs\">\n";
  const std::optional<size_t> suite_row = SuiteRow(in.suite, label);
  for (const Pick& pick : PickEpisodes(in.episodes.lines, label)) {
    thumbs << "<div class=\"thumb\"><b>first " << pick.outcome << "</b>";
    if (!pick.line) {
      thumbs << "<div class=\"none\">no " << pick.outcome << " in this run</div></div>\n";
    } else if (in.python_policy) {
      thumbs << "<div class=\"none\">a Python policy (crowdsim_bench.evaluate), which the report "
                "cannot replay</div></div>\n";
    } else if (!suite_row) {
      thumbs << "<div class=\"none\">row not in the suite file any more</div></div>\n";
    } else {
      WritePicture(thumbs, figures, in, *suite_row, label, pick, registry, options);
    }
  }
  thumbs << "</div>\n";
}

}  // namespace

EpisodeSections EpisodePictures(const ReportInputs& in, PluginRegistry& registry,
                                const ReportOptions& options) {
  std::ostringstream thumbs, figures;
  for (size_t r = 0; r < in.table.rows.size(); ++r) {
    WriteRow(thumbs, figures, in, r, registry, options);
  }
  return {thumbs.str(), figures.str()};
}

}  // namespace crowdsim::render
