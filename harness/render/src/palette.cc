#include "crowdsim/render/palette.h"

#include <cstring>

namespace crowdsim::render::palette {

Color Human(int i) {
  // Hues that stay apart from the blue and orange robots and from the grey obstacles.
  static constexpr Color kHumans[] = {
      {44, 160, 44, 1.0},   {214, 39, 40, 1.0},  {148, 103, 189, 1.0}, {140, 86, 75, 1.0},
      {227, 119, 194, 1.0}, {188, 189, 34, 1.0}, {23, 190, 207, 1.0},  {80, 80, 160, 1.0}};
  constexpr int n = static_cast<int>(sizeof(kHumans) / sizeof(kHumans[0]));
  return kHumans[((i % n) + n) % n];
}

Color Outcome(const char* status_name) {
  if (std::strcmp(status_name, "success") == 0) return kSuccess;
  if (std::strncmp(status_name, "collision", 9) == 0) return kCollision;
  if (std::strcmp(status_name, "timeout") == 0) return kTimeout;
  return kOther;
}

}  // namespace crowdsim::render::palette
