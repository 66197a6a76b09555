#include "orca/linear_program.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "orca/geometry.h"

namespace crowdsim::orca {
namespace {

// Optimum on line `line_no` inside the disc, subject to lines [0, line_no). False when the
// feasible interval on that line is empty.
bool SolveOnLine(std::span<const OrcaLine> lines, std::size_t line_no, double radius,
                 const Vec2& opt, bool direction_opt, Vec2* result) {
  const OrcaLine& line = lines[line_no];
  const double dot = line.point.dot(line.direction);
  const double discriminant = dot * dot + radius * radius - line.point.squaredNorm();
  if (discriminant < 0.0) return false;  // the line misses the max-speed disc

  const double sqrt_disc = std::sqrt(discriminant);
  double t_left = -dot - sqrt_disc;
  double t_right = -dot + sqrt_disc;
  for (std::size_t i = 0; i < line_no; ++i) {
    const double denominator = Det(line.direction, lines[i].direction);
    const double numerator = Det(lines[i].direction, line.point - lines[i].point);
    if (std::abs(denominator) <= kEpsilon) {
      // Parallel: either line i excludes all of this line or none of it.
      if (numerator < 0.0) return false;
      continue;
    }
    const double t = numerator / denominator;
    if (denominator >= 0.0) {
      t_right = std::min(t_right, t);
    } else {
      t_left = std::max(t_left, t);
    }
    if (t_left > t_right) return false;
  }

  if (direction_opt) {
    *result = line.point + (opt.dot(line.direction) > 0.0 ? t_right : t_left) * line.direction;
  } else {
    const double t = std::clamp(line.direction.dot(opt - line.point), t_left, t_right);
    *result = line.point + t * line.direction;
  }
  return true;
}

}  // namespace

std::size_t SolveLinearProgram2(std::span<const OrcaLine> lines, double radius, const Vec2& opt,
                                bool direction_opt, Vec2* result) {
  if (direction_opt) {
    *result = opt * radius;
  } else if (opt.squaredNorm() > radius * radius) {
    *result = opt.normalized() * radius;
  } else {
    *result = opt;
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (Det(lines[i].direction, lines[i].point - *result) > 0.0) {
      // The current optimum violates line i: the new optimum lies on it.
      const Vec2 previous = *result;
      if (!SolveOnLine(lines, i, radius, opt, direction_opt, result)) {
        *result = previous;
        return i;
      }
    }
  }
  return lines.size();
}

void SolveLinearProgram3(std::span<const OrcaLine> lines, std::size_t num_hard, std::size_t begin,
                         double radius, Vec2* result) {
  thread_local std::vector<OrcaLine> projected;
  double distance = 0.0;
  for (std::size_t i = begin; i < lines.size(); ++i) {
    if (Det(lines[i].direction, lines[i].point - *result) <= distance) continue;
    // Line i is violated by more than the current worst: optimise the violation of line i
    // against each earlier soft line j along their bisector, keeping the hard lines.
    projected.assign(lines.begin(), lines.begin() + static_cast<std::ptrdiff_t>(num_hard));
    for (std::size_t j = num_hard; j < i; ++j) {
      OrcaLine bisector;
      const double determinant = Det(lines[i].direction, lines[j].direction);
      if (std::abs(determinant) <= kEpsilon) {
        if (lines[i].direction.dot(lines[j].direction) > 0.0) continue;  // same direction
        bisector.point = 0.5 * (lines[i].point + lines[j].point);
      } else {
        bisector.point = lines[i].point +
                         (Det(lines[j].direction, lines[i].point - lines[j].point) / determinant) *
                             lines[i].direction;
      }
      bisector.direction = (lines[j].direction - lines[i].direction).normalized();
      projected.push_back(bisector);
    }
    const Vec2 previous = *result;
    const Vec2 outward(-lines[i].direction.y(), lines[i].direction.x());
    if (SolveLinearProgram2(projected, radius, outward, true, result) < projected.size()) {
      // Only floating-point error can make this fail; the previous result stays valid.
      *result = previous;
    }
    distance = Det(lines[i].direction, lines[i].point - *result);
  }
}

}  // namespace crowdsim::orca
