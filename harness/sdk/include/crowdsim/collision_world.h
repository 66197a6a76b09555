// The static collision world: Bullet's broadphase culls the map's rectangles, an exact 2D narrow
// phase decides. Agents are discs per query.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/geometry.h"
#include "crowdsim/static_map.h"

namespace crowdsim {

/// How the first contact of a swept disc is found.
struct CROWDSIM_SDK_API SweepHit {
  double fraction = kInfinity;  ///< of the motion, in [0, 1]; kInfinity: no contact
  int rect = -1;                ///< index into StaticMap::rectangles
};

class CROWDSIM_SDK_API CollisionWorld {
 public:
  explicit CollisionWorld(std::shared_ptr<const StaticMap> map);
  ~CollisionWorld();
  CollisionWorld(const CollisionWorld&) = delete;
  CollisionWorld& operator=(const CollisionWorld&) = delete;

  const StaticMap& map() const { return *map_; }

  /// Unique in the process, never reused: a sensor may key map-derived data on it.
  std::uint64_t serial() const { return serial_; }

  /// Indices of rectangles whose box overlaps `box` (Bullet broadphase aabbTest).
  void QueryRects(const Rect& box, std::vector<int>* out) const;

  /// True if the disc overlaps any rectangle.
  bool DiscOverlaps(const Vec2& center, double radius) const;

  /// First contact of a disc moving in a straight line from a to b (no tunnelling).
  SweepHit SweepDisc(const Vec2& a, const Vec2& b, double radius) const;

  /// Distance from p to the nearest rectangle (kInfinity if none within `search_radius`).
  double ClearanceAt(const Vec2& p, double search_radius) const;

  /// Ray scan: per world-frame beam angle, distance to the nearest rectangle or disc, or max_range.
  /// One broadphase query per scan.
  void CastRays(const Vec2& origin, std::span<const double> world_angles, double max_range,
                std::span<const Circle> discs, double* ranges) const;

  /// The same scan along world-frame unit directions (no sine and cosine per beam).
  void CastRays(const Vec2& origin, std::span<const Vec2> world_directions, double max_range,
                std::span<const Circle> discs, double* ranges) const;

  /// Sight lines from `origin` to each of `ends`: lengths[k] = |ends[k] - origin|, blocked[k] = 1
  /// when a rectangle meets the line nearer than its end (as CastRays along it finds), else 0.
  /// Lines are culled four at a time by their bounding box: list neighbouring ones together.
  void SightLines(const Vec2& origin, std::span<const Vec2> ends, double* lengths,
                  std::uint8_t* blocked) const;

  /// Reference scan: btCollisionWorld::rayTest per beam, boxes only (slow; tests and benchmarks).
  /// Its first call builds Bullet's full world.
  void CastRaysBullet(const Vec2& origin, std::span<const double> world_angles, double max_range,
                      double* ranges) const;

 private:
  struct Impl;
  std::shared_ptr<const StaticMap> map_;
  std::uint64_t serial_;
  std::unique_ptr<Impl> impl_;  // null when the map has no rectangles
};

}  // namespace crowdsim
