#include "crowdsim/collision_world.h"

#include <btBulletCollisionCommon.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

#include "beam_scan.h"
#include "crowdsim/thread_scratch.h"

namespace crowdsim {
namespace {

// Boxes extend this far above and below the z = 0 plane every query lives in.
constexpr double kBoxHalfHeight = 1.0;

// Bullet's AABBs are float: queries are padded by this (m) and decided in double, so rounding drops
// no contact.
constexpr double kBroadphasePad = 1e-3;

// This world never runs Bullet's narrow phase, so tiny manifold and pair pools save megabytes.
constexpr int kBulletPoolSize = 16;

// Per-thread buffers so that scans and sweeps do not allocate once warmed up.
struct Scratch {
  std::vector<int> ids;
  std::vector<RelRect> rects;
  std::vector<RelDisc> discs;
  std::vector<Vec2> directions;  // the angle overload of CastRays
  std::vector<RelRect> group;    // the rectangles near four sight lines
  std::vector<Vec2> offsets;     // of the sight lines' ends from their origin
};

// Up to this many rectangles, a query tests every box (one AVX2 compare each) instead of walking
// Bullet's tree, whose traversal costs more on small maps (tests/bench/lidar_bench.cc).
constexpr std::size_t kLinearCullUpTo = 64;

// Collects the rectangle index of every proxy the broadphase reports (its client object).
struct IndexCollector final : btBroadphaseAabbCallback {
  IndexCollector(const Rect* first, std::vector<int>* out) : first(first), out(out) {}
  bool process(const btBroadphaseProxy* proxy) override {
    out->push_back(static_cast<int>(static_cast<const Rect*>(proxy->m_clientObject) - first));
    return true;
  }
  const Rect* first;
  std::vector<int>* out;
};

// Closed-box overlap (touching counts): culling must keep grazing contacts.
bool Touches(const Rect& a, const Rect& b) {
  return a.min.x() <= b.max.x() && b.min.x() <= a.max.x() && a.min.y() <= b.max.y() &&
         b.min.y() <= a.max.y();
}

}  // namespace

// Bullet's full collision world, built on the reference ray test's first call (costly, rarely
// needed).
struct BulletReferenceWorld {
  explicit BulletReferenceWorld(const std::vector<Rect>& rects)
      : config(ConstructionInfo()), dispatcher(&config), world(&dispatcher, &broadphase, &config) {
    for (const Rect& r : rects) {
      const Vec2 half = 0.5 * r.Size();
      const Vec2 center = r.Center();
      auto shape = std::make_unique<btBoxShape>(btVector3(static_cast<btScalar>(half.x()),
                                                          static_cast<btScalar>(half.y()),
                                                          static_cast<btScalar>(kBoxHalfHeight)));
      auto object = std::make_unique<btCollisionObject>();
      object->setCollisionShape(shape.get());
      btTransform transform;
      transform.setIdentity();
      transform.setOrigin(
          btVector3(static_cast<btScalar>(center.x()), static_cast<btScalar>(center.y()), 0));
      object->setWorldTransform(transform);
      object->setCollisionFlags(object->getCollisionFlags() | btCollisionObject::CF_STATIC_OBJECT);
      world.addCollisionObject(object.get(), btBroadphaseProxy::StaticFilter,
                               btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
      shapes.push_back(std::move(shape));
      objects.push_back(std::move(object));
    }
  }

  ~BulletReferenceWorld() {
    // btCollisionWorld's destructor touches the proxies of the objects it still holds.
    for (auto& object : objects) world.removeCollisionObject(object.get());
  }

  // This world never runs Bullet's narrow phase: tiny pools save megabytes.
  static btDefaultCollisionConstructionInfo ConstructionInfo() {
    btDefaultCollisionConstructionInfo info;
    info.m_defaultMaxPersistentManifoldPoolSize = kBulletPoolSize;
    info.m_defaultMaxCollisionAlgorithmPoolSize = kBulletPoolSize;
    return info;
  }

  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher;
  btDbvtBroadphase broadphase;
  btCollisionWorld world;
  std::vector<std::unique_ptr<btBoxShape>> shapes;
  std::vector<std::unique_ptr<btCollisionObject>> objects;
};

// Every query culls with Bullet's btDbvtBroadphase, one proxy per rectangle, exactly its box;
// a small map by testing all the boxes.
struct CollisionWorld::Impl {
  explicit Impl(const std::vector<Rect>& rects) : first(rects.data()) {
    if (rects.size() <= kLinearCullUpTo) {
      for (const Rect& r : rects) boxes.push_back({r.min.x(), r.min.y(), r.max.x(), r.max.y()});
      return;
    }
    proxies.reserve(rects.size());
    for (const Rect& r : rects) {
      const btVector3 lo(static_cast<btScalar>(r.min.x()), static_cast<btScalar>(r.min.y()),
                         static_cast<btScalar>(-kBoxHalfHeight));
      const btVector3 hi(static_cast<btScalar>(r.max.x()), static_cast<btScalar>(r.max.y()),
                         static_cast<btScalar>(kBoxHalfHeight));
      proxies.push_back(broadphase.createProxy(
          lo, hi, BOX_SHAPE_PROXYTYPE, const_cast<Rect*>(&r), btBroadphaseProxy::StaticFilter,
          btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter, nullptr));
    }
  }

