// Synthetic floor plans for the importer tests.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "floorplan/grid.h"

namespace crowdsim::floorplan::testing {

/// Writes `g` as a binary PGM (navigable 255, blocked 0).
inline void WritePgm(const Grid& g, const std::filesystem::path& path) {
  std::ofstream f(path, std::ios::binary);
  f << "P5\n" << g.width << " " << g.height << "\n255\n";
  for (auto c : g.cells) f.put(static_cast<char>(c ? 255 : 0));
}

/// Sets cells rows r0..r1, cols c0..c1 (inclusive) to `value`.
inline void Fill(Grid& g, int r0, int c0, int r1, int c1, std::uint8_t value) {
  for (int r = r0; r <= r1; ++r) {
    for (int c = c0; c <= c1; ++c) g(r, c) = value;
  }
}

/// An outline drawing at 0.1 m/px: white page, a square room of 1-cell walls from (top, left)
/// with `size` cells per side, and a door of `door` cells in the left wall.
inline Grid OutlineRoom(int page, int top, int left, int size, int door) {
  Grid g(page, page, 1);
  const int bottom = top + size - 1, right = left + size - 1;
  Fill(g, top, left, top, right, 0);
  Fill(g, bottom, left, bottom, right, 0);
  Fill(g, top, left, bottom, left, 0);
  Fill(g, top, right, bottom, right, 0);
  const int mid = top + size / 2;
  if (door > 0) Fill(g, mid - door / 2, left, mid - door / 2 + door - 1, left, 1);
  return g;
}

/// An 8 x 8 m room with a 0.8 m door and a table, on a 12 x 12 m page: written as dir/room.pgm.
inline std::filesystem::path WriteRoomPlan(const std::filesystem::path& dir) {
  Grid g = OutlineRoom(120, 20, 20, 80, 8);
  Fill(g, 40, 40, 49, 59, 0);  // a table
  const auto path = dir / "room.pgm";
  WritePgm(g, path);
  return path;
}

}  // namespace crowdsim::floorplan::testing
