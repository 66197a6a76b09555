// Human start and goal placement in free space, shared by world plugins. The caller gives free
// space (connected for the disc) and candidates; placement adds separation and bounded retries.
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/rng.h"
#include "crowdsim/scenario.h"
#include "crowdsim/static_map.h"
#include "crowdsim/world_source.h"

namespace crowdsim {

/// Placement failed (the room is too small for the request); what() says what and the fix.
class CROWDSIM_SDK_API PlacementError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Points where a disc of `clearance` fits: inside the bounds and touching no rectangle.
class CROWDSIM_SDK_API DiscFreeSpace {
 public:
  /// `clearance` is the agent radius plus any safety margin (m, >= 0).
  DiscFreeSpace(std::shared_ptr<const StaticMap> map, double clearance);
  /// True if the disc centred at `p` lies inside the bounds and overlaps no rectangle.
  bool Contains(const Vec2& p) const;
  /// The clearance this space is built with (m).
  double clearance() const { return clearance_; }

 private:
  std::shared_ptr<const StaticMap> map_;
  double clearance_;
  Rect inner_;               // where the disc's centre keeps inside the bounds
  std::vector<Rect> reach_;  // each rectangle grown by the clearance (and a hair): the
                             // points outside it cannot touch the rectangle
};

/// Candidate points for starts and goals; the placement filters them with the predicate.
using PointSampler = std::function<Vec2(Rng&)>;

/// Uniform candidates in `region` (rooms generated from rectangles).
CROWDSIM_SDK_API PointSampler UniformSampler(const Rect& region);
/// Uniform candidates in the disc of `radius` around `centre` (group members near their leader).
CROWDSIM_SDK_API PointSampler DiscSampler(const Vec2& centre, double radius);
/// Candidates drawn uniformly from a fixed list (floor plans' free points); `points` non-empty.
CROWDSIM_SDK_API PointSampler ListSampler(std::vector<Vec2> points);

/// Free space and candidate points of one world.
struct CROWDSIM_SDK_API PlacementArea {
  std::function<bool(const Vec2&)> is_free;  ///< true where a human's centre may stand
  PointSampler sample;                       ///< candidate centres
  /// Optional stricter goal rule: where a standing human leaves room to pass. Relaxed to `is_free`
  /// late in the tries.
  std::function<bool(const Vec2&)> is_goal_free;
  /// Optional (zero area: none) box around the free space: points `sample` fails are then drawn
  /// uniformly from it; failures report density.
  Rect region;
};

/// The worlds' default `passage_padding` (m): 0.01, the radius padding CrowdNav's ORCA humans use.
inline constexpr double kDefaultPassagePadding = 0.01;

/// Centre clearance leaving room to pass a standing human: its radius plus a passer's diameter,
/// each radius plus `padding`.
CROWDSIM_SDK_API double PassableGoalClearance(double human_radius, double padding);

/// The rules of human placement (defaults: paper settings).
struct CROWDSIM_SDK_API HumanPlacementOptions {
  double human_radius = 0.3;     ///< m
  double human_v_pref = 1.0;     ///< m/s
  double robot_radius = 0.3;     ///< m
  double discomfort_dist = 0.2;  ///< m; extra gap between agents' discs at start and at goal
  double goal_min_dist = 3.0;    ///< m; a goal's distance from the previous point, if room allows
  int new_goal_count = 16;       ///< goals per human in HumanGoalMode::kNewGoal (>= 1)
  int max_tries = 2000;          ///< candidate draws per point before giving up (>= 1)
  double group_spread = 1.5;     ///< m; a group member starts and ends this near its leader's

  /// Options from a request's radii, speeds and discomfort distance (other fields default).
  static HumanPlacementOptions FromRequest(const ScenarioRequest& request);
};

/// Places request.num_humans humans. Starts at least 2 r_h + discomfort_dist apart, r_h + r_robot +
/// discomfort_dist from the robot's start; goals likewise (goal k against goal k, and the robot's
/// goal). Each goal is at least goal_min_dist from the previous point and satisfies
/// area.is_goal_free (if set); both relax over the second half of the tries. kStay: one goal;
/// kNewGoal: new_goal_count. Candidates: area.sample, then area.region if set; a group member's
/// first within group_spread of its leader's point. Deterministic per rng state. Throws
/// PlacementError (with density when area.region is set).
CROWDSIM_SDK_API std::vector<HumanSpec> PlaceHumans(const PlacementArea& area,
                                                    const Vec2& robot_start, const Vec2& robot_goal,
                                                    const ScenarioRequest& request,
                                                    const HumanPlacementOptions& options, Rng& rng);

}  // namespace crowdsim
