// The immutable static part of a world: axis-aligned rectangles and the world bounds.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/geometry.h"

namespace crowdsim {

/// Optional raster of the navigable area (floor plans), row 0 at max y, 1 = navigable.
struct CROWDSIM_SDK_API NavigableMask {
  int width = 0;
  int height = 0;
  double resolution = 0.1;     ///< metres per pixel
  Vec2 origin = Vec2::Zero();  ///< world position of the lower-left corner of pixel (height-1, 0)
  std::vector<unsigned char> cells;  ///< row-major, size width * height
  bool Navigable(int row, int col) const {
    return cells[static_cast<size_t>(row) * width + col] != 0;
  }
};

/// Rectangles and bounds of a world; never changes during an episode.
struct CROWDSIM_SDK_API StaticMap {
  std::string name;                           ///< world identity (file name or layout id)
  Rect bounds;                                ///< region agents live in, walls included
  std::vector<Rect> rectangles;               ///< obstacles and walls
  std::shared_ptr<const NavigableMask> mask;  ///< floor plans only; may be null
  std::string attribution;                    ///< source credit for derived real-world maps
};

}  // namespace crowdsim
