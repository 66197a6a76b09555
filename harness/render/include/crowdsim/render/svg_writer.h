// SVG text of a Drawing, written directly (not through Cairo) so that every element carries
// its class (tests count obstacles and trajectories) and the bytes are deterministic.
#pragma once

#include <string>

#include "crowdsim/render/drawing.h"

namespace crowdsim::render {

/// How the SVG is wrapped.
struct SvgOptions {
  bool standalone = true;  ///< XML declaration first (a .svg file); false to inline in HTML
};

/// The drawing as SVG 1.1 text; the same drawing always gives the same bytes.
std::string ToSvg(const Drawing& drawing, const SvgOptions& options = {});

}  // namespace crowdsim::render
