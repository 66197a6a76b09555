#include "floorplan_command.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>

#include "crowdsim/cli/args.h"
#include "crowdsim/world_file.h"
#include "floorplan_dataset.h"
#include "floorplan_error.h"
#include "floorplan_import.h"
#include "image_io.h"
#include "svg_preview.h"

namespace crowdsim::floorplan {

const char kFloorplanUsage[] =
    R"(  crowdsim-bench floorplan import IMAGE --out WORLD.yaml [--resolution M_PER_PX]
                 [--kind navmesh|outline] [--max-rectangles 30] [--seed 1] [--test-pairs 500]
                 [--train-pairs 500] [--free-points 400] [--min-distance 5] [--agent-radius 0.3]
                 [--mask-png FILE.png]
  crowdsim-bench floorplan preview WORLD.yaml --out FILE.svg [--image IMAGE] [--pairs 40]
  crowdsim-bench floorplan dataset --source DIR --out DIR [--gibson-out DIR] [--seed 1]
                 [--train-pairs 200]
      imports real floor plans into rectangle worlds (tools/floorplan/README.md). IMAGE: PNG
      (any colour type) or PGM, navigable white (or transparent), blocked black; --resolution
      defaults to maps_metadata/<name>.yaml next to the maps folder (Gibson), or 0.1 for
      *_0.1m.png navmesh rasters; --kind defaults to navmesh for *_0.1m.png, else outline.
      preview draws a world (mask, rectangles, free points, pairs) as SVG; dataset imports
      every plan of a source folder (../shared/floorplans) and keeps the curated ones
)";

