#include "navigable_component.h"

#include <cmath>
#include <utility>

#include "morphology.h"

namespace crowdsim::floorplan {

std::vector<double> ClearanceCells(const Grid& navigable) {
  std::vector<double> d = SquaredDistanceToZero(navigable);
  for (double& x : d) x = x > 0.0 ? std::sqrt(x) - 0.5 : 0.0;
  return d;
}

DiscComponent LargestDiscComponent(const Grid& navigable, double radius_cells) {
  DiscComponent out;
  const std::vector<double> clearance = ClearanceCells(navigable);
  Grid centres(navigable.width, navigable.height, 0);
  for (size_t i = 0; i < clearance.size(); ++i) {
    centres.cells[i] = navigable.cells[i] && clearance[i] >= radius_cells - 1e-9 ? 1 : 0;
  }
  out.centre_cells_all = centres.Count();

  // Label the components with one breadth-first pass; keep the biggest.
  const int w = centres.width;
  std::vector<int> label(centres.cells.size(), -1);
  std::vector<size_t> queue;
  int best_label = -1;
  long best_count = 0;
  for (size_t seed = 0; seed < centres.cells.size(); ++seed) {
    if (!centres.cells[seed] || label[seed] >= 0) continue;
    const int id = out.components++;
    queue.assign(1, seed);
    label[seed] = id;
    for (size_t head = 0; head < queue.size(); ++head) {
      const size_t i = queue[head];
      const int r = static_cast<int>(i / w), c = static_cast<int>(i % w);
      const std::pair<int, int> next[4] = {{r + 1, c}, {r - 1, c}, {r, c + 1}, {r, c - 1}};
      for (const auto& [nr, nc] : next) {
        if (!centres.Inside(nr, nc)) continue;
        const size_t j = centres.Index(nr, nc);
        if (centres.cells[j] && label[j] < 0) {
          label[j] = id;
          queue.push_back(j);
        }
      }
    }
    if (static_cast<long>(queue.size()) > best_count) {
      best_count = static_cast<long>(queue.size());
      best_label = id;
    }
  }
  if (best_count == 0) {
    out.centres = Grid(navigable.width, navigable.height, 0);
    out.reach = out.centres;
    return out;
  }
  Grid best(navigable.width, navigable.height, 0);
  for (size_t i = 0; i < label.size(); ++i) best.cells[i] = label[i] == best_label ? 1 : 0;
  out.centres = best;
  // Reach: distance to the nearest centre cell, so the centres are the zeros.
  const std::vector<double> to_centre = SquaredDistanceToZero(Inverted(best), false);
  const double limit = (radius_cells + 0.5) * (radius_cells + 0.5) + 1e-9;
  out.reach = Grid(navigable.width, navigable.height, 0);
  for (size_t i = 0; i < to_centre.size(); ++i) {
    out.reach.cells[i] = navigable.cells[i] && to_centre[i] <= limit ? 1 : 0;
  }
  return out;
}

}  // namespace crowdsim::floorplan
