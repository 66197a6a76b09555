// The people detector of CrowdNav: every human's position, velocity and radius in the
// robot's frame, optionally limited to a detection range, a field of view and what the robot
// can see past the map's rectangles and other people, with false detections, tracked
// identities and estimated velocities.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "crowdsim/params.h"
#include "crowdsim/sensor.h"
#include "false_detections.h"
#include "person_tracker.h"

namespace crowdsim::person {

/// What hides a person from the robot.
enum class Occlusion { kNone, kObstacles, kObstaclesAndPeople };

class PersonSensor final : public Sensor {
 public:
  explicit PersonSensor(const Params& params);
  void Sense(const SenseInput& in, SensorReading* out) const override;
  /// All the episode with the nearest-neighbour tracker, the last max_gap + 1 steps for
  /// velocities estimated alone, else none.
  int HistorySteps() const override;

 private:
  struct Scratch;  // one thread's buffers and tracker memos (person_sensor.cc)

  /// This step's detections (in range, view and sight, not missed, noisy) and phantoms.
  void Detect(const SenseInput& in, Scratch& s, std::vector<Detection>* out) const;
  /// s.state: the tracker's state after the last of `in.past` (replayed, or continued from this
  /// thread's memo of the same history).
  void TrackedBefore(const SenseInput& in, Scratch& s) const;
  /// Keeps s.state, the tracker's after this real (not lookahead) reading, for the next one.
  void KeepPending(const SenseInput& in, Scratch& s) const;
  /// Whether human `i` lies within max_range and the field of view.
  bool InRangeAndView(const SenseInput& in, std::size_t i) const;
  /// Keeps the candidates (s.detected) a sight line from the robot's centre reaches (the centre
  /// or either edge of the disc), in order.
  void Unoccluded(const SenseInput& in, Scratch& s) const;
  /// Whether another person stands on the sight line to `end` (on human `target`), `length` m;
  /// `near`: each person's distance from the robot's centre less its radius.
  bool PersonInTheWay(const SenseInput& in, const Vec2& end, double length, std::size_t target,
                      std::span<const double> near) const;

  double max_range_;     // m; 0 = unlimited
  double half_fov_cos_;  // cos of half the field of view; -1 = all around
  Occlusion occlusion_;
  double detection_prob_;    // per step and human in view
  double position_noise_;    // m, per axis
  double false_detections_;  // expected phantoms a reading
  SensedArea phantom_area_;
  bool estimate_velocity_;
  bool track_;  // nearest-neighbour tracker: report track ids
  TrackerConfig tracker_;
};

/// The parameters person declares (max_range, fov_deg, occlusion, detection_prob,
/// position_noise, false_detections, velocity, tracker, track_gate, track_max_gap).
ParamSchema Schema();

}  // namespace crowdsim::person
