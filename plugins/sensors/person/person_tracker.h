// The person sensor's tracker: greedy nearest-neighbour association of a step's detections to
// the tracks of the steps before, identities that persist while a person is seen, and velocities
// estimated from the detections' positions. A pure step function: the sensor replays it over the
// episode's past (no state between readings).
#pragma once

#include <vector>

#include "crowdsim/geometry.h"
#include "crowdsim/observation.h"

namespace crowdsim::person {

/// One detection of a reading: as reported (sensor frame), where it lies in the world, and what
/// the tracker makes of it.
struct Detection {
  PersonObservation seen;        ///< sensor frame, as reported before tracking
  Vec2 world = Vec2::Zero();     ///< the reported position in the world frame
  int person = -1;               ///< the human detected; -1 a false detection
  int track = -1;                ///< set by TrackStep: the track's id (kIdentity: the person)
  Vec2 velocity = Vec2::Zero();  ///< set by TrackStep: the estimate, world frame, m/s
};

/// How detections are associated from step to step.
enum class Association {
  kNearest,   ///< greedy nearest neighbour within the gate (a real tracker's rule)
  kIdentity,  ///< the true person (velocity estimates without a tracker); phantoms: none
};

struct TrackerConfig {
  Association association = Association::kNearest;
  double gate = 1.0;        ///< m; the farthest a detection may lie from a track's last position
  int max_gap = 2;          ///< steps a track survives without a detection
  double time_step = 0.25;  ///< s
};

/// A followed person: its id, its last detected position (world frame) and that step.
struct Track {
  int id = 0;
  Vec2 position = Vec2::Zero();
  int last_step = 0;
};

/// The tracks alive after a step and the next new track's id (ids count up from 0).
struct TrackerState {
  std::vector<Track> tracks;
  int next_id = 0;
};

/// Associates the detections of `step` to `state`'s tracks (those detected within max_gap steps
/// before), sets each detection's track and estimated velocity (the change of position since
/// its track's last detection over the time between; zero for a new track), starts tracks for
/// the rest and drops the tracks that can no longer be continued at the next step.
void TrackStep(const TrackerConfig& config, int step, std::vector<Detection>* detections,
               TrackerState* state);

}  // namespace crowdsim::person
