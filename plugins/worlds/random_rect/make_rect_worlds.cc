// crowdsim-make-rect-worlds: writes the frozen random-room sets, or one custom set.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "frozen_sets.h"

namespace {

namespace fs = std::filesystem;
using crowdsim::random_rect::RectLayoutConfig;
using crowdsim::random_rect::RectLayoutStats;
using crowdsim::random_rect::SetSpec;

constexpr const char* kUsage =
    "usage: crowdsim-make-rect-worlds [--out DIR]\n"
    "         writes the four committed sets obstacles_{1,3}_{train,test}.yaml into DIR\n"
    "         (default, for the build's own binary: the source folder worlds/random_rect;\n"
    "         an installed copy needs --out)\n"
    "       crowdsim-make-rect-worlds --obstacles N [--split NAME] [--seed X] [--count K]\n"
    "           [--min-side M] [--max-side M] [--wall-margin M] [--obstacle-margin M] --out FILE\n"
    "         writes one custom set (sizes and margins in metres)\n";

void Report(const SetSpec& spec, const RectLayoutStats& s, const fs::path& path) {
  std::printf(
      "%-24s %3d layouts  draws %8lld  rejected %7.3f%% (placement %lld, disconnected "
      "%lld, no pair %lld)  mean side %.3f m\n",
      path.filename().string().c_str(), spec.count, static_cast<long long>(s.attempts),
      100.0 * s.RejectionRate(), static_cast<long long>(s.rejected_placement),
      static_cast<long long>(s.rejected_disconnected), static_cast<long long>(s.rejected_no_pair),
      s.MeanSide());
}

/// Whether this is the build tree's binary (whose source folder is the default output), not an
/// installed copy (which wrote into the source tree of the machine that built the package).
bool RunsFromTheBuildTree() {
  std::error_code ec;
  const fs::path self = fs::canonical("/proc/self/exe", ec);
  const fs::path bin = fs::weakly_canonical(CROWDSIM_BUILD_BIN_DIR, ec);
  return !self.empty() && self.parent_path() == bin;
}

int Run(int argc, char** argv) {
  fs::path out = CROWDSIM_RANDOM_RECT_SOURCE_DIR;
  bool out_given = false;
  SetSpec custom;
  RectLayoutConfig config;
  bool is_custom = false;
  bool has_seed = false;
  std::string options;  // the custom options, echoed into the file's regenerate command
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (i + 1 >= argc) {
      std::fprintf(stderr, "crowdsim-make-rect-worlds: '%s' needs a value\n%s", arg.c_str(),
                   kUsage);
      return 2;
    }
    const std::string value = argv[++i];
    if (arg == "--out") {
      out = value;
      out_given = true;
      continue;
    }
    options += " " + arg + " " + value;
    is_custom = true;
    if (arg == "--obstacles") {
      custom.obstacles = std::stoi(value);
    } else if (arg == "--split") {
      custom.split = value;
    } else if (arg == "--seed") {
      custom.seed = std::stoull(value);
      has_seed = true;
    } else if (arg == "--count") {
      custom.count = std::stoi(value);
    } else if (arg == "--min-side") {
      config.min_side = std::stod(value);
    } else if (arg == "--max-side") {
      config.max_side = std::stod(value);
    } else if (arg == "--wall-margin") {
      config.wall_margin = std::stod(value);
    } else if (arg == "--obstacle-margin") {
      config.obstacle_margin = std::stod(value);
    } else {
      std::fprintf(stderr, "crowdsim-make-rect-worlds: unknown option '%s'\n%s", arg.c_str(),
                   kUsage);
      return 2;
    }
  }
  if (!is_custom) {
    if (!out_given && !RunsFromTheBuildTree()) {
      std::fprintf(stderr,
                   "crowdsim-make-rect-worlds: an installed copy has no source folder to write "
                   "to: give --out DIR\n%s",
                   kUsage);
      return 2;
    }
    for (const SetSpec& spec : crowdsim::random_rect::CommittedSets()) {
      const fs::path path = out / spec.FileName();
      Report(spec, WriteSet(spec, config, crowdsim::random_rect::kCommittedSetsCommand, path),
             path);
    }
    return 0;
  }
  if (!out_given) {
    std::fprintf(stderr, "crowdsim-make-rect-worlds: a custom set needs --out FILE\n%s", kUsage);
    return 2;
  }
  if (!has_seed) {
    // A seed of its own per obstacle count and split, and never a committed set's seed.
    custom.seed = 1000ULL * static_cast<unsigned long long>(custom.obstacles) + 901 +
                  (custom.split == "test" ? 1 : 0);
    options += " --seed " + std::to_string(custom.seed);
  }
  const std::string command =
      "build/bin/crowdsim-make-rect-worlds" + options + " --out " + out.filename().string();
  Report(custom, WriteSet(custom, config, command, out), out);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "crowdsim-make-rect-worlds: %s\n", e.what());
    return 1;
  }
}
