// The static collision world: the map's rectangles as proxies in Bullet's broadphase (its
// dynamic AABB tree, btDbvtBroadphase), which culls; an exact 2D narrow phase decides. Agents are
// passed as discs per query (few, moving every step and per lookahead candidate).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/geometry.h"
#include "crowdsim/static_map.h"

namespace crowdsim {

/// How the first contact of a swept disc was found.
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

  /// Unique within the process and never reused (unlike an address): a sensor may key data it
  /// derives from the map (e.g. route's distance field) on it.
  std::uint64_t serial() const { return serial_; }

  /// Indices of rectangles whose box overlaps `box` (Bullet broadphase aabbTest).
  void QueryRects(const Rect& box, std::vector<int>* out) const;

  /// True if the disc overlaps any rectangle.
  bool DiscOverlaps(const Vec2& center, double radius) const;

  /// First contact of a disc moving in a straight line from a to b (no tunnelling).
  SweepHit SweepDisc(const Vec2& a, const Vec2& b, double radius) const;

  /// Distance from p to the nearest rectangle (kInfinity if none within `search_radius`).
  double ClearanceAt(const Vec2& p, double search_radius) const;

  /// Ray scan: for each world-frame beam angle, the distance to the nearest rectangle or disc
  /// hit from `origin`, or max_range. One broadphase query per scan, exact 2D per beam.
  void CastRays(const Vec2& origin, std::span<const double> world_angles, double max_range,
                std::span<const Circle> discs, double* ranges) const;

  /// The same scan along world-frame unit directions (a sensor with fixed beams rotates its
  /// precomputed beam directions by the heading instead of taking a sine and cosine per beam).
  void CastRays(const Vec2& origin, std::span<const Vec2> world_directions, double max_range,
                std::span<const Circle> discs, double* ranges) const;

  /// Reference scan: btCollisionWorld::rayTest per beam against the boxes only (slow;
  /// kept for tests and benchmarks that check the fast scan). Its first call builds Bullet's
  /// complete collision world (configuration, dispatcher, box objects) for this map.
  void CastRaysBullet(const Vec2& origin, std::span<const double> world_angles, double max_range,
                      double* ranges) const;

 private:
  struct Impl;
  std::shared_ptr<const StaticMap> map_;
  std::uint64_t serial_;
  std::unique_ptr<Impl> impl_;  // null when the map has no rectangles
};

}  // namespace crowdsim
