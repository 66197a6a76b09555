#include "floorplan_import.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "floorplan_error.h"
#include "image_io.h"
#include "morphology.h"
#include "navigable_component.h"
#include "rect_decomposition.h"
#include "resample.h"

namespace crowdsim::floorplan {
namespace {

// A length or resolution for a message: as short as it is exact ("0.3", not "0.300000").
std::string Num(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

constexpr const char* kGibsonAttribution =
    "Derived from the GibsonEnv floor map %s (github.com/micheleantonazzi/gibson-env-utilities "
    "@ c2e3811, Apache-2.0); buildings from the Gibson dataset (Matterport3D / Stanford 2D-3D-S "
    "scans), academic non-commercial use";
constexpr const char* kHm3dAttribution =
    "Derived from the Habitat navmesh raster of HM3D scene %s (github.com/hanruihua/ir-sim @ "
    "20b6d84be8f9, MIT); scene under the HM3D academic terms";

// Blocked share of a cell that makes it blocked when resampling: the majority for filled
// navmesh rasters; a quarter for outline maps, whose 0.05-0.1 m strokes would otherwise
// vanish when they straddle two cells.
constexpr double kNavmeshBlockedShare = 0.5;
constexpr double kOutlineBlockedShare = 0.25;
// Outline maps: blocked components up to this area are specks the closing may fill.
constexpr double kSpeckArea = 0.04;  // m2 (4 cells)
// Pairs whose geodesic length is measured for the tortuosity statistic.
constexpr int kTortuosityPairs = 64;
// A centre cell is "narrow" when the agent has less than this much room beyond its radius.
constexpr double kNarrowSlack = 0.3;  // m

[[noreturn]] void Fail(const std::filesystem::path& path, const std::string& what) {
  throw FloorplanError(path.string() + ": " + what);
}

std::string Format(const char* pattern, const std::string& arg) {
  std::string s(pattern);
  return s.replace(s.find("%s"), 2, arg);
}

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

int Cells(double metres, double cell) { return static_cast<int>(std::lround(metres / cell)); }

// The source name without the "_0.1m" suffix of the navmesh rasters.
std::string BaseName(const std::filesystem::path& image) {
  std::string stem = image.stem().string();
  if (EndsWith(stem, "_0.1m")) stem.resize(stem.size() - 5);
  return stem;
}

PlanKind ResolveKind(const std::filesystem::path& image, PlanKind kind) {
  if (kind != PlanKind::kAuto) return kind;
  return EndsWith(image.filename().string(), "_0.1m.png") ? PlanKind::kNavmesh : PlanKind::kOutline;
}

double ResolveResolution(const std::filesystem::path& image, const ImportOptions& o,
                         PlanKind kind) {
  const bool named_decimetre = EndsWith(image.stem().string(), "_0.1m");
  double res = o.source_resolution;
  if (res > 0.0) {
    if (named_decimetre && std::abs(res - 0.1) > 1e-9) {  // the option is wrong: exit 2
      throw FloorplanOptionError(image.string() +
                                 ": the file name says 0.1 m per pixel but --resolution is " +
                                 Num(res) + " (drop --resolution, or rename the file)");
    }
  } else if ((res = MetadataResolution(image)) > 0.0) {
  } else if (named_decimetre || kind == PlanKind::kNavmesh) {
    res = 0.1;
  } else {
    throw FloorplanOptionError(image.string() +
                               ": unknown resolution: pass --resolution M_PER_PX, or put "
                               "maps_metadata/" +
                               image.stem().string() +
                               ".yaml (with 'scale: M_PER_PX') next to the maps folder");
  }
  if (!(res >= 0.005 && res <= 2.0 * o.cell_size)) {
    const std::string what = "resolution " + Num(res) + " m/px is out of range [0.005, " +
                             Num(2.0 * o.cell_size) + "] (check --resolution: metres per pixel)";
    // Given as --resolution: the option is wrong (exit 2); read from the map's metadata: the
    // import fails on its data (exit 1).
    if (o.source_resolution > 0.0) throw FloorplanOptionError(image.string() + ": " + what);
    Fail(image, what);
  }
  return res;
}

// Largest and smallest row/column with a navigable cell.
struct Box {
  int r0, c0, r1, c1;
};
Box Bounds(const Grid& g) {
  Box b{g.height, g.width, -1, -1};
  for (int r = 0; r < g.height; ++r) {
    for (int c = 0; c < g.width; ++c) {
      if (!g.cells[g.Index(r, c)]) continue;
      b.r0 = std::min(b.r0, r), b.c0 = std::min(b.c0, c);
      b.r1 = std::max(b.r1, r), b.c1 = std::max(b.c1, c);
    }
  }
  return b;
}

// The window [r0, r0 + h) x [c0, c0 + w) of g; cells beyond g are blocked.
Grid Crop(const Grid& g, int r0, int c0, int h, int w) {
  Grid out(w, h, 0);
  for (int r = 0; r < h; ++r) {
    for (int c = 0; c < w; ++c) out(r, c) = g.At(r0 + r, c0 + c);
  }
  return out;
}

Grid PrepareNavigable(const std::filesystem::path& image, const Grid& raw, const ImportOptions& o,
                      PlanKind kind, double res) {
  if (raw.Count() == 0) {
    Fail(image, "every pixel is blocked (black): navigable space must be white or transparent");
  }
  const double ratio = res / o.cell_size;
  if (double(raw.width) * ratio * double(raw.height) * ratio > 16e6) {
    Fail(image, "the plan is larger than 16 million cells at " + Num(o.cell_size) +
                    " m (check --resolution: metres per pixel, not pixels per metre)");
  }
  Grid g = Resample(raw, res, o.cell_size,
                    kind == PlanKind::kNavmesh ? kNavmeshBlockedShare : kOutlineBlockedShare);
  if (kind == PlanKind::kOutline) {
    // The page is white inside and outside the building. Close doors on a copy, flood the
    // outside from the border there, and block what the flood reached.
    const Grid sealed = CloseBlocked(g, Cells(0.5 * o.door_gap, o.cell_size));
    std::vector<std::pair<int, int>> border;
    for (int c = 0; c < g.width; ++c) border.push_back({0, c}), border.push_back({g.height - 1, c});
    for (int r = 0; r < g.height; ++r) border.push_back({r, 0}), border.push_back({r, g.width - 1});
    const Grid exterior = FloodFill(sealed, border, 1);
    for (size_t i = 0; i < g.cells.size(); ++i) {
      if (exterior.cells[i]) g.cells[i] = 0;
    }
    if (g.Count() == 0) {
      Fail(image, "no interior found: the building outline is open wider than the door gap (" +
                      Num(o.door_gap) +
                      " m) or the image is not an outline map "
                      "(try --kind navmesh)");
    }
  }
  // The paper's two closings of the navigable area with a 3x3 element. A closing is
  // idempotent, so one pass gives the same result as two. Outline strokes are one or two
  // cells thin and a closing would erase them (and every wall between two rooms), so there
  // it only fills blocked components of at most kSpeckArea: specks, not walls.
  if (kind == PlanKind::kNavmesh) return CloseNavigable(g, 1);
  const long speck_cells = std::lround(kSpeckArea / (o.cell_size * o.cell_size));
  return CloseNavigableKeepingStrokes(g, 1, speck_cells);
}

}  // namespace

std::shared_ptr<const NavigableMask> ToNavigableMask(const Grid& mask, const RasterFrame& frame) {
  auto m = std::make_shared<NavigableMask>();
  m->width = mask.width;
  m->height = mask.height;
  m->resolution = frame.cell_size;
  m->origin = frame.origin;
  m->cells.reserve(mask.cells.size());
  for (const std::uint8_t c : mask.cells) m->cells.push_back(c ? 1 : 0);
  return m;
}

double MetadataResolution(const std::filesystem::path& image) {
  const auto meta =
      image.parent_path().parent_path() / "maps_metadata" / (image.stem().string() + ".yaml");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(meta, ec)) return 0.0;
  try {
    const YAML::Node root = YAML::LoadFile(meta.string());
    const double scale = root["scale"].as<double>();
    if (!(scale > 0.0)) throw FloorplanError("");
    return scale;
  } catch (const std::exception&) {
    throw FloorplanError(meta.string() +
                         ": needs 'scale: M_PER_PX' (a positive number); fix the "
                         "file or pass --resolution");
  }
}

double StatValue(const WorldFile& world, const std::string& key) {
  for (const auto& [k, v] : world.stats) {
    if (k == key) return v;
  }
  throw FloorplanError("world '" + world.name + "' has no statistic '" + key +
                       "' (re-import it with this version of the importer)");
}

ImportResult ImportFloorplan(const std::filesystem::path& image, const ImportOptions& o) {
  const auto t0 = std::chrono::steady_clock::now();
  if (o.max_rectangles < 1) Fail(image, "--max-rectangles must be at least 1");
  if (o.test_pairs < 1 || o.train_pairs < 0 || o.free_points < 1) {
    Fail(image, "pair and point counts must be positive");
  }
  ImportResult result;
  result.kind = ResolveKind(image, o.kind);
  // Read the image before anything else, so a file that is no image says so first.
  const Grid raw = ReadBinaryImage(image);
  result.source_resolution = ResolveResolution(image, o, result.kind);
  const double cell = o.cell_size;
  const Grid interior = PrepareNavigable(image, raw, o, result.kind, result.source_resolution);

  const double radius_cells = o.agent_radius / cell;
  const DiscComponent comp = LargestDiscComponent(interior, radius_cells);
  if (comp.centres.Count() == 0) {
    Fail(image, "no place where a disc of radius " + Num(o.agent_radius) +
                    " m fits: the navigable area is too narrow (check the resolution, or the "
                    "colours: navigable must be white)");
  }

  // Crop to the navigable mask plus a blocked margin; centre the world on the origin.
  const Box box = Bounds(comp.reach);
  const int pad = static_cast<int>(std::ceil(o.margin / cell - 1e-9));
  const int h = box.r1 - box.r0 + 1 + 2 * pad, w = box.c1 - box.c0 + 1 + 2 * pad;
  result.mask = Crop(comp.reach, box.r0 - pad, box.c0 - pad, h, w);
  const Grid centres = Crop(comp.centres, box.r0 - pad, box.c0 - pad, h, w);
  result.frame = RasterFrame{Vec2(-(w / 2) * cell, -(h / 2) * cell), cell, h};

  // Rectangles: the exact greedy, run to full coverage for the statistics.
  const std::vector<CellRect> all = DecomposeBlocked(result.mask);
  const long blocked_cells = long(w) * h - result.mask.Count();
  const int kept = std::min<int>(o.max_rectangles, static_cast<int>(all.size()));
  WorldFile& world = result.world;
  world.name = o.name.empty() ? BaseName(image) : o.name;
  if (!o.attribution.empty()) {
    world.attribution = o.attribution;
  } else if (image.parent_path().filename() == "maps") {
    world.attribution = Format(kGibsonAttribution, image.filename().string());
  } else if (EndsWith(image.stem().string(), "_0.1m")) {
    world.attribution = Format(kHm3dAttribution, BaseName(image));
  }
  world.bounds = Rect{result.frame.origin, result.frame.origin + cell * Vec2(w, h)};
  world.mask = ToNavigableMask(result.mask, result.frame);
  long kept_cells = 0;
  for (int k = 0; k < kept; ++k) {
    const CellRect& r = all[k];
    world.rectangles.push_back(result.frame.CellsToRect(r.row0, r.col0, r.row1, r.col1));
    kept_cells += r.Area();
  }

  // Samples: the test split first, so that changing the train size keeps the test set.
  const FreeSpace space(result.mask, centres, result.frame, world.rectangles, o.clearance);
  const Box cbox = Bounds(centres);
  const double extent = cell * std::max(cbox.r1 - cbox.r0 + 1, cbox.c1 - cbox.c0 + 1);
  const double min_distance = std::min(o.min_pair_distance, 0.5 * extent);
  Rng rng(o.seed);
  Rng test_rng = rng.Fork(1), train_rng = rng.Fork(2), point_rng = rng.Fork(3);
  world.test_pairs = space.SamplePairs(o.test_pairs, min_distance, test_rng);
  if (o.train_pairs > 0 && !world.test_pairs.empty()) {
    world.train_pairs = space.SamplePairs(o.train_pairs, min_distance, train_rng, world.test_pairs);
  }
  if (world.test_pairs.empty() || (o.train_pairs > 0 && world.train_pairs.empty())) {
    std::ostringstream msg;
    msg << "cannot sample " << o.test_pairs << " + " << o.train_pairs << " start/goal pairs "
        << min_distance << " m apart with " << o.clearance << " m clearance: the navigable "
        << "component is too small or too cluttered (lower --min-distance or use another plan)";
    Fail(image, msg.str());
  }
  for (int k = 0; k < o.free_points; ++k) {
    const auto p = space.Sample(point_rng);
    if (!p) Fail(image, "cannot sample free points for humans: the free space is too cluttered");
    world.free_points.push_back(*p);
  }

  // Difficulty ingredients (README.md, "Difficulty").
  double tortuosity = 0.0;
  int measured = 0;
  for (int k = 0; k < std::min<int>(kTortuosityPairs, world.test_pairs.size()); ++k) {
    const StartGoal& p = world.test_pairs[k];
    const double geo = space.GeodesicDistance(p.start, p.goal);
    if (!std::isfinite(geo)) continue;
    tortuosity += std::max(1.0, geo / (p.goal - p.start).norm());
    ++measured;
  }
  tortuosity = measured > 0 ? tortuosity / measured : 1.0;
  const std::vector<double> clearance = ClearanceCells(result.mask);
  long narrow = 0;
  const long centre_cells = centres.Count();
  for (size_t i = 0; i < clearance.size(); ++i) {
    if (centres.cells[i] && clearance[i] * cell < o.agent_radius + kNarrowSlack) ++narrow;
  }
  const double narrow_share = double(narrow) / double(std::max(1L, centre_cells));

  const double cell_area = cell * cell;
  const double free_area = result.mask.Count() * cell_area;
  const double interior_area = interior.Count() * cell_area;
  world.stats = {
      {"kind_navmesh", result.kind == PlanKind::kNavmesh ? 1.0 : 0.0},
      {"source_mm_per_px", 1000.0 * result.source_resolution},
      {"cell_size_m", cell},
      {"seed", static_cast<double>(o.seed)},
      {"size_x_m", w * cell},
      {"size_y_m", h * cell},
      {"interior_free_area_m2", interior_area},
      {"free_area_m2", free_area},
      {"component_share", free_area / interior_area},
      {"components", static_cast<double>(comp.components)},
      {"blocked_area_m2", blocked_cells * cell_area},
      {"rectangles_total", static_cast<double>(all.size())},
      {"rectangles_95", static_cast<double>(RectanglesForCoverage(all, blocked_cells, 0.95))},
      {"rectangles_99", static_cast<double>(RectanglesForCoverage(all, blocked_cells, 0.99))},
      {"rectangles_kept", static_cast<double>(kept)},
      {"kept_coverage_pct", 100.0 * double(kept_cells) / double(std::max(1L, blocked_cells))},
      {"min_pair_distance_m", min_distance},
      {"test_pairs", static_cast<double>(world.test_pairs.size())},
      {"train_pairs", static_cast<double>(world.train_pairs.size())},
      {"free_points", static_cast<double>(world.free_points.size())},
      {"tortuosity_mean", tortuosity},
      {"narrow_share", narrow_share},
      {"difficulty", (tortuosity - 1.0) + narrow_share},
  };
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace crowdsim::floorplan
