#include "crowdsim/render/learning_curve.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "crowdsim/bench/csv.h"
#include "crowdsim/render/figure_output.h"
#include "crowdsim/render/palette.h"
#include "crowdsim/render/results_folder.h"

namespace crowdsim::render {
namespace fs = std::filesystem;

namespace {

enum Outcome { kSuccessful, kCollided, kTimedOut, kOutcomes };

struct Validation {
  double episode = 0;
  double rate[kOutcomes] = {0, 0, 0};
};

std::vector<Validation> ReadValidations(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::vector<Validation> out;
  if (!std::getline(in, line)) return out;
  while (std::getline(in, line)) {
    const auto f = SplitCsvLine(line);
    if (f.size() < 4) continue;
    Validation v;
    v.episode = std::atof(f[0].c_str());
    for (int k = 0; k < kOutcomes; ++k) v.rate[k] = std::atof(f[1 + k].c_str());
    out.push_back(v);
  }
  return out;
}

std::string Fixed(double v, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

/// Tick spacing 1, 2 or 5 times a power of ten, at most 10 intervals over [0, max].
double TickStep(double max) {
  for (double decade = 1;; decade *= 10) {
    for (double m : {1.0, 2.0, 5.0}) {
      if (max / (m * decade) <= 10) return m * decade;
    }
  }
}

// The canvas and the plot area's margins (px).
constexpr double kWidth = 925, kHeight = 440;
constexpr double kLeft = 60, kRight = 215, kTop = 40, kBottom = 50;
constexpr Color kOutcomeColour[kOutcomes] = {palette::kSuccess, palette::kCollision,
                                             palette::kTimeout};
constexpr const char* kOutcomeName[kOutcomes] = {"success", "collision", "timeout"};

// The plot area: RL episodes 0..max_x across, rates 0..1 up.
struct Plot {
  double max_x = 1;
  double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
  Vec2 At(double episode, double rate) const {
    return Vec2(kLeft + pw * episode / max_x, kTop + ph * (1.0 - rate));
  }
};

// The last episode shown: of the RL episodes or of a validation, at least 1.
double EpisodeAxisEnd(const std::vector<RlEpisodeRow>& eps, const std::vector<Validation>& val) {
  double max_x = static_cast<double>(eps.size());
  for (const auto& v : val) max_x = std::max(max_x, v.episode);
  return std::max(max_x, 1.0);
}

// The title, the rate grid and ticks, the episode ticks, the frame and the axis labels.
void DrawAxes(Drawing* d, const Plot& p, const std::string& title, size_t episodes) {
  d->AddText("chart-title", Vec2(kLeft, 24),
             title + ": learning curve (" + std::to_string(episodes) + " RL episodes)", 15,
             palette::kInk, TextAnchor::kStart, true);
  Style grid;
  grid.stroke = Color{221, 221, 221, 1.0};
  Style axis;
  axis.stroke = palette::kInk;
  for (int k = 0; k <= 5; ++k) {
    const double r = k / 5.0;
    d->AddPolyline("grid", {p.At(0, r), p.At(p.max_x, r)}, grid);
    d->AddText("tick", p.At(0, r) + Vec2(-8, 4), Fixed(r, 1), 12, palette::kInk, TextAnchor::kEnd);
  }
  const double step = TickStep(p.max_x);
  for (double e = 0; e <= p.max_x + 1e-9; e += step) {
    d->AddPolyline("tick", {p.At(e, 0), p.At(e, 0) + Vec2(0, 5)}, axis);
    d->AddText("tick", p.At(e, 0) + Vec2(0, 18), std::to_string(static_cast<long>(e)), 12,
               palette::kInk, TextAnchor::kMiddle);
  }
  d->AddPolygon("axis", {p.At(0, 0), p.At(p.max_x, 0), p.At(p.max_x, 1), p.At(0, 1)}, axis);
  d->AddText("axis-label", Vec2(kLeft + p.pw / 2, d->height - 12), "RL episode", 12, palette::kInk,
             TextAnchor::kMiddle);
  d->AddText("axis-label", Vec2(8, kTop - 10), "rate", 12, palette::kInk);
}

// Rolling rates over the last `window` episodes and epsilon, at most ~400 points per line.
void DrawRollingRates(Drawing* d, const Plot& p, const std::vector<RlEpisodeRow>& eps,
                      std::size_t window) {
  if (eps.size() < 2) return;
  std::vector<Vec2> line[kOutcomes];
  std::vector<Vec2> epsilon;
  int count[kOutcomes] = {0, 0, 0};
  const std::size_t stride = std::max<std::size_t>(1, eps.size() / 400);
  for (std::size_t i = 0; i < eps.size(); ++i) {
    ++count[eps[i].outcome];
    if (i >= window) --count[eps[i - window].outcome];
    if (i % stride != 0 && i + 1 != eps.size()) continue;
    const double n = static_cast<double>(std::min(i + 1, window));
    for (int k = 0; k < kOutcomes; ++k) line[k].push_back(p.At(i + 1.0, count[k] / n));
    epsilon.push_back(p.At(i + 1.0, eps[i].epsilon));
  }
  for (int k = 0; k < kOutcomes; ++k) {
    Style s;
    s.stroke = kOutcomeColour[k];
    s.stroke_width = 1.5;
    d->AddPolyline(std::string("rolling ") + kOutcomeName[k], std::move(line[k]), s);
  }
  Style s;
  s.stroke = palette::kMutedInk;
  s.dashed = true;
  d->AddPolyline("epsilon", std::move(epsilon), s);
}

// Validation points (greedy, fixed scenarios); episode 0 is the imitation start.
void DrawValidations(Drawing* d, const Plot& p, const std::vector<Validation>& val) {
  for (const auto& v : val) {
    for (int k = 0; k < kOutcomes; ++k) {
      Style s;
      s.fill = Color{255, 255, 255, 1.0};
      s.stroke = kOutcomeColour[k];
      s.stroke_width = 2;
      d->AddCircle(std::string("validation ") + kOutcomeName[k], p.At(v.episode, v.rate[k]), 4, s);
    }
  }
}

// The legend right of the plot: the lines, the markers and how to read them.
void DrawLegend(Drawing* d, const Plot& p, std::size_t window) {
  const double lx = kLeft + p.pw + 15;
  for (int k = 0; k < kOutcomes; ++k) {
    const double y = kTop + 10 + 20 * k;
    Style s;
    s.stroke = kOutcomeColour[k];
    s.stroke_width = 2;
    d->AddPolyline("legend-line", {Vec2(lx, y), Vec2(lx + 22, y)}, s);
    d->AddText("legend", Vec2(lx + 28, y + 4), kOutcomeName[k], 12, palette::kInk);
  }
  Style dashed;
  dashed.stroke = palette::kMutedInk;
  dashed.dashed = true;
  d->AddPolyline("legend-line", {Vec2(lx, kTop + 70), Vec2(lx + 22, kTop + 70)}, dashed);
  d->AddText("legend", Vec2(lx + 28, kTop + 74), "epsilon", 12, palette::kInk);
  Style marker;
  marker.fill = Color{255, 255, 255, 1.0};
  marker.stroke = palette::kInk;
  marker.stroke_width = 2;
  d->AddCircle("legend-marker", Vec2(lx + 11, kTop + 90), 4, marker);
  d->AddText("legend", Vec2(lx + 28, kTop + 94), "validation (greedy)", 12, palette::kInk);
  const std::string notes[] = {"lines: rolling rates of the",
                               "last " + std::to_string(window) + " RL episodes (exploring)",
                               "points: validation episodes;", "at 0 the starting weights"};
  for (int i = 0; i < 4; ++i) {
    d->AddText("legend-note", Vec2(lx, kTop + 120 + 14 * i), notes[i], 10, palette::kMutedInk);
  }
}

}  // namespace

std::vector<RlEpisodeRow> ParseRlEpisodes(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::vector<RlEpisodeRow> out;
  if (!std::getline(in, line)) return out;
  std::map<std::string, std::size_t> col;
  const auto header = SplitCsvLine(line);
  for (std::size_t i = 0; i < header.size(); ++i) col[header[i]] = i;
  const char* names[] = {"phase",  "index",         "epsilon",     "outcome",       "loss",
                         "memory", "mem_imitation", "mem_success", "mem_collision", "mem_timeout"};
  std::size_t need = 0;
  for (const char* n : names) {
    if (!col.count(n)) return out;
    need = std::max(need, col[n]);
  }
  auto number = [](const std::string& s) { return std::atof(s.c_str()); };
  while (std::getline(in, line)) {
    const auto f = SplitCsvLine(line);
    if (f.size() <= need || f[col["phase"]] != "rl") continue;
    RlEpisodeRow e;
    e.index = std::atoi(f[col["index"]].c_str());
    e.epsilon = number(f[col["epsilon"]]);
    const std::string& o = f[col["outcome"]];
    e.outcome =
        o == "success" ? kSuccessful : (o.rfind("collision", 0) == 0 ? kCollided : kTimedOut);
    e.loss = number(f[col["loss"]]);
    e.memory = number(f[col["memory"]]);
    for (int k = 0; k < 4; ++k) e.sources[k] = number(f[col[names[6 + k]]]);
    out.push_back(e);
  }
  return out;
}

Drawing LearningCurveDrawing(const std::string& episodes_csv, const std::string& validation_csv,
                             const std::string& title) {
  const std::vector<RlEpisodeRow> eps = ParseRlEpisodes(episodes_csv);
  const std::vector<Validation> val = ReadValidations(validation_csv);
  Plot p;
  p.max_x = EpisodeAxisEnd(eps, val);
  Drawing d;
  d.width = kWidth;
  d.height = kHeight;
  // Rolling rates over a window of about 1/25 of the run (at least 50 episodes).
  const std::size_t window = std::max<std::size_t>(50, eps.size() / 25);
  DrawAxes(&d, p, title, eps.size());
  DrawRollingRates(&d, p, eps, window);
  DrawValidations(&d, p, val);
  DrawLegend(&d, p, window);
  return d;
}

void WriteLearningCurve(const fs::path& folder, const std::string& title) {
  const fs::path episodes = folder / "training_episodes.csv";
  const fs::path validation = folder / "training_log.csv";
  if (!fs::exists(episodes) && !fs::exists(validation)) {
    throw std::runtime_error("'" + folder.string() +
                             "' holds neither training_episodes.csv nor "
                             "training_log.csv: not a training folder");
  }
  const Drawing d =
      LearningCurveDrawing(ReadTextFileIfExists(episodes), ReadTextFileIfExists(validation), title);
  WriteFigure(d, folder / "learning_curve.svg");
  WriteFigure(d, folder / "learning_curve.png", 1.0);
}

}  // namespace crowdsim::render
