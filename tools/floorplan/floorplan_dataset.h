// The floor-plan dataset: import every source plan, index their statistics, keep a curated
// set, and pick the easy / medium / hard worlds (README.md, "Curation" and "Difficulty").
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include "crowdsim/world_file.h"

namespace crowdsim::floorplan {

/// Curation thresholds: a plan is kept when all hold.
struct CurationRules {
  double min_free_area_m2 = 25.0;       ///< navigable area of the largest disc component
  double min_component_share = 0.4;     ///< that component / all interior free area
  double min_kept_coverage_pct = 80.0;  ///< blocked area covered by the kept rectangles
};

/// Rules for choosing the easy / medium / hard worlds among the curated Gibson plans.
struct DifficultyPick {
  double min_kept_coverage_pct = 90.0;  ///< the simulated world must look like the plan
  double min_free_area_m2 = 40.0;
  double max_free_area_m2 = 200.0;
  double quantiles[3] = {0.1, 0.5, 0.9};  ///< of the difficulty ranking: easy, medium, hard
};

/// What `floorplan dataset` does and where it writes.
struct DatasetOptions {
  std::filesystem::path source;      ///< folder with gibson/ and hm3d/ (../shared/floorplans)
  std::filesystem::path out;         ///< index.csv, curated.csv and curated world files
  std::filesystem::path gibson_out;  ///< easy/medium/hard.yaml; empty = skip
  std::uint64_t seed = 1;
  int train_pairs = 200;          ///< per curated world (size of the committed set)
  int picked_train_pairs = 2000;  ///< per easy/medium/hard world
  CurationRules rules;
  DifficultyPick pick;
};

/// Source images under `source`: gibson/maps/*.png then hm3d/*_0.1m.png, sorted.
std::vector<std::filesystem::path> ListSourcePlans(const std::filesystem::path& source);

/// Runs the whole dataset build, logging one line per plan to `log`. Returns 0, or throws
/// FloorplanError when the source folder has no plans.
int BuildDataset(const DatasetOptions& options, std::ostream& log);

}  // namespace crowdsim::floorplan
