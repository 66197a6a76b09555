// Reading floor-plan images (PNG of any colour type, binary or ASCII PGM) as binary grids,
// and writing grids as PNG (previews).
#pragma once

#include <filesystem>
#include <string>

#include "grid.h"

namespace crowdsim::floorplan {

/// Reads PNG (gray, gray+alpha, palette, RGB, RGBA; 8 or 16 bit) or PGM (P2/P5). A pixel is
/// navigable when it is transparent (alpha 0) or light (luminance >= half the range): the
/// Gibson maps draw obstacles black on a transparent or white page. Throws FloorplanError
/// naming the file when it is missing, not an image, or empty.
Grid ReadBinaryImage(const std::filesystem::path& path);

/// PNG bytes of `grid` (navigable white, blocked `blocked_gray`), for embedding in SVG.
std::string EncodePng(const Grid& grid, unsigned char blocked_gray = 0);

/// Writes `grid` as an 8-bit PNG file (navigable 255, blocked 0). Throws FloorplanError.
void WritePng(const Grid& grid, const std::filesystem::path& path);

}  // namespace crowdsim::floorplan
