// What the suite report reads: a `crowdsim-bench run` output folder (manifest.json, table.csv,
// episodes.csv) and the suite it ran, loaded again with the run's overrides to replay episodes.
#pragma once

#include <filesystem>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/render/report.h"
#include "crowdsim/render/results_folder.h"

namespace crowdsim::render {

/// Where table.csv keeps the columns the charts draw.
struct TableColumns {
  size_t label = 0, success = 0, collision = 0, timeout = 0, nav = 0, danger = 0;
};

/// A results folder as the report uses it.
struct ReportInputs {
  std::filesystem::path dir;         ///< the results folder
  std::filesystem::path manifest;    ///< its manifest.json
  std::filesystem::path suite_file;  ///< the suite replayed (--suite or the manifest's)
  Suite suite;
  CsvTable table;  ///< table.csv
  TableColumns columns;
  EpisodesCsvRead episodes;  ///< episodes.csv, damaged lines skipped
  /// Written by crowdsim_bench.evaluate(): its one row is a Python function (the manifest's
  /// policy file "<python>") in the place of a suite row, which the report cannot replay, and
  /// its config hash is of the suite with that row, not of the suite file.
  bool python_policy = false;
};

/// Reads the folder and loads its suite. Throws ReportError naming the file and the fix.
ReportInputs ReadReportInputs(const std::filesystem::path& dir, PluginRegistry& registry,
                              const ReportOptions& options);

}  // namespace crowdsim::render
