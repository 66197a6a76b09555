// The learning curve of a training folder: rolling success / collision / timeout rates of the
// RL episodes (training_episodes.csv), epsilon, and the greedy validation points
// (training_log.csv). Drawn from the files alone, so it works for finished, running and
// resumed trainings; `train` writes it at every checkpoint, `report` shows it.
#pragma once

#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "crowdsim/render/drawing.h"

namespace crowdsim::render {

/// One RL episode of training_episodes.csv.
struct RlEpisodeRow {
  int index = 0;
  double epsilon = 0.0;
  int outcome = 2;  ///< 0 success, 1 collision (human or obstacle), 2 timeout or other
  double loss = 0.0;
  double memory = 0.0;              ///< replay-memory entries after it
  std::array<double, 4> sources{};  ///< of which from imitation, success, collision, timeout
};

/// The RL episodes of a training_episodes.csv text, columns found by name (other phases and
/// short lines skipped; empty when the header lacks a column).
std::vector<RlEpisodeRow> ParseRlEpisodes(const std::string& episodes_csv);

/// The figure from the two files' contents (either may be empty).
Drawing LearningCurveDrawing(const std::string& episodes_csv, const std::string& validation_csv,
                             const std::string& title);

/// Reads `folder`/training_episodes.csv and training_log.csv and writes
/// `folder`/learning_curve.svg and learning_curve.png. Throws std::runtime_error when the
/// folder holds neither file.
void WriteLearningCurve(const std::filesystem::path& folder, const std::string& title);

}  // namespace crowdsim::render
