#include "floorplan_cli.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <map>
#include <stdexcept>

#include "crowdsim/world_file.h"
#include "floorplan_dataset.h"
#include "floorplan_error.h"
#include "floorplan_import.h"
#include "image_io.h"
#include "svg_preview.h"

namespace crowdsim::floorplan {
namespace {

constexpr const char* kUsage = R"(usage:
  floorplan import IMAGE --out WORLD.yaml [--resolution M_PER_PX] [--kind navmesh|outline]
                   [--max-rectangles 30] [--seed 1] [--test-pairs 500] [--train-pairs 500]
                   [--free-points 400] [--min-distance 5] [--agent-radius 0.3]
                   [--mask-png FILE.png]
  floorplan preview WORLD.yaml --out FILE.svg [--image IMAGE] [--pairs 40]
  floorplan dataset --source DIR --out DIR [--gibson-out DIR] [--seed 1] [--train-pairs 200]

IMAGE: PNG (any colour type) or PGM; navigable white (or transparent), blocked black.
--resolution defaults to maps_metadata/<name>.yaml next to the maps folder (Gibson), or 0.1
for *_0.1m.png navmesh rasters. --kind defaults to navmesh for *_0.1m.png, else outline.
)";

class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Positional arguments and --key value options; every option takes a value.
struct Parsed {
  std::vector<std::string> positional;
  std::map<std::string, std::string> options;
};

Parsed Parse(const std::vector<std::string>& args, size_t first,
             const std::vector<std::string>& known) {
  Parsed p;
  for (size_t i = first; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.rfind("--", 0) != 0) {
      p.positional.push_back(a);
      continue;
    }
    bool ok = false;
    for (const auto& k : known) ok = ok || k == a;
    if (!ok) throw UsageError("unknown option '" + a + "'");
    if (i + 1 >= args.size()) throw UsageError("option '" + a + "' needs a value");
    p.options[a] = args[++i];
  }
  return p;
}

double ToDouble(const std::string& key, const std::string& v) {
  try {
    size_t used = 0;
    const double x = std::stod(v, &used);
    if (used == v.size()) return x;
  } catch (const std::exception&) {
  }
  throw UsageError(key + " needs a number, got '" + v + "'");
}

long ToInt(const std::string& key, const std::string& v, double max = 9e15) {
  const double x = ToDouble(key, v);
  if (x < 0 || x > max || x != static_cast<double>(static_cast<long>(x))) {
    char bound[32];
    std::snprintf(bound, sizeof(bound), "%.0f", max);
    throw UsageError(key + " needs a whole number in [0, " + bound + "], got '" + v + "'");
  }
  return static_cast<long>(x);
}

std::string Required(const Parsed& p, const std::string& key) {
  auto it = p.options.find(key);
  if (it == p.options.end()) throw UsageError("missing " + key);
  return it->second;
}

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

