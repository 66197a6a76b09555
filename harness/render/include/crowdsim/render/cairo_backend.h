// Cairo painting of a Drawing: PNG and PDF files, raw rasters for animations, PNG bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "crowdsim/render/drawing.h"

namespace crowdsim::render {

/// Writes the drawing as a PNG, `scale` px per drawing px. Throws std::runtime_error on I/O.
void WritePng(const Drawing& drawing, const std::filesystem::path& path, double scale = 1.0);

/// Writes the drawing as a one-page PDF (1 drawing px = 1 pt). Throws std::runtime_error.
void WritePdf(const Drawing& drawing, const std::filesystem::path& path);

/// PNG file bytes of the drawing (thumbnails in the report).
std::string PngBytes(const Drawing& drawing, double scale = 1.0);

/// PNG file bytes of a raster (the mask image inside SVG figures).
std::string EncodePng(const RgbaImage& image);

/// An opaque 8-bit RGB raster, row-major, row 0 at the top.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  ///< 3 bytes per pixel
};

/// The drawing rasterised at `scale` (animation frames).
RgbImage Rasterize(const Drawing& drawing, double scale = 1.0);

}  // namespace crowdsim::render
