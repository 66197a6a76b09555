// A raster of where a disc's centre may stand in a room: used to reject random layouts whose
// free space is split in pieces or too small for a long robot trip.
#pragma once

#include <vector>

#include "crowdsim/geometry.h"
#include "crowdsim/static_map.h"

namespace crowdsim::random_rect {

/// Cell centres of `region` at `resolution`, each marked free when a disc of `clearance`
/// centred there is inside the map's bounds and touches no rectangle.
class FreeRaster {
 public:
  /// `resolution` in m (> 0); cells cover `region` (the room without its walls).
  FreeRaster(const StaticMap& map, const Rect& region, double clearance, double resolution);

  /// Cells along y.
  int rows() const { return rows_; }
  /// Cells along x.
  int cols() const { return cols_; }
  /// Cell side (m).
  double resolution() const { return resolution_; }
  /// Centre of cell (row, col); row 0 at min y.
  Vec2 CellCentre(int row, int col) const;
  /// True if the disc fits at the centre of cell (row, col).
  bool Free(int row, int col) const { return free_[Index(row, col)] != 0; }
  /// Number of free cells.
  int FreeCount() const { return free_count_; }
  /// Free area (m^2): free cells times the cell area.
  double FreeArea() const { return free_count_ * resolution_ * resolution_; }
  /// Number of 4-connected components of free cells (0 when nothing is free).
  int ComponentCount() const;
  /// True if two free cell centres are at least `distance` apart (checked on every
  /// `stride`-th cell in each direction, so it may miss pairs only a stride away from it).
  bool HasPairAtLeast(double distance, int stride) const;

 private:
  size_t Index(int row, int col) const { return static_cast<size_t>(row) * cols_ + col; }

  Rect region_;
  double resolution_;
  int rows_ = 0;
  int cols_ = 0;
  int free_count_ = 0;
  std::vector<unsigned char> free_;
};

}  // namespace crowdsim::random_rect
