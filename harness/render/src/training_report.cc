#include "crowdsim/render/training_report.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <sstream>

#include "crowdsim/bench/csv.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/render/learning_curve.h"
#include "crowdsim/render/report.h"
#include "crowdsim/render/results_folder.h"
#include "crowdsim/render/svg_writer.h"
#include "crowdsim/render/xml_escape.h"

namespace crowdsim::render {
namespace fs = std::filesystem;

namespace {

/// Outcomes, loss and memory of a block of consecutive RL episodes.
struct Block {
  int first = 0, last = 0, episodes = 0;
  std::array<int, 3> outcomes{};  // success, collision, timeout
  double epsilon_sum = 0, loss_sum = 0;
  std::array<double, 4> memory{};  // last episode's entries by source
  double memory_size = 0;
};

// `v` with `decimals` decimals.
std::string Fixed(double v, int decimals) {
  char buf[40];
  std::snprintf(buf, sizeof(buf), "%.*f", decimals, v);
  return buf;
}

// The RL episodes summed by block of `block_size` consecutive indices.
std::vector<Block> RlBlocks(const std::string& csv, int block_size) {
  std::vector<Block> blocks;
  for (const RlEpisodeRow& e : ParseRlEpisodes(csv)) {
    if (blocks.empty() || e.index / block_size != blocks.back().first / block_size) {
      blocks.push_back(Block{});
      blocks.back().first = e.index;
    }
    Block& b = blocks.back();
    b.last = e.index;
    ++b.episodes;
    ++b.outcomes[e.outcome];
    b.epsilon_sum += e.epsilon;
    b.loss_sum += e.loss;
    b.memory_size = e.memory;
    b.memory = e.sources;
  }
  return blocks;
}

// The document head, the training's name and folder, and its learning curve.
// A training that stopped before its end says so at the top (its summary.json's "finished":
// false was the only sign, deep in the JSON at the bottom).
std::string UnfinishedNote(const fs::path& dir) {
  const fs::path summary = dir / "summary.json";
  if (ReadManifestBool(summary, "finished").value_or(true)) return "";
  // summary.json's phase and counter (training_checkpoint.h: 0 demonstrations, 1 imitation
  // epochs, 2 RL episodes).
  const long phase = ReadManifestInteger(summary, "phase");
  const long done = ReadManifestInteger(summary, "counter");
  const char* const kPhases[] = {"demonstrations", "imitation epochs", "RL episodes"};
  std::string text = "Unfinished: the training stopped";
  if (phase >= 0 && phase < 3 && done >= 0) {
    text += " after " + std::to_string(done) + " " + kPhases[phase];
    if (phase == 2) {
      text += " of its " + std::to_string(ReadManifestInteger(summary, "/procedure/rl_episodes"));
    }
  }
  return text + "; continue it with the same `crowdsim-bench train` command and --resume.";
}

void WriteHeader(std::ostream& html, const fs::path& dir, const std::string& name,
                 const std::string& episodes, const std::string& validation) {
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" << XmlEscape(name)
       << " · crowdsim-bench training report</title>\n<style>" << ReportCss()
       << "</style></head><body>\n<h1>Training " << XmlEscape(name) << "</h1>\n<p class=\"meta\">"
       << XmlEscape(dir.string()) << "</p>\n";
  if (const std::string note = UnfinishedNote(dir); !note.empty()) {
    html << "<p class=\"warn\">" << XmlEscape(note) << "</p>\n";
  }
  html << "<h2>Learning curve</h2>\n<div class=\"figure\">"
       << ToSvg(LearningCurveDrawing(episodes, validation, name), SvgOptions{.standalone = false})
       << "</div>\n";
}

// training_log.csv as a table: the greedy validations.
void WriteValidations(std::ostream& html, const std::string& validation) {
  html << "<h2>Validation (greedy, fixed episodes)</h2>\n";
  if (validation.empty()) {
    html << "<p class=\"none\">no validation ran</p>\n";
    return;
  }
  html << "<table>\n";
  std::istringstream in(validation);
  bool first = true;
  for (std::string line; std::getline(in, line);) {
    html << "<tr>";
    for (const auto& f : SplitCsvLine(line)) {
      html << (first ? "<th>" : "<td>") << XmlEscape(f) << (first ? "</th>" : "</td>");
    }
    html << "</tr>\n";
    first = false;
  }
  html << "</table>\n";
}

// One block's row: outcome rates, mean epsilon and loss, the memory and its sources.
void WriteBlockRow(std::ostream& html, const Block& b) {
  const double n = std::max(1, b.episodes);
  const double m = std::max(1.0, b.memory_size);
  html << "<tr><td>" << b.first << "-" << b.last << "</td>";
  for (int k = 0; k < 3; ++k) html << "<td>" << Fixed(b.outcomes[k] / n, 3) << "</td>";
  html << "<td>" << Fixed(b.epsilon_sum / n, 3) << "</td><td>" << Fixed(b.loss_sum / n, 5)
       << "</td><td>" << static_cast<long>(b.memory_size) << "</td>";
  for (int k = 0; k < 4; ++k) html << "<td>" << Fixed(b.memory[k] / m, 3) << "</td>";
  html << "</tr>\n";
}

// The RL episodes of training_episodes.csv summed by block of 500.
void WriteBlocks(std::ostream& html, const std::string& episodes) {
  const std::vector<Block> blocks = RlBlocks(episodes, 500);
  html << "<h2>RL episodes by block of 500</h2>\n<p class=\"meta\">Outcomes while exploring, mean "
          "epsilon and loss, and the replay memory after the block: its size and the share of "
          "entries from imitation, success, collision and timeout episodes.</p>\n";
  if (blocks.empty()) {
    html << "<p class=\"none\">no RL episode logged yet</p>\n";
    return;
  }
  html << "<table>\n<tr><th>episodes</th><th>success</th><th>collision</th><th>timeout</th>"
          "<th>epsilon</th><th>loss</th><th>memory</th><th>imitation</th><th>success</th>"
          "<th>collision</th><th>timeout</th></tr>\n";
  for (const Block& b : blocks) WriteBlockRow(html, b);
  html << "</table>\n";
}

// summary.json as written when the training stopped; closes the document.
void WriteSummary(std::ostream& html, const std::string& summary) {
  html << "<h2>Summary</h2>\n";
  if (summary.empty()) {
    html << "<p class=\"none\">no summary.json yet (written when a training stops)</p>\n";
  } else {
    html << "<pre>" << XmlEscape(summary) << "</pre>\n";
  }
  html << "<p class=\"meta\">Made by <code>crowdsim-bench report</code> from the training folder's "
          "files.</p>\n</body></html>\n";
}

}  // namespace

bool IsTrainingFolder(const fs::path& dir) {
  return fs::exists(dir / "training_episodes.csv") ||
         fs::exists(dir / "training_episodes.csv.gz") || fs::exists(dir / "training_log.csv");
}

std::string BuildTrainingReport(const fs::path& dir) {
  if (!IsTrainingFolder(dir)) {
    throw ReportError("'" + dir.string() +
                      "' is not a training folder (no training_episodes.csv "
                      "or training_log.csv): give the --out of `crowdsim-bench train`");
  }
  std::string name = ReadManifestField(dir / "summary.json", "name");
  if (name.empty()) name = dir.filename().string();
  const std::string episodes = ReadTrainingEpisodes(dir);
  const std::string validation = ReadTextFileIfExists(dir / "training_log.csv");
  std::ostringstream html;
  WriteHeader(html, dir, name, episodes, validation);
  WriteValidations(html, validation);
  WriteBlocks(html, episodes);
  WriteSummary(html, ReadTextFileIfExists(dir / "summary.json"));
  return html.str();
}

}  // namespace crowdsim::render
