// Writes a still figure to a file in the format its extension names.
#pragma once

#include <filesystem>

#include "crowdsim/render/drawing.h"

namespace crowdsim::render {

/// Default PNG pixels per drawing pixel: crisp on high-density screens and in papers.
inline constexpr double kDefaultPngScale = 2.0;

/// Writes `drawing` to `path` as SVG, PNG (`png_scale` px per drawing px) or PDF (by
/// extension). Throws std::invalid_argument for another extension (animations need
/// WriteAnimation) and std::runtime_error on I/O.
void WriteFigure(const Drawing& drawing, const std::filesystem::path& path,
                 double png_scale = kDefaultPngScale);

}  // namespace crowdsim::render
