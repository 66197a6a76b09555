// The report of a training folder (`crowdsim-bench report results/train/<name>`): procedure and
// build (summary.json), the learning curve, the validations, and per block of RL episodes the
// outcomes, loss and replay-memory composition, as one self-contained HTML page.
#pragma once

#include <filesystem>
#include <string>

namespace crowdsim::render {

/// True when `dir` looks like a training folder (training_episodes.csv or training_log.csv).
bool IsTrainingFolder(const std::filesystem::path& dir);

/// The page. Throws ReportError when `dir` is not a training folder.
std::string BuildTrainingReport(const std::filesystem::path& dir);

}  // namespace crowdsim::render
