// The key under an episode figure: a scale bar in metres and one entry per kind of mark the
// figure uses (start, goal, time dots, detections, collision, ...), flowed into lines that fit
// the figure's width.
#pragma once

#include <string>
#include <vector>

#include "crowdsim/render/drawing.h"

namespace crowdsim::render {

/// The marks a key can explain; a figure lists those it draws.
enum class KeyMark {
  kRobotStart,        ///< white square
  kRobotGoal,         ///< gold star
  kHumanStart,        ///< small open circle in the human's colour
  kHumanGoal,         ///< open diamond in the human's colour
  kTimeDot,           ///< dot every N s on every path
  kEndDisc,           ///< disc of the agent's radius where it ended (or is, in an animation)
  kObstacle,          ///< grey rectangle
  kMask,              ///< light grey: not navigable in a floor plan's mask
  kLidar,             ///< lidar beam and its hit
  kPersonReading,     ///< dashed ring and velocity of a person-sensor detection
  kCollision,         ///< dashed red ring around the robot that collided
  kCollisionPartner,  ///< red ring around the human or obstacle it hit
};

struct KeyEntry {
  KeyMark mark;
  std::string text;
};

/// A key laid out for a canvas `width` px wide: its height is known before the figure is.
class FigureKey {
 public:
  /// `px_per_metre` sizes the scale bar (a 1-2-5 length of 50-150 px).
  FigureKey(std::vector<KeyEntry> entries, double px_per_metre, double width, double margin);

  double height() const { return height_; }
  /// Draws the key with its top edge at `top`.
  void Draw(Drawing* d, double top) const;

 private:
  struct Placed {
    KeyEntry entry;
    double x = 0.0;
    int line = 0;
  };
  std::vector<Placed> placed_;
  double bar_metres_ = 1.0;
  double bar_px_ = 0.0;
  double margin_ = 0.0;
  double height_ = 0.0;
};

}  // namespace crowdsim::render