namespace {

using cli::Args;
using cli::CreateFolderOf;
using cli::UsageError;

constexpr std::int64_t kMaxSeed = 9'000'000'000'000'000;
constexpr std::int64_t kMaxInt = std::numeric_limits<int>::max();

void PrintReport(const ImportResult& r, const std::filesystem::path& out) {
  std::printf("imported %s -> %s in %.3f s\n", r.world.name.c_str(), out.string().c_str(),
              r.seconds);
  for (const auto& [k, v] : r.world.stats) {
    // Counts, flags and seeds are whole numbers: print them as such.
    if (v == std::floor(v) && std::fabs(v) < 1e15) {
      std::printf("  %-22s %.0f\n", k.c_str(), v);
    } else {
      std::printf("  %-22s %.4f\n", k.c_str(), v);
    }
  }
}

std::uint64_t Seed(const Args& a, std::uint64_t fallback) {
  const auto seed = a.GetInt("--seed", static_cast<std::int64_t>(fallback), 0, kMaxSeed);
  return static_cast<std::uint64_t>(seed);
}

PlanKind ParseKind(const std::string& kind) {
  if (kind == "navmesh") return PlanKind::kNavmesh;
  if (kind == "outline") return PlanKind::kOutline;
  throw UsageError("--kind must be navmesh or outline, got '" + kind + "'");
}

int Import(const std::vector<std::string>& args) {
  const Args a = Args::Parse(
      args,
      {"--out", "--resolution", "--kind", "--max-rectangles", "--seed", "--test-pairs",
       "--train-pairs", "--free-points", "--min-distance", "--mask-png", "--agent-radius"},
      {});
  if (a.positional.size() != 1) throw UsageError("floorplan import needs exactly one IMAGE");
  const auto out = a.Get("--out");
  if (!out) throw UsageError("floorplan import needs --out WORLD.yaml");
  ImportOptions o;
  o.source_resolution = a.GetNumber("--resolution", o.source_resolution);
  if (a.Has("--resolution") && !(o.source_resolution > 0.0)) {
    throw UsageError("--resolution must be a positive number of metres per pixel");
  }
  if (auto kind = a.Get("--kind")) o.kind = ParseKind(*kind);
  // Counts are bounded: each one sizes work and memory (a typo of 10^8 pairs ran for hours).
  o.max_rectangles = static_cast<int>(a.GetInt("--max-rectangles", o.max_rectangles, 1, 10'000));
  o.seed = Seed(a, o.seed);
  o.test_pairs = static_cast<int>(a.GetInt("--test-pairs", o.test_pairs, 1, 100'000));
  // 0 training pairs: a world for tests only (a training on it is refused, naming this option).
  o.train_pairs = static_cast<int>(a.GetInt("--train-pairs", o.train_pairs, 0, 100'000));
  o.free_points = static_cast<int>(a.GetInt("--free-points", o.free_points, 1, 1'000'000));
  o.min_pair_distance = a.GetNumber("--min-distance", o.min_pair_distance);
  if (!(o.min_pair_distance > 0.0)) {
    throw UsageError(
        "--min-distance must be a positive distance in metres (the least start-goal "
        "distance of a robot trip)");
  }
  o.agent_radius = a.GetNumber("--agent-radius", o.agent_radius);
  if (!(o.agent_radius > 0.0)) {
    throw UsageError("--agent-radius must be a positive radius in metres");
  }
  // Both outputs are checked before either is written: an error leaves nothing behind.
  const auto mask_png = a.Get("--mask-png");
  for (const std::string* path : {&*out, mask_png ? &*mask_png : nullptr}) {
    if (path == nullptr) continue;
    std::error_code ec;
    if (std::filesystem::is_directory(*path, ec)) {
      throw UsageError("'" + *path + "' is a folder; give the file to write (e.g. " +
                       (std::filesystem::path(*path) / "plan.yaml").string() + ")");
    }
    // The image read is never the file written (links and other spellings of it included).
    if (std::filesystem::equivalent(*path, a.positional[0], ec) ||
        std::filesystem::weakly_canonical(*path, ec) ==
            std::filesystem::weakly_canonical(a.positional[0], ec)) {
      throw UsageError("'" + *path + "' is the input image " + a.positional[0] +
                       "; writing it would destroy the image: choose another file");
    }
  }
  if (mask_png && (*mask_png == *out || std::filesystem::weakly_canonical(*mask_png) ==
                                            std::filesystem::weakly_canonical(*out))) {
    throw UsageError("--mask-png and --out name the same file '" + *out +
                     "'; give each its own file");
  }
  const ImportResult r = [&] {
    try {
      return ImportFloorplan(a.positional[0], o);
    } catch (const FloorplanOptionError& e) {
      throw UsageError(e.what());  // an option missing (--resolution): exit 2, with the usage
    }
  }();
  if (mask_png) CreateFolderOf("--mask-png", *mask_png);
  CreateFolderOf("--out", *out);
  if (mask_png) WritePng(r.mask, *mask_png);
  WriteWorldFile(r.world, *out);
  PrintReport(r, *out);
  return 0;
}

int Preview(const std::vector<std::string>& args) {
  const Args a = Args::Parse(args, {"--out", "--image", "--pairs"}, {});
  if (a.positional.size() != 1) throw UsageError("floorplan preview needs exactly one WORLD.yaml");
  const auto out_option = a.Get("--out");
  if (!out_option) throw UsageError("floorplan preview needs --out FILE.svg");
  const std::filesystem::path out = *out_option;
  if (out.extension() != ".svg") {
    // It wrote SVG bytes into a .png before: the format follows the extension or is an error.
    throw UsageError("floorplan preview writes SVG: --out must end in .svg, got '" + out.string() +
                     "' (for PNG or PDF figures of episodes in a floor plan, see "
                     "`crowdsim-bench render`)");
  }
  const int pairs = static_cast<int>(a.GetInt("--pairs", 40, 0, kMaxInt));
  std::string given_ext = std::filesystem::path(a.positional[0]).extension().string();
  for (char& c : given_ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (given_ext == ".png" || given_ext == ".jpg" || given_ext == ".jpeg" || given_ext == ".pgm") {
    throw UsageError("'" + a.positional[0] +
                     "' is an image: preview draws the world file that `floorplan import` "
                     "wrote (WORLD.yaml), over its source image when given --image");
  }
  const WorldFile world = ReadWorldFile(a.positional[0]);
  ImportResult source;
  PreviewMask mask;
  Grid stored;
  const auto image_option = a.Get("--image");
  if (world.mask && !image_option) {
    const NavigableMask& m = *world.mask;
    stored = Grid(m.width, m.height);
    for (size_t i = 0; i < m.cells.size(); ++i) stored.cells[i] = m.cells[i] ? 1 : 0;
    mask = PreviewMask{&stored, RasterFrame{m.origin, m.resolution, m.height}};
  }
  if (image_option) {
    // Import the source again with the world's settings (for worlds written without a mask,
    // or to check the source; the mask does not depend on the sampling, so one pair is enough).
    const std::filesystem::path image = *image_option;
    ImportOptions o;
    o.kind = StatValue(world, "kind_navmesh") > 0.5 ? PlanKind::kNavmesh : PlanKind::kOutline;
    if (MetadataResolution(image) <= 0.0) {
      o.source_resolution = StatValue(world, "source_mm_per_px") / 1000.0;
    }
    o.cell_size = StatValue(world, "cell_size_m");
    o.test_pairs = 1, o.train_pairs = 0, o.free_points = 1;
    source = ImportFloorplan(image, o);
    if ((source.world.bounds.min - world.bounds.min).norm() > 1e-3 ||
        (source.world.bounds.max - world.bounds.max).norm() > 1e-3) {
      throw FloorplanError(image.string() + ": its mask does not match " + a.positional[0] +
                           " (different bounds): is it the world's source image?");
    }
    mask = PreviewMask{&source.mask, source.frame};
  }
  CreateFolderOf("--out", out.string());
  std::ofstream f(out, std::ios::binary);
  f << RenderPreviewSvg(world, mask, pairs);
  if (!f) throw FloorplanError(out.string() + ": cannot write the preview");
  std::printf("wrote %s\n", out.string().c_str());
  return 0;
}

int Dataset(const std::vector<std::string>& args) {
  const Args a =
      Args::Parse(args, {"--source", "--out", "--gibson-out", "--seed", "--train-pairs"}, {});
  if (!a.positional.empty()) throw UsageError("floorplan dataset takes no positional arguments");
  const auto source = a.Get("--source");
  if (!source) throw UsageError("floorplan dataset needs --source DIR (../shared/floorplans)");
  const auto out = a.Get("--out");
  if (!out) throw UsageError("floorplan dataset needs --out DIR (curated worlds and their index)");
  DatasetOptions o;
  o.source = *source;
  o.out = *out;
  o.gibson_out = a.Get("--gibson-out").value_or("");
  o.seed = Seed(a, o.seed);
  o.train_pairs = static_cast<int>(a.GetInt("--train-pairs", o.train_pairs, 0, kMaxInt));
  return BuildDataset(o, std::cout);
}

}  // namespace

int FloorplanCommand(const std::vector<std::string>& args) {
  if (args.empty()) throw UsageError("floorplan needs a command: import, preview or dataset");
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (args[0] == "import") return Import(rest);
  if (args[0] == "preview") return Preview(rest);
  if (args[0] == "dataset") return Dataset(rest);
  throw UsageError("unknown floorplan command '" + args[0] + "' (import, preview, dataset)");
}

}  // namespace crowdsim::floorplan
