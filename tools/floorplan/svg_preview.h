// SVG picture of an imported world, like the paper's Figure 2: the kept rectangles over the
// navigable mask (when known), with the free points and some test pairs.
#pragma once

#include <string>

#include "crowdsim/world_file.h"
#include "free_space.h"
#include "grid.h"

namespace crowdsim::floorplan {

/// Optional mask drawn under the rectangles (the world's own, or a re-import of its source).
struct PreviewMask {
  const Grid* mask = nullptr;  ///< navigable cells; null = no mask
  RasterFrame frame;
};

/// The SVG document; `pairs_shown` test pairs are drawn as lines.
std::string RenderPreviewSvg(const WorldFile& world, const PreviewMask& mask = {},
                             int pairs_shown = 40);

}  // namespace crowdsim::floorplan
