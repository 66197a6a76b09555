#include "rect_layout.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "free_raster.h"

namespace crowdsim::random_rect {
namespace {

// Layouts are built on a millimetre grid in integers: the margin tests are exact, and the
// file (4 decimals) holds exactly the layout that was checked.
std::int64_t Mm(double metres) { return std::llround(metres * 1000.0); }
double Metres(std::int64_t mm) { return static_cast<double>(mm) / 1000.0; }

// Integer box [x0, x1) x [y0, y1) of obstacle min corners (mm).
struct Box {
  std::int64_t x0, y0, x1, y1;
  bool Contains(std::int64_t x, std::int64_t y) const {
    return x >= x0 && x < x1 && y >= y0 && y < y1;
  }
};

// Obstacle in integer mm.
struct MmRect {
  std::int64_t x0, y0, x1, y1;
};

enum class Verdict { kOk, kDisconnected, kNoPair };

Verdict Check(const WorldFile& world, const RectLayoutConfig& config, double* disc_free_area) {
  const StaticMap map = world.ToStaticMap();
  const FreeRaster raster(map, RoomRegion(config), config.agent_radius, config.raster_resolution);
  if (disc_free_area) *disc_free_area = raster.FreeArea();
  if (raster.ComponentCount() != 1) return Verdict::kDisconnected;
  // About 0.2 m between tested cells: plenty for a 7 m test, and fast.
  const int stride = std::max(1, static_cast<int>(std::lround(0.2 / config.raster_resolution)));
  if (!raster.HasPairAtLeast(config.min_start_goal_dist, stride)) return Verdict::kNoPair;
  return Verdict::kOk;
}

// Buffers reused across the many layout draws (most draws are rejected quickly).
struct Scratch {
  std::vector<Box> forbidden;
  std::vector<std::int64_t> xs, ys;
  struct Cell {
    std::int64_t x0, y0, nx, count;
  };
  std::vector<Cell> cells;
};

// Draws the min corner of a w x h obstacle uniformly among all grid positions that keep the
// margins to the walls and to `placed` (exact: the free positions are the allowed box minus
// one forbidden box per placed obstacle, split into cells along their edges). False if none.
bool PlaceObstacle(const RectLayoutConfig& config, std::int64_t w, std::int64_t h,
                   const std::vector<MmRect>& placed, Rng& rng, Scratch& scratch, MmRect* out) {
  const std::int64_t lo = Mm(-0.5 * config.room_size + config.wall_margin);
  const std::int64_t hi = Mm(0.5 * config.room_size - config.wall_margin);
  const std::int64_t m = Mm(config.obstacle_margin);
  const Box allowed{lo, lo, hi - w + 1, hi - h + 1};
  if (allowed.x1 <= allowed.x0 || allowed.y1 <= allowed.y0) return false;
  // A corner in a forbidden box puts the obstacle closer than the margin to `p`.
  std::vector<Box>& forbidden = scratch.forbidden;
  std::vector<std::int64_t>& xs = scratch.xs;
  std::vector<std::int64_t>& ys = scratch.ys;
  forbidden.clear();
  xs.assign({allowed.x0, allowed.x1});
  ys.assign({allowed.y0, allowed.y1});
  for (const MmRect& p : placed) {
    const Box f{p.x0 - m - w + 1, p.y0 - m - h + 1, p.x1 + m, p.y1 + m};
    forbidden.push_back(f);
    for (std::int64_t x : {f.x0, f.x1}) xs.push_back(std::clamp(x, allowed.x0, allowed.x1));
    for (std::int64_t y : {f.y0, f.y1}) ys.push_back(std::clamp(y, allowed.y0, allowed.y1));
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());

  std::vector<Scratch::Cell>& cells = scratch.cells;
  cells.clear();
  std::int64_t total = 0;
  for (size_t j = 0; j + 1 < ys.size(); ++j) {
    for (size_t i = 0; i + 1 < xs.size(); ++i) {
      // Cell edges include every forbidden edge, so one corner decides the whole cell.
      const bool blocked = std::any_of(forbidden.begin(), forbidden.end(),
                                       [&](const Box& f) { return f.Contains(xs[i], ys[j]); });
      if (blocked) continue;
      const std::int64_t nx = xs[i + 1] - xs[i];
      const std::int64_t count = nx * (ys[j + 1] - ys[j]);
      cells.push_back({xs[i], ys[j], nx, count});
      total += count;
    }
  }
  if (total == 0) return false;
  std::int64_t k = static_cast<std::int64_t>(rng.Below(static_cast<std::uint64_t>(total)));
  for (const Scratch::Cell& c : cells) {
    if (k < c.count) {
      const std::int64_t x0 = c.x0 + k % c.nx;
      const std::int64_t y0 = c.y0 + k / c.nx;
      *out = MmRect{x0, y0, x0 + w, y0 + h};
      return true;
    }
    k -= c.count;
  }
  return false;  // not reached: k < total
}

}  // namespace

void RectLayoutConfig::Validate() const {
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("random rectangle layout: " + what);
  };
  if (obstacles < 0) fail("obstacles must be >= 0");
  if (!(room_size > 0.0)) fail("room_size must be > 0");
  if (!(wall_thickness > 0.0)) fail("wall_thickness must be > 0");
  if (!(min_side > 0.0 && min_side <= max_side)) fail("need 0 < min_side <= max_side");
  if (!(wall_margin >= 0.0 && obstacle_margin >= 0.0)) fail("margins must be >= 0");
  if (max_side > room_size - 2.0 * wall_margin) {
    fail("max_side must be <= room_size - 2 * wall_margin, or large obstacles never fit");
  }
  if (!(agent_radius > 0.0)) fail("agent_radius must be > 0");
  if (!(min_start_goal_dist >= 0.0)) fail("min_start_goal_dist must be >= 0");
  if (!(raster_resolution > 0.0)) fail("raster_resolution must be > 0");
  if (max_layout_tries < 1) fail("max_layout_tries must be >= 1");
}