  ~Impl() {
    // No pair is ever computed (static proxies, no narrow phase), so no dispatcher is needed.
    for (btBroadphaseProxy* proxy : proxies) broadphase.destroyProxy(proxy, nullptr);
  }

  // Appends the indices of rectangles whose AABB touches `box` padded, unsorted.
  void Broadphase(const Rect& box, std::vector<int>* out) const {
    if (!boxes.empty()) {
      const std::size_t old = out->size();
      out->resize(old + boxes.size());
      const RelRect padded{box.min.x() - kBroadphasePad, box.min.y() - kBroadphasePad,
                           box.max.x() + kBroadphasePad, box.max.y() + kBroadphasePad};
      out->resize(old + RectIdsTouching(boxes, padded, out->data() + old));
      return;
    }
    const btVector3 lo(static_cast<btScalar>(box.min.x() - kBroadphasePad),
                       static_cast<btScalar>(box.min.y() - kBroadphasePad),
                       static_cast<btScalar>(-0.5 * kBoxHalfHeight));
    const btVector3 hi(static_cast<btScalar>(box.max.x() + kBroadphasePad),
                       static_cast<btScalar>(box.max.y() + kBroadphasePad),
                       static_cast<btScalar>(0.5 * kBoxHalfHeight));
    IndexCollector collector(first, out);
    // aabbTest only reads the tree (no mutable state), so concurrent const queries are safe.
    const_cast<btDbvtBroadphase&>(broadphase).aabbTest(lo, hi, collector);
  }

