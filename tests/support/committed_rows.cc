#include "committed_rows.h"

#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "crowdsim/bench/episode_columns.h"
#include "crowdsim/bench/runner.h"
#include "crowdsim/bench/suite.h"
#include "temp_dir.h"
#include "test_paths.h"

namespace crowdsim::testing {

std::string LinesOfRow(const std::string& csv, const std::string& row) {
  std::istringstream in(csv);
  std::string line, out;
  std::getline(in, line);
  out = line + "\n";
  while (std::getline(in, line)) {
    if (line.rfind(row + ",", 0) == 0) out += line + "\n";
  }
  return out;
}

RowRerun RerunCommittedRow(PluginRegistry& registry, const std::filesystem::path& out_dir,
                           const std::string& suite_name, const std::string& row) {
  std::filesystem::current_path(SourceDir());  // the suites name files from the root
  const SuiteLoadResult loaded =
      LoadSuite(SourceDir() / "suites" / (suite_name + ".yaml"), registry);
  if (!loaded.suite) throw std::runtime_error("suites/" + suite_name + ".yaml does not load");
  Suite suite = *loaded.suite;
  std::erase_if(suite.rows, [&](const RowSpec& r) { return r.label != row; });
  suite.summaries.clear();
  if (suite.rows.size() != 1) throw std::runtime_error("no row " + row + " in " + suite_name);
  RunOptions o;
  o.out_dir = out_dir;
  o.jobs = 2;
  o.progress = false;
  RunSuite(suite, registry, o);
  RowRerun result;
  result.rerun = WithoutTimingColumns(ReadText(out_dir / "episodes.csv"));
  result.committed = LinesOfRow(
      WithoutTimingColumns(ReadText(SourceDir() / "results" / suite_name / "episodes.csv")), row);
  return result;
}

std::string LearnedRowsSkipReason() {
  if (!std::filesystem::exists(PluginDir() / "crowdsim_sarl.so") ||
      !std::filesystem::exists(PluginDir() / "crowdsim_cadrl.so")) {
    return "no learned-policy plugins in this build (built without libtorch)";
  }
#if defined(__x86_64__)
  if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) {
    return "this processor has no AVX2 and FMA: OpenBLAS cannot run the Haswell kernels the "
           "committed tables were made with";
  }
#endif
  const char* core = std::getenv("OPENBLAS_CORETYPE");
  if (core != nullptr && std::string(core) != "Haswell") {
    return "OPENBLAS_CORETYPE=" + std::string(core) +
           " is set outside the harness; the committed tables were made with OpenBLAS's "
           "Haswell kernels";
  }
  return "";
}

}  // namespace crowdsim::testing
