#include "grid.h"

#include <numeric>

namespace crowdsim::floorplan {

long Grid::Count() const {
  return std::accumulate(cells.begin(), cells.end(), 0L,
                         [](long n, std::uint8_t c) { return n + (c != 0); });
}

Grid Inverted(const Grid& g) {
  Grid out = g;
  for (auto& c : out.cells) c = c ? 0 : 1;
  return out;
}

}  // namespace crowdsim::floorplan
