#include "crowdsim/render/view.h"

#include <algorithm>

namespace crowdsim::render {

View View::Fit(const Rect& world, double max_side, double margin, double header, double footer) {
  View v;
  v.world_ = world;
  const Vec2 size = world.Size().cwiseMax(Vec2(1e-6, 1e-6));
  v.scale_ = max_side / std::max(size.x(), size.y());
  v.offset_x_ = margin;
  v.offset_y_ = margin + header;
  // The header needs room for its text even when the world is tall and narrow.
  v.width_ = std::max(2.0 * margin + size.x() * v.scale_, 420.0);
  v.height_ = v.offset_y_ + size.y() * v.scale_ + margin + footer;
  // Centre a narrow world in the minimum width.
  v.offset_x_ = 0.5 * (v.width_ - size.x() * v.scale_);
  return v;
}

}  // namespace crowdsim::render
