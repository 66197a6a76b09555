#include "crowds_command.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "crowd_tracks/tracks.h"
#include "crowdsim/cli/args.h"
#include "known_scenes.h"
#include "validate_command.h"

namespace crowdsim::crowds {

const char kCrowdsUsage[] =
    R"(  crowdsim-bench crowds import SCENE.txt --out TRACKS [--scene NAME] [--source TEXT]
                 [--cite TEXT]
  crowdsim-bench crowds dataset --source DIR --out DIR
      imports recorded pedestrian tracks (ETH/UCY: `frame person x y [vx vy]`, 2.5 Hz) into
      track files for the crowds world (docs/crowds.md): frames renumbered from 0, positions
      in mm, the scene's source and citation in the header. The six known scene files
      (biwi_eth.txt ... crowds_zara02.txt) carry their own; another file needs --scene,
      --source and --cite. dataset imports the six of DIR (../shared/pedestrians) into
      DIR/<scene>.tracks
  crowdsim-bench crowds validate [TRACKS...] [--models LIST] [--out DIR]
      walks each recorded person of the scenes' windows (default: the six of
      worlds/crowds) by each human model (default: orca,social_force,hsfm,linear,replay)
      among the others replayed, and writes DIR/table.csv and DIR/table.md (default
      DIR: runs/crowds_validation): ADE and FDE over 4.8 s, collision rate, mean speeds
)";

namespace {

using cli::Args;
using cli::UsageError;
using crowd_tracks::Tracks;

// Reads `in` (every check before anything is written), then writes `out` whole.
void ImportFile(const std::filesystem::path& in, const std::filesystem::path& out,
                const std::string& scene, const std::string& source, const std::string& cite) {
  Tracks tracks = crowd_tracks::ReadTracks(in);
  tracks.scene = scene;
  tracks.source = source;
  tracks.cite = cite;
  std::ostringstream text;
  crowd_tracks::WriteTracks(tracks, text);
  cli::CreateFolderOf("--out", out.string());
  std::ofstream file(out, std::ios::binary);
  file << text.str();
  if (!file.flush()) throw std::runtime_error(out.string() + ": cannot be written");
  std::printf("imported %s -> %s: %zu people, %lld frames (%.1f s)\n", in.string().c_str(),
              out.string().c_str(), tracks.people.size(), static_cast<long long>(tracks.frames),
              tracks.duration());
}

int Import(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--out", "--scene", "--source", "--cite"}, {});
  if (a.positional.size() != 1) throw UsageError("crowds import needs exactly one SCENE.txt");
  const auto out = a.Get("--out");
  if (!out) throw UsageError("crowds import needs --out TRACKS");
  const std::filesystem::path in = a.positional[0];
  const KnownScene* known = FindKnownScene(in.filename().string());
  const auto pick = [&](const char* option, const char* fallback) {
    if (const auto v = a.Get(option)) return *v;
    if (fallback != nullptr) return std::string(fallback);
    throw UsageError(in.filename().string() + " is not one of the six known scenes: give " +
                     option + " (every derived file names its scene, source and citation)");
  };
  ImportFile(in, *out, pick("--scene", known ? known->scene : nullptr),
             pick("--source", known ? known->source : nullptr),
             pick("--cite", known ? known->cite : nullptr));
  return 0;
}

int Dataset(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--source", "--out"}, {});
  if (!a.positional.empty()) throw UsageError("crowds dataset takes no positional argument");
  const auto source = a.Get("--source");
  const auto out = a.Get("--out");
  if (!source || !out) throw UsageError("crowds dataset needs --source DIR and --out DIR");
  for (const KnownScene& s : KnownScenes()) {
    ImportFile(std::filesystem::path(*source) / s.file,
               std::filesystem::path(*out) / (std::string(s.scene) + ".tracks"), s.scene, s.source,
               s.cite);
  }
  return 0;
}

}  // namespace

int CrowdsCommand(const std::vector<std::string>& args) {
  if (args.empty()) throw UsageError("crowds needs a command: import, dataset or validate");
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "import") return Import(rest);
  if (args[0] == "dataset") return Dataset(rest);
  if (args[0] == "validate") return ValidateCrowds(rest);
  throw UsageError("unknown crowds command '" + args[0] + "' (import, dataset, validate)");
}

}  // namespace crowdsim::crowds
