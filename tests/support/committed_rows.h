// A committed table's row run again, for tests that check it reruns identically (the learned
// rows with their BLAS kernel, the ORCA rows on the scalar path).
#pragma once

#include <filesystem>
#include <string>

#include "crowdsim/bench/plugin_registry.h"

namespace crowdsim::testing {

/// The header line and the lines of `row` of an episodes.csv text.
std::string LinesOfRow(const std::string& csv, const std::string& row);

/// `row` of suites/<suite>.yaml run alone (two jobs) into `out_dir`, and the same row's
/// episodes in results/<suite>/episodes.csv, both without the timing columns. Paths in the
/// suites are taken from the repository root, which becomes the working directory. Throws
/// std::runtime_error when the suite does not load or has no such row.
struct RowRerun {
  std::string rerun;
  std::string committed;
};
RowRerun RerunCommittedRow(PluginRegistry& registry, const std::filesystem::path& out_dir,
                           const std::string& suite_name, const std::string& row);

/// Why a committed row of a learned policy cannot be expected to rerun identically here, or ""
/// when it can: no learned-policy plugins in this build (built without libtorch), a processor
/// without AVX2 and FMA (no Haswell kernels), or an OPENBLAS_CORETYPE set outside the harness
/// to other kernels than the tables were made with.
std::string LearnedRowsSkipReason();

}  // namespace crowdsim::testing
