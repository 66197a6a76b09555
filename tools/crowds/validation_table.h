// The validation's table: one line per scene and human model, as CSV and Markdown.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "scene_validation.h"

namespace crowdsim::crowds {

/// A scene's people walked by one model, summarised.
struct ValidationRow {
  std::string scene;
  std::string model;
  int people = 0;                ///< recorded people validated
  double ade = 0.0;              ///< m, mean over the people
  double fde = 0.0;              ///< m, mean over the people
  double collision_rate = 0.0;   ///< share of the people who overlapped somebody
  double simulated_speed = 0.0;  ///< m/s, mean over the people
  double recorded_speed = 0.0;   ///< m/s, mean over the people
};

/// The row of `people` (none: zeros).
ValidationRow Summarise(const std::string& scene, const std::string& model,
                        std::span<const PersonValidation> people);

/// The table as CSV (a header, then one line a row; 4 decimals).
std::string ValidationCsv(std::span<const ValidationRow> rows);
/// The table as Markdown (3 decimals).
std::string ValidationMarkdown(std::span<const ValidationRow> rows);

}  // namespace crowdsim::crowds
