#include "crowdsim/render/report_inputs.h"

#include <stdexcept>

namespace crowdsim::render {
namespace fs = std::filesystem;
namespace {

// The folder exists and holds the three files `crowdsim-bench run` writes.
void CheckResultsFolder(const fs::path& dir) {
  if (!fs::is_directory(dir)) {
    // A file (the suite, its table.md) was said not to exist.
    std::error_code ec;
    throw ReportError("results folder '" + dir.string() + "' " +
                      (fs::exists(dir, ec) ? "is a file, not a folder" : "does not exist") +
                      " (give the --out folder of `crowdsim-bench run`, e.g. runs/quick)");
  }
  // A folder of `run` without its tables: a shard (merge first) or a run that did not finish.
  // (Builds before 2026-11-26 left an earlier run's tables in place while a rerun went on: an
  // empty finished_utc tells such a folder too.)
  const fs::path manifest = dir / "manifest.json";
  // A damaged manifest ties its episodes to no configuration: a resumed run refuses them too.
  if (fs::exists(manifest) && ReadManifestField(manifest, "config_hash").empty()) {
    throw ReportError("'" + manifest.string() +
                      "' is damaged or not crowdsim-bench's (it names no config_hash), so which "
                      "configuration made the folder's episodes is unknown and neither report nor "
                      "a resumed run can use them: run the suite again into a new --out folder "
                      "(or into this one with --fresh, which replaces them)");
  }
  if (fs::exists(manifest) &&
      (!fs::exists(dir / "table.csv") || ReadManifestField(manifest, "finished_utc").empty())) {
    const std::string shard = ReadManifestField(manifest, "shard");
    if (!shard.empty()) {
      throw ReportError("'" + dir.string() + "' is shard " + shard +
                        " of a run, which has no tables: join the shards with `crowdsim-bench "
                        "merge SHARD_DIR... --out DIR` and report DIR");
    }
    throw ReportError("'" + dir.string() +
                      "' holds a run that has not finished (no table.csv, or a manifest without "
                      "finished_utc): rerun the same "
                      "`crowdsim-bench run` command to finish it (it resumes), then report");
  }
  for (const char* f : {"manifest.json", "table.csv", "episodes.csv"}) {
    if (!fs::exists(dir / f)) {
      throw ReportError("'" + dir.string() + "' has no " + f +
                        ": give the folder `crowdsim-bench run` wrote (it holds manifest.json, "
                        "table.csv, episodes.csv)");
    }
  }
}

// The suite to replay: --suite when given, else the one the manifest names.
fs::path FindSuiteFile(const fs::path& dir, const fs::path& manifest,
                       const ReportOptions& options) {
  if (!options.suite_file.empty()) {
    if (!fs::exists(options.suite_file))
      throw ReportError("suite file '" + options.suite_file.string() + "' does not exist");
    return options.suite_file;
  }
  const std::string recorded = ReadManifestField(manifest, "suite_file");
  if (recorded.empty()) {
    throw ReportError((dir / "manifest.json").string() +
                      " names no suite_file: pass the suite with --suite FILE");
  }
  const fs::path p(recorded);
  if (fs::exists(p)) return p;
  throw ReportError(
      "the suite file '" + recorded + "' named in " + (dir / "manifest.json").string() +
      " was not found from " + fs::current_path().string() +
      " (run the report from the folder the suite was run from, or pass --suite FILE)");
}

// The suite with the overrides the run was given (`--set`, recorded in the manifest).
Suite LoadRecordedSuite(const fs::path& suite_file, const fs::path& manifest,
                        PluginRegistry& registry) {
  SuiteLoadResult loaded =
      LoadSuite(suite_file, registry, ReadManifestStrings(manifest, "overrides"));
  if (!loaded.suite) {
    std::string msg = "cannot load the suite " + suite_file.string() + ":";
    for (const SuiteError& e : loaded.errors) msg += "\n  " + e.Format();
    throw ReportError(msg);
  }
  return std::move(*loaded.suite);
}

// table.csv and the columns the charts draw.
void ReadTable(const fs::path& dir, CsvTable* table, TableColumns* columns) {
  try {
    *table = ReadCsv(dir / "table.csv");
    columns->label = table->Column("label");
    columns->success = table->Column("success rate");
    columns->collision = table->Column("collision rate");
    columns->timeout = table->Column("timeout rate");
    columns->nav = table->Column("nav. time");
    columns->danger = table->Column("danger freq.");
  } catch (const std::runtime_error& e) {
    throw ReportError((dir / "table.csv").string() + ": " + e.what());
  }
}

// episodes.csv, its damaged lines skipped and counted.
EpisodesCsvRead ReadEpisodes(const fs::path& dir) {
  try {
    return ReadEpisodesCsvChecked(dir / "episodes.csv");
  } catch (const std::runtime_error& e) {
    throw ReportError(e.what());
  }
}

}  // namespace

ReportInputs ReadReportInputs(const fs::path& dir, PluginRegistry& registry,
                              const ReportOptions& options) {
  CheckResultsFolder(dir);
  ReportInputs in;
  in.dir = dir;
  in.manifest = dir / "manifest.json";
  in.suite_file = FindSuiteFile(dir, in.manifest, options);
  in.suite = LoadRecordedSuite(in.suite_file, in.manifest, registry);
  in.python_policy = ReadManifestField(in.manifest, "/rows/0/policy/file") == "<python>";
  // Another suite's file would title the page and label its figures with rows this run does
  // not have (each "not in the suite file any more").
  const std::string ran = ReadManifestField(in.manifest, "suite");
  if (!ran.empty() && ran != in.suite.name) {
    throw ReportError(in.suite_file.string() + " is the suite '" + in.suite.name + "', but " +
                      dir.string() + " holds a run of the suite '" + ran +
                      "' (manifest.json): give that suite's file with --suite, or leave --suite "
                      "out (the manifest names it)");
  }
  ReadTable(dir, &in.table, &in.columns);
  in.episodes = ReadEpisodes(dir);
  return in;
}

}  // namespace crowdsim::render
