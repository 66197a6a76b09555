// The map from world metres (y up) to canvas pixels (y down) of one figure.
#pragma once

#include "crowdsim/geometry.h"

namespace crowdsim::render {

/// World-to-canvas transform: uniform scale, y flipped, a margin, a header and a footer band.
class View {
 public:
  /// Fits `world` into at most `max_side` px per side, below a `header` px band and above a
  /// `footer` px band.
  static View Fit(const Rect& world, double max_side, double margin, double header,
                  double footer = 0.0);

  /// Canvas point of a world point.
  Vec2 ToCanvas(const Vec2& p) const {
    return Vec2(offset_x_ + (p.x() - world_.min.x()) * scale_,
                offset_y_ + (world_.max.y() - p.y()) * scale_);
  }
  /// Canvas length of a world length (m).
  double Length(double metres) const { return metres * scale_; }
  double scale() const { return scale_; }    ///< px per metre
  double width() const { return width_; }    ///< canvas px
  double height() const { return height_; }  ///< canvas px
  const Rect& world() const { return world_; }

 private:
  Rect world_;
  double scale_ = 1.0;
  double offset_x_ = 0.0;
  double offset_y_ = 0.0;
  double width_ = 0.0;
  double height_ = 0.0;
};

}  // namespace crowdsim::render
