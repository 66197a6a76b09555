// The visual suite report: one self-contained HTML file (no external resources) with the
// table, bar charts and, per row, figures of its first success, collision and timeout.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"

namespace crowdsim::render {

/// A report that cannot be made: the message names the file or value and the fix.
class ReportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Report choices.
struct ReportOptions {
  std::filesystem::path suite_file;  ///< the suite to replay; empty: manifest.json's suite_file
  double thumbnail_scale = 0.36;     ///< thumbnail px per figure px
  /// Receives the page's warnings as text (damaged lines, a suite changed since the run), for
  /// the command line to say them too; may be null.
  std::vector<std::string>* warnings = nullptr;
};

/// The style sheet every report page embeds.
const char* ReportCss();

/// The report of a `crowdsim-bench run` output folder (manifest.json, table.csv, episodes.csv);
/// replays the shown episodes with the suite's plugins. Throws ReportError.
std::string BuildReport(const std::filesystem::path& results_dir, PluginRegistry& registry,
                        const ReportOptions& options = {});

}  // namespace crowdsim::render
