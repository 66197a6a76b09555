// A binary raster of a floor plan: 1 = navigable (white), 0 = blocked (black). Row 0 is the
// top of the image (largest y), as in crowdsim::NavigableMask.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace crowdsim::floorplan {

/// Row-major binary image; cells outside the image count as blocked.
struct Grid {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> cells;  ///< size width * height, 1 = navigable

  Grid() = default;
  /// A width x height grid filled with `value`.
  Grid(int w, int h, std::uint8_t value = 0)
      : width(w), height(h), cells(static_cast<std::size_t>(w) * h, value) {}

  /// Index of (row, col); no bounds check.
  std::size_t Index(int row, int col) const { return static_cast<std::size_t>(row) * width + col; }
  /// True inside the image.
  bool Inside(int row, int col) const {
    return row >= 0 && row < height && col >= 0 && col < width;
  }
  /// The cell value; 0 (blocked) outside the image.
  std::uint8_t At(int row, int col) const { return Inside(row, col) ? cells[Index(row, col)] : 0; }
  /// Writable cell; no bounds check.
  std::uint8_t& operator()(int row, int col) { return cells[Index(row, col)]; }
  /// Cell value; no bounds check.
  std::uint8_t operator()(int row, int col) const { return cells[Index(row, col)]; }
  /// Number of navigable cells.
  long Count() const;
  bool operator==(const Grid& o) const = default;
};

/// Cell-wise complement (navigable <-> blocked).
Grid Inverted(const Grid& g);

}  // namespace crowdsim::floorplan
