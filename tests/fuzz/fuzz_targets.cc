#include "fuzz_targets.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/bench/training/train_spec.h"
#include "crowdsim/world_file.h"
#include "loader/elf_check.h"
#include "temp_dir.h"

namespace crowdsim::fuzz {
namespace {

namespace fs = std::filesystem;

/// The readers take paths (and resolve relative paths against the file's folder), so each
/// input is written to one scratch file of this process, as a user's file would be.
fs::path WriteScratch(const std::string& name, std::string_view input) {
  static const testing::TempDir dir;
  const fs::path file = dir.path() / name;
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(input.data(), static_cast<std::streamsize>(input.size()));
  return file;
}

/// One registry for the whole process, as in one CLI run: the default search path
/// (CROWDSIM_PLUGIN_PATH, then the plugins built with this core), so the plugins that inputs
/// name resolve and parameter validation is reached. Plugins stay loaded between inputs.
PluginRegistry& Registry() {
  static PluginRegistry registry;
  return registry;
}

/// Leading `#set key.path=value` lines are `--set` overrides (YAML comments, so every suite is
/// an input as it stands); the fuzzer reaches the override and sweep code through them.
std::vector<std::string> Overrides(std::string_view input) {
  std::vector<std::string> out;
  constexpr std::string_view kPrefix = "#set ";
  while (input.starts_with(kPrefix)) {
    const size_t end = input.find('\n');
    out.emplace_back(input.substr(kPrefix.size(), end == std::string_view::npos
                                                      ? std::string_view::npos
                                                      : end - kPrefix.size()));
    if (end == std::string_view::npos) break;
    input.remove_prefix(end + 1);
  }
  return out;
}

/// Errors must exist exactly when there is no result, and each must name the file (or the
/// `--set` override it is about) and say something.
std::string CheckErrors(bool has_result, const std::vector<SuiteError>& errors,
                        const fs::path& file) {
  if (has_result == !errors.empty()) {
    return has_result ? "a result together with errors" : "neither a result nor an error";
  }
  for (const SuiteError& e : errors) {
    if (e.file != file.string() && !e.file.starts_with("--set "))
      return "an error names another file: " + e.Format();
    if (e.message.empty()) return "an error without a message: " + e.Format();
    if (e.line < 0 || e.column < 0) return "an error with a negative position: " + e.Format();
  }
  return "";
}

std::string CheckPlugin(const PluginUse& use, const std::string& what) {
  return use.loaded ? "" : what + " '" + use.plugin + "' was accepted but not loaded";
}

std::string SuiteReader(std::string_view input) {
  const fs::path file = WriteScratch("suite.yaml", input);
  const SuiteLoadResult r = LoadSuite(file, Registry(), Overrides(input));
  if (auto problem = CheckErrors(r.suite.has_value(), r.errors, file); !problem.empty())
    return problem;
  if (!r.suite) return "";
  if (r.suite->rows.empty()) return "a suite without rows was accepted";
  for (const RowSpec& row : r.suite->rows) {
    for (const auto& problem : {CheckPlugin(row.policy, "policy"), CheckPlugin(row.world, "world"),
                                CheckPlugin(row.humans.policy, "human policy")}) {
      if (!problem.empty()) return "row '" + row.label + "': " + problem;
    }
    for (const PluginUse& sensor : row.sensors) {
      if (auto problem = CheckPlugin(sensor, "sensor"); !problem.empty())
        return "row '" + row.label + "': " + problem;
    }
  }
  return "";
}

std::string TrainingReader(std::string_view input) {
  const fs::path file = WriteScratch("train.yaml", input);
  const training::TrainSpecLoadResult r =
      training::LoadTrainSpec(file, Registry(), Overrides(input));
  if (auto problem = CheckErrors(r.spec.has_value(), r.errors, file); !problem.empty())
    return problem;
  if (!r.spec) return "";
  const RowSpec& row = r.spec->row;
  for (const auto& problem :
       {CheckPlugin(row.policy, "policy"), CheckPlugin(row.world, "world"),
        CheckPlugin(row.humans.policy, "human policy"), CheckPlugin(r.spec->teacher, "teacher")}) {
    if (!problem.empty()) return problem;
  }
  for (const auto& sensor : row.sensors) {
    if (auto problem = CheckPlugin(sensor, "sensor"); !problem.empty()) return problem;
  }
  return "";
}

/// A world the reader returned must be one the simulator can use.
std::string CheckWorld(const WorldFile& w) {
  auto valid = [](const Rect& r) { return r.min.x() < r.max.x() && r.min.y() < r.max.y(); };
  if (!valid(w.bounds)) return "world '" + w.name + "': empty bounds accepted";
  for (const Rect& r : w.rectangles) {
    if (!valid(r)) return "world '" + w.name + "': an empty rectangle accepted";
  }
  if (w.mask) {
    const NavigableMask& m = *w.mask;
    if (m.width < 1 || m.height < 1 || m.cells.size() != static_cast<size_t>(m.width) * m.height) {
      return "world '" + w.name + "': mask of " + std::to_string(m.width) + " x " +
             std::to_string(m.height) + " cells holds " + std::to_string(m.cells.size());
    }
  }
  return "";
}

/// A WorldFileError must name the file it is about.
std::string CheckWorldError(const WorldFileError& e, const fs::path& file) {
  return std::string_view(e.what()).starts_with(file.string())
             ? ""
             : std::string("error without the file name: ") + e.what();
}

/// Both entry points of the world file reader: a single world and a world set.
std::string WorldReader(std::string_view input) {
  const fs::path file = WriteScratch("world.yaml", input);
  try {
    if (auto problem = CheckWorld(ReadWorldFile(file)); !problem.empty()) return problem;
  } catch (const WorldFileError& e) {
    if (auto problem = CheckWorldError(e, file); !problem.empty()) return problem;
  }
  try {
    for (const WorldFile& w : ReadWorldSet(file)) {
      if (auto problem = CheckWorld(w); !problem.empty()) return problem;
    }
  } catch (const WorldFileError& e) {
    if (auto problem = CheckWorldError(e, file); !problem.empty()) return problem;
  }
  return "";
}

/// episodes.csv as a resume or merge reads it: lines kept are valid, damaged ones counted, and an
/// unreadable file is a runtime_error naming it.
std::string EpisodesReader(std::string_view input) {
  const fs::path file = WriteScratch("episodes.csv", input);
  EpisodesCsvRead read;
  try {
    read = ReadEpisodesCsvChecked(file);
  } catch (const std::runtime_error& e) {
    return std::string_view(e.what()).find(file.string()) == std::string_view::npos
               ? std::string("error without the file name: ") + e.what()
               : "";
  }
  if (read.damaged != static_cast<int>(read.damaged_lines.size()))
    return "damaged count and damaged lines differ";
  if (read.damaged > 0 && read.first_damage.empty()) return "damage without its place";
  for (const EpisodeLine& l : read.lines) {
    const EpisodeOutcome& o = l.outcome;
    if (l.episode < 0 || o.steps < 0 || o.danger_steps < 0 || o.humans_at_goal < 0)
      return "a negative count was kept (episode " + std::to_string(l.episode) + ")";
    for (const double v :
         {o.time, o.path_length, o.discounted_return, o.decision_time_us, o.max_speed}) {
      if (!std::isfinite(v)) return "a non-finite number was kept";
    }
    if (o.time < 0 || o.path_length < 0 || o.max_speed < 0) return "a negative measure was kept";
  }
  return "";
}

/// manifest.json through every reader the harness uses on it: anything missing, mistyped or
/// malformed reads as absent, never throws.
std::string ManifestReader(std::string_view input) {
  const fs::path file = WriteScratch("manifest.json", input);
  for (const char* key : {"config_hash", "suite", "shard", "/procedure/rl_episodes", "/a/0/b", "/"})
    (void)ReadManifestField(file, key);
  (void)ReadManifestStrings(file, "overrides");
  (void)ReadManifestStrings(file, "row_hashes");
  (void)ReadManifestInteger(file, "episodes");
  (void)ReadManifestInteger(file, "/procedure/rl_episodes");
  (void)ReadManifestBool(file, "finished");
  return "";
}

/// A plugin file's ELF check, before any dlopen: a verdict for any bytes, never a crash.
std::string PluginFileCheck(std::string_view input) {
  const fs::path file = WriteScratch("crowdsim_fuzzed.so", input);
  const std::string problem = ElfFileProblem(file);
  if (problem.empty() && input.size() < 64) return "a file shorter than an ELF header accepted";
  return "";
}

}  // namespace

const std::vector<FuzzTarget>& FuzzTargets() {
  static const std::vector<FuzzTarget> targets = {
      {"suite_reader", "LoadSuite: a suite file (with leading '#set k=v' lines as --set overrides)",
       SuiteReader},
      {"world_reader", "ReadWorldFile and ReadWorldSet: a world file or a world set", WorldReader},
      {"training_reader", "LoadTrainSpec: a training file (leading '#set k=v' lines as --set)",
       TrainingReader},
      {"episodes_reader", "ReadEpisodesCsvChecked: an episodes.csv as resume and merge read it",
       EpisodesReader},
      {"manifest_reader", "the manifest.json readers (fields, lists, numbers, JSON pointers)",
       ManifestReader},
      {"plugin_file", "ElfFileProblem: a plugin file's headers, checked before dlopen",
       PluginFileCheck},
  };
  return targets;
}

const FuzzTarget* FindFuzzTarget(std::string_view name) {
  for (const FuzzTarget& t : FuzzTargets()) {
    if (name == t.name) return &t;
  }
  return nullptr;
}

}  // namespace crowdsim::fuzz
