// The navigable region of a floor plan for a disc-shaped agent: the largest connected set of
// centre positions where the disc fits, and the area the disc sweeps from there.
#pragma once

#include <vector>

#include "grid.h"

namespace crowdsim::floorplan {

/// Result of LargestDiscComponent; all grids have the input's size.
struct DiscComponent {
  Grid centres;  ///< cells whose centre has clearance >= radius, in the largest component
  Grid reach;    ///< navigable cells within radius of a centre cell: the usable free space
  long centre_cells_all = 0;  ///< centre cells over all components
  int components = 0;         ///< number of components of centre cells
};

/// Erodes the navigable area by a disc of `radius_cells` (a cell is a centre when its centre
/// is at least radius + half a cell from the centre of every blocked cell, i.e. the disc stays
/// off the blocked squares along the axes), labels the 4-connected components of the centres
/// (4-connected: a diagonal step between two centres may graze a corner), keeps the largest
/// (first in row order on ties), and grows it back by the radius within the navigable area.
DiscComponent LargestDiscComponent(const Grid& navigable, double radius_cells);

/// Clearance of every cell centre in cells: distance to the nearest blocked cell's edge along
/// the centre line (centre-to-centre distance minus half a cell; outside counts as blocked).
std::vector<double> ClearanceCells(const Grid& navigable);

}  // namespace crowdsim::floorplan
