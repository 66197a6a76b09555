// The person sensor's false detections (clutter): phantom people a detector reports where
// nobody stands, a Poisson number per reading spread uniformly over the free sensed area.
#pragma once

#include <vector>

#include "crowdsim/sensor.h"
#include "person_tracker.h"

namespace crowdsim::person {

/// How far phantoms appear when the sensor's range is unlimited (m).
inline constexpr double kPhantomRange = 5.0;
/// A phantom's radius (m), a person's in CrowdNav.
inline constexpr double kPhantomRadius = 0.3;
/// Draws of a phantom's place before it is dropped (none free in the sensed area).
inline constexpr int kPhantomTries = 16;

/// Where phantoms may appear: within `range` m of the robot and `half_fov` rad of its heading.
struct SensedArea {
  double range = kPhantomRange;
  double half_fov = 3.141592653589793;
};

/// A Poisson draw with mean `mean` (Knuth's product of uniforms; the mean stays small).
int PoissonCount(Rng& rng, double mean);

/// Appends this reading's phantoms (`rate` expected) to `out`: each uniform over `area`, its disc
/// clear of the map's rectangles and inside its bounds, at rest; drawn from the reading's noise
/// stream (episode, step), so the same on any thread and in a lookahead.
void AddFalseDetections(const SenseInput& in, const SensedArea& area, double rate,
                        std::vector<Detection>* out);

}  // namespace crowdsim::person