  const Rect* first;
  std::vector<RelRect> boxes;  // every rectangle's, on a small map (then no proxies)
  btDbvtBroadphase broadphase;
  std::vector<btBroadphaseProxy*> proxies;
  // btDbvtBroadphase::rayTest shares one traversal stack (no BT_THREADSAFE): serialise; builds
  // `reference`.
  std::mutex ray_mutex;
  std::unique_ptr<BulletReferenceWorld> reference;
};

namespace {
std::atomic<std::uint64_t> next_serial{1};
}  // namespace

CollisionWorld::CollisionWorld(std::shared_ptr<const StaticMap> map)
    : map_(std::move(map)), serial_(next_serial.fetch_add(1, std::memory_order_relaxed)) {
  // No rectangles: no broadphase, and every query answers "free".
  if (!map_->rectangles.empty()) impl_ = std::make_unique<Impl>(map_->rectangles);
}

CollisionWorld::~CollisionWorld() = default;

void CollisionWorld::QueryRects(const Rect& box, std::vector<int>* out) const {
  out->clear();
  if (!impl_) return;
  impl_->Broadphase(box, out);
  const auto& rects = map_->rectangles;
  std::erase_if(*out, [&](int i) { return !Touches(rects[i], box); });
  std::sort(out->begin(), out->end());
}

bool CollisionWorld::DiscOverlaps(const Vec2& center, double radius) const {
  if (!impl_) return false;
  std::vector<int>& ids = ThreadScratch<Scratch>().ids;
  ids.clear();
  impl_->Broadphase(Rect{center, center}.Inflated(radius), &ids);
  const auto& rects = map_->rectangles;
  return std::any_of(ids.begin(), ids.end(),
                     [&](int i) { return DiscOverlapsRect(center, radius, rects[i]); });
}

SweepHit CollisionWorld::SweepDisc(const Vec2& a, const Vec2& b, double radius) const {
  if (!impl_) return SweepHit{};
  std::vector<int>& ids = ThreadScratch<Scratch>().ids;
  ids.clear();
  // The swept AABB holds every rectangle the disc can reach, so thin walls are never tunnelled.
  const Rect swept = Rect{a.cwiseMin(b), a.cwiseMax(b)}.Inflated(radius);
  impl_->Broadphase(swept, &ids);
  SweepHit hit;
  const auto& rects = map_->rectangles;
  for (int i : ids) {
    const double t = SweptDiscRectTime(a, b, radius, rects[i]);
    if (t < hit.fraction || (t == hit.fraction && t != kInfinity && i < hit.rect)) {
      hit.fraction = t;
      hit.rect = i;
    }
  }
  return hit;
}

double CollisionWorld::ClearanceAt(const Vec2& p, double search_radius) const {
  if (!impl_) return kInfinity;
  std::vector<int>& ids = ThreadScratch<Scratch>().ids;
  ids.clear();
  impl_->Broadphase(Rect{p, p}.Inflated(search_radius), &ids);
  double best = kInfinity;
  const auto& rects = map_->rectangles;
  for (int i : ids) best = std::min(best, PointToRectDistance(p, rects[i]));
  return best <= search_radius ? best : kInfinity;
}

void CollisionWorld::CastRays(const Vec2& origin, std::span<const double> world_angles,
                              double max_range, std::span<const Circle> discs,
                              double* ranges) const {
  std::vector<Vec2>& directions = ThreadScratch<Scratch>().directions;
  directions.clear();
  for (double a : world_angles) directions.emplace_back(std::cos(a), std::sin(a));
  CastRays(origin, directions, max_range, discs, ranges);
}

void CollisionWorld::CastRays(const Vec2& origin, std::span<const Vec2> world_directions,
                              double max_range, std::span<const Circle> discs,
                              double* ranges) const {
  Scratch& s = ThreadScratch<Scratch>();
  s.ids.clear();
  s.rects.clear();
  s.discs.clear();
  if (impl_) impl_->Broadphase(Rect{origin, origin}.Inflated(max_range), &s.ids);
  const auto& rects = map_->rectangles;
  for (int i : s.ids) {
    const Rect& r = rects[i];
    // The broadphase box is a square; drop what lies in its corners, beyond every beam.
    if (PointToRectDistance(origin, r) > max_range) continue;
    s.rects.push_back({r.min.x() - origin.x(), r.min.y() - origin.y(), r.max.x() - origin.x(),
                       r.max.y() - origin.y()});
  }
  for (const Circle& d : discs) {
    const Vec2 c = d.center - origin;
    const double reach = max_range + d.radius;
    const double c2 = c.squaredNorm();
    if (c2 > reach * reach) continue;
    s.discs.push_back({c.x(), c.y(), c2 - d.radius * d.radius});
  }

  ScanBeams(world_directions, max_range, s.rects, s.discs, ranges);
}

void CollisionWorld::SightLines(const Vec2& origin, std::span<const Vec2> ends, double* lengths,
                                std::uint8_t* blocked) const {
  Scratch& s = ThreadScratch<Scratch>();
  const std::size_t n = ends.size();
  s.directions.resize(n);
  s.offsets.resize(n);
  Vec2 lo = origin, hi = origin;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 to = ends[k] - origin;
    s.offsets[k] = to;
    lengths[k] = to.norm();
    s.directions[k] = lengths[k] > 0.0 ? Vec2(to / lengths[k]) : Vec2(1.0, 0.0);
    lo = lo.cwiseMin(ends[k]);
    hi = hi.cwiseMax(ends[k]);
  }
  s.ids.clear();
  s.rects.clear();
  if (impl_) impl_->Broadphase(Rect{lo, hi}.Inflated(kSightPad), &s.ids);
  for (int i : s.ids) {
    const Rect& r = map_->rectangles[i];
    s.rects.push_back({r.min.x() - origin.x(), r.min.y() - origin.y(), r.max.x() - origin.x(),
                       r.max.y() - origin.y()});
  }
  s.group.resize(s.rects.size());
  ScanSightLines(s.offsets, s.directions, lengths, s.rects, s.group.data(), blocked);
}

void CollisionWorld::CastRaysBullet(const Vec2& origin, std::span<const double> world_angles,
                                    double max_range, double* ranges) const {
  if (!impl_) {
    std::fill(ranges, ranges + world_angles.size(), max_range);
    return;
  }
  std::lock_guard<std::mutex> lock(impl_->ray_mutex);
  if (!impl_->reference)
    impl_->reference = std::make_unique<BulletReferenceWorld>(map_->rectangles);
  btCollisionWorld& world = impl_->reference->world;
  const btVector3 from(static_cast<btScalar>(origin.x()), static_cast<btScalar>(origin.y()), 0);
  for (size_t k = 0; k < world_angles.size(); ++k) {
    const Vec2 end =
        origin + max_range * Vec2(std::cos(world_angles[k]), std::sin(world_angles[k]));
    const btVector3 to(static_cast<btScalar>(end.x()), static_cast<btScalar>(end.y()), 0);
    btCollisionWorld::ClosestRayResultCallback callback(from, to);
    world.rayTest(from, to, callback);
    ranges[k] = callback.hasHit() ? static_cast<double>(callback.m_closestHitFraction) * max_range
                                  : max_range;
  }
}

}  // namespace crowdsim
