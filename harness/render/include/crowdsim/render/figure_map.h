// The map layer of an episode figure: a floor plan's navigable mask, the map bounds and the
// rectangle obstacles, drawn under everything else.
#pragma once

#include <string>

#include "crowdsim/render/drawing.h"
#include "crowdsim/render/view.h"
#include "crowdsim/scenario.h"

namespace crowdsim::render {

/// A world rectangle on the canvas (its corners mapped, y flipped).
void AddWorldRect(Drawing* d, const View& v, const std::string& cls, const Rect& r,
                  const Style& style);

/// Draws the mask (blocked cells grey) under the dashed bounds and the filled obstacles.
void DrawMap(Drawing* d, const View& v, const StaticMap& map);

}  // namespace crowdsim::render