int Import(const std::vector<std::string>& args) {
  const Parsed p = Parse(args, 1,
                         {"--out", "--resolution", "--kind", "--max-rectangles", "--seed",
                          "--test-pairs", "--train-pairs", "--free-points", "--min-distance",
                          "--mask-png", "--agent-radius"});
  if (p.positional.size() != 1) throw UsageError("import needs exactly one IMAGE");
  const std::filesystem::path out = Required(p, "--out");
  ImportOptions o;
  for (const auto& [k, v] : p.options) {
    if (k == "--resolution") o.source_resolution = ToDouble(k, v);
    // Counts are bounded: each one sizes work and memory (a typo of 10^8 pairs ran for hours).
    if (k == "--max-rectangles") o.max_rectangles = static_cast<int>(ToInt(k, v, 10'000));
    if (k == "--seed") o.seed = static_cast<std::uint64_t>(ToInt(k, v));
    if (k == "--test-pairs") o.test_pairs = static_cast<int>(ToInt(k, v, 100'000));
    if (k == "--train-pairs") o.train_pairs = static_cast<int>(ToInt(k, v, 100'000));
    if (k == "--free-points") o.free_points = static_cast<int>(ToInt(k, v, 1'000'000));
    if (k == "--min-distance") o.min_pair_distance = ToDouble(k, v);
    if (k == "--agent-radius") o.agent_radius = ToDouble(k, v);
    if (k == "--kind") {
      if (v == "navmesh") o.kind = PlanKind::kNavmesh;
      else if (v == "outline") o.kind = PlanKind::kOutline;
      else throw UsageError("--kind must be navmesh or outline, got '" + v + "'");
    }
  }
  if (p.options.count("--resolution") && !(o.source_resolution > 0.0)) {
    throw UsageError("--resolution must be a positive number of metres per pixel");
  }
  const ImportResult r = ImportFloorplan(p.positional[0], o);
  WriteWorldFile(r.world, out);
  if (p.options.count("--mask-png")) WritePng(r.mask, p.options.at("--mask-png"));
  PrintReport(r, out);
  return 0;
}

int Preview(const std::vector<std::string>& args) {
  const Parsed p = Parse(args, 1, {"--out", "--image", "--pairs"});
  if (p.positional.size() != 1) throw UsageError("preview needs exactly one WORLD.yaml");
  const std::filesystem::path out = Required(p, "--out");
  if (out.extension() != ".svg") {
    // It wrote SVG bytes into a .png before: the format follows the extension or is an error.
    throw UsageError("floorplan preview writes SVG: --out must end in .svg, got '" + out.string() +
                     "' (for PNG or PDF figures of episodes in a floor plan, see `crowdsim-bench render`)");
  }
  const WorldFile world = ReadWorldFile(p.positional[0]);
  const int pairs = p.options.count("--pairs") ? static_cast<int>(ToInt("--pairs", p.options.at("--pairs"))) : 40;
  ImportResult source;
  PreviewMask mask;
  Grid stored;
  if (world.mask && !p.options.count("--image")) {
    const NavigableMask& m = *world.mask;
    stored = Grid(m.width, m.height);
    for (size_t i = 0; i < m.cells.size(); ++i) stored.cells[i] = m.cells[i] ? 1 : 0;
    mask = PreviewMask{&stored, RasterFrame{m.origin, m.resolution, m.height}};
  }
  if (p.options.count("--image")) {
    // Import the source again with the world's settings (for worlds written without a mask,
    // or to check the source; the mask does not depend on the sampling, so one pair is enough).
    const std::filesystem::path image = p.options.at("--image");
    ImportOptions o;
    o.kind = StatValue(world, "kind_navmesh") > 0.5 ? PlanKind::kNavmesh : PlanKind::kOutline;
    if (MetadataResolution(image) <= 0.0) o.source_resolution = StatValue(world, "source_mm_per_px") / 1000.0;
    o.cell_size = StatValue(world, "cell_size_m");
    o.test_pairs = 1, o.train_pairs = 0, o.free_points = 1;
    source = ImportFloorplan(image, o);
    if ((source.world.bounds.min - world.bounds.min).norm() > 1e-3 ||
        (source.world.bounds.max - world.bounds.max).norm() > 1e-3) {
      throw FloorplanError(image.string() + ": its mask does not match " + p.positional[0] +
                           " (different bounds): is it the world's source image?");
    }
    mask = PreviewMask{&source.mask, source.frame};
  }
  std::ofstream f(out, std::ios::binary);
  f << RenderPreviewSvg(world, mask, pairs);
  if (!f) throw FloorplanError(out.string() + ": cannot write the preview");
  std::printf("wrote %s\n", out.string().c_str());
  return 0;
}

int Dataset(const std::vector<std::string>& args) {
  const Parsed p = Parse(args, 1, {"--source", "--out", "--gibson-out", "--seed", "--train-pairs"});
  if (!p.positional.empty()) throw UsageError("dataset takes no positional arguments");
  DatasetOptions o;
  o.source = Required(p, "--source");
  o.out = Required(p, "--out");
  if (p.options.count("--gibson-out")) o.gibson_out = p.options.at("--gibson-out");
  if (p.options.count("--seed")) o.seed = static_cast<std::uint64_t>(ToInt("--seed", p.options.at("--seed")));
  if (p.options.count("--train-pairs")) {
    o.train_pairs = static_cast<int>(ToInt("--train-pairs", p.options.at("--train-pairs")));
  }
  return BuildDataset(o, std::cout);
}

}  // namespace

int RunFloorplanCli(const std::vector<std::string>& args) {
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(kUsage, args.empty() ? stderr : stdout);
    return args.empty() ? 2 : 0;
  }
  try {
    if (args[0] == "import") return Import(args);
    if (args[0] == "preview") return Preview(args);
    if (args[0] == "dataset") return Dataset(args);
    throw UsageError("unknown command '" + args[0] + "' (import, preview, dataset)");
  } catch (const UsageError& e) {
    std::fprintf(stderr, "floorplan: %s\n%s", e.what(), kUsage);
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "floorplan: error: %s\n", e.what());
    return 1;
  }
}

}  // namespace crowdsim::floorplan
