#include "crowdsim/render/marks.h"

#include <cmath>

namespace crowdsim::render {

std::vector<Vec2> Star(const Vec2& c, double outer) {
  std::vector<Vec2> pts;
  for (int i = 0; i < 10; ++i) {
    const double a = -M_PI / 2 + i * M_PI / 5;
    const double r = i % 2 == 0 ? outer : 0.45 * outer;
    pts.emplace_back(c.x() + r * std::cos(a), c.y() + r * std::sin(a));
  }
  return pts;
}

std::vector<Vec2> Square(const Vec2& c, double half) {
  return {c + Vec2(-half, -half), c + Vec2(half, -half), c + Vec2(half, half),
          c + Vec2(-half, half)};
}

std::vector<Vec2> Diamond(const Vec2& c, double half) {
  return {c + Vec2(0, -half), c + Vec2(half, 0), c + Vec2(0, half), c + Vec2(-half, 0)};
}

}  // namespace crowdsim::render
