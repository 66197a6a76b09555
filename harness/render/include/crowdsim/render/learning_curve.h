// The learning curve of a training folder: rolling success / collision / timeout rates of the
// RL episodes (training_episodes.csv), epsilon, and the greedy validation points
// (training_log.csv). Drawn from the files alone, so it works for finished, running and
// resumed trainings; `train` writes it at every checkpoint, `report` shows it.
#pragma once

#include <filesystem>
#include <string>

#include "crowdsim/render/drawing.h"

namespace crowdsim::render {

/// The figure from the two files' contents (either may be empty).
Drawing LearningCurveDrawing(const std::string& episodes_csv, const std::string& validation_csv,
                             const std::string& title);

/// Reads `folder`/training_episodes.csv and training_log.csv and writes
/// `folder`/learning_curve.svg and learning_curve.png. Throws std::runtime_error when the
/// folder holds neither file.
void WriteLearningCurve(const std::filesystem::path& folder, const std::string& title);

}  // namespace crowdsim::render