Rect RoomRegion(const RectLayoutConfig& config) {
  const double h = 0.5 * config.room_size;
  return Rect::FromCorners(-h, -h, h, h);
}

WorldFile EmptyRoom(const RectLayoutConfig& config, const std::string& name) {
  const double h = 0.5 * config.room_size;
  const double o = h + config.wall_thickness;
  WorldFile w;
  w.name = name;
  w.bounds = Rect::FromCorners(-o, -o, o, o);
  // Bottom and top span the corners; left and right fit between them.
  w.rectangles = {Rect::FromCorners(-o, -o, o, -h), Rect::FromCorners(-o, h, o, o),
                  Rect::FromCorners(-o, -h, -h, h), Rect::FromCorners(h, -h, o, h)};
  return w;
}

bool LayoutIsNavigable(const WorldFile& world, const RectLayoutConfig& config,
                       RectLayoutStats* stats) {
  const Verdict v = Check(world, config, nullptr);
  if (stats && v == Verdict::kDisconnected) ++stats->rejected_disconnected;
  if (stats && v == Verdict::kNoPair) ++stats->rejected_no_pair;
  return v == Verdict::kOk;
}

WorldFile GenerateLayout(const RectLayoutConfig& config, const std::string& name, Rng& rng,
                         RectLayoutStats* stats) {
  config.Validate();
  RectLayoutStats local;
  RectLayoutStats& s = stats ? *stats : local;
  Scratch scratch;
  std::vector<MmRect> placed;
  for (int attempt = 0; attempt < config.max_layout_tries; ++attempt) {
    ++s.attempts;
    placed.clear();
    bool placed_all = true;
    const std::int64_t side_lo = Mm(config.min_side);
    const std::int64_t side_span = Mm(config.max_side) - side_lo + 1;
    for (int i = 0; i < config.obstacles && placed_all; ++i) {
      // Sizes are drawn once per obstacle and layout draw: a size that does not fit redraws
      // the whole layout rather than shrinking, so accepted sizes are the uniform draws
      // conditioned only on fitting.
      const std::int64_t w = side_lo + static_cast<std::int64_t>(rng.Below(side_span));
      const std::int64_t h = side_lo + static_cast<std::int64_t>(rng.Below(side_span));
      MmRect r;
      placed_all = PlaceObstacle(config, w, h, placed, rng, scratch, &r);
      if (placed_all) placed.push_back(r);
    }
    if (!placed_all) {
      ++s.rejected_placement;
      continue;
    }
    WorldFile world = EmptyRoom(config, name);
    std::vector<Rect> obstacles;
    for (const MmRect& r : placed) {
      obstacles.push_back(
          Rect::FromCorners(Metres(r.x0), Metres(r.y0), Metres(r.x1), Metres(r.y1)));
    }
    world.rectangles.insert(world.rectangles.end(), obstacles.begin(), obstacles.end());
    double disc_free_area = 0.0;
    const Verdict v = Check(world, config, &disc_free_area);
    if (v == Verdict::kDisconnected) ++s.rejected_disconnected;
    if (v == Verdict::kNoPair) ++s.rejected_no_pair;
    if (v != Verdict::kOk) continue;

    double obstacle_area = 0.0;
    for (const Rect& r : obstacles) {
      obstacle_area += r.Area();
      s.side_sum += r.Size().x() + r.Size().y();
      s.side_count += 2;
    }
    ++s.layouts;
    world.stats = {{"free_area_m2", config.room_size * config.room_size - obstacle_area},
                   {"disc_free_area_m2", disc_free_area},
                   {"draws", static_cast<double>(attempt + 1)}};
    return world;
  }
  throw std::runtime_error("random rectangle layout '" + name + "': no valid layout after " +
                           std::to_string(config.max_layout_tries) +
                           " draws; use fewer or smaller obstacles, or smaller margins");
}

}  // namespace crowdsim::random_rect
