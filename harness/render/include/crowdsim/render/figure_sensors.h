// The sensor layer of an episode figure (--sensors-at STEP): where the agents were at that
// step, the lidar beams and their hits, the person detections with their velocities.
#pragma once

#include <string>

#include "crowdsim/render/drawing.h"
#include "crowdsim/render/sensor_snapshot.h"
#include "crowdsim/render/view.h"

namespace crowdsim::render {

/// Draws the snapshot over the figure; the robot's disc in `robot_color`.
void DrawSensorSnapshot(Drawing* d, const View& v, const SensorSnapshot& s,
                        const Color& robot_color);

/// The sensors read, for the header: e.g. "lidar (720 beams), person (3 people), route (7.42,
/// 0.71, -0.70)" (a sensor's other features as read, two decimals).
std::string SensorList(const SensorSnapshot& s);

}  // namespace crowdsim::render
