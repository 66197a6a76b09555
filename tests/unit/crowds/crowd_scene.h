// A synthetic recorded scene for the crowds tests: four people along x, 60 s at 2.5 Hz, written
// as a scene file and imported into a track file.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "crowd_tracks/tracks.h"

namespace crowdsim::testing {

/// The scene file: person 1 walks x from -6 to 6 at y = 0 all along (frames 0..150), person 2
/// walks -x at y = 2 over frames 10..40 (4-16 s), person 3 +x at y = -2 over 70..100 (28-40 s),
/// person 4 -x at y = 3 over 80..150 (32-60 s). Frame numbers advance by 10.
inline std::string SyntheticScene() {
  std::ostringstream out;
  char line[96];
  for (int k = 0; k <= 150; ++k) {
    const auto row = [&](int person, double x, double y) {
      std::snprintf(line, sizeof(line), "%d %d %.3f %.3f\n", 10 * k, person, x, y);
      out << line;
    };
    row(1, -6.0 + 0.08 * k, 0.0);
    if (k >= 10 && k <= 40) row(2, 3.0 - 0.2 * (k - 10), 2.0);
    if (k >= 70 && k <= 100) row(3, -4.0 + 0.1 * (k - 70), -2.0);
    if (k >= 80) row(4, 5.0 - 0.1 * (k - 80), 3.0);
  }
  return out.str();
}

/// Writes the scene's track file (as `crowdsim-bench crowds import` does) into `dir`.
inline std::filesystem::path WriteSyntheticTracks(const std::filesystem::path& dir) {
  const auto scene = dir / "synthetic.txt";
  std::ofstream(scene) << SyntheticScene();
  crowd_tracks::Tracks t = crowd_tracks::ReadTracks(scene);
  t.scene = "synthetic";
  t.source = "synthetic.txt, four people of a test";
  t.cite = "none (a test)";
  const auto file = dir / "synthetic.tracks";
  std::ofstream out(file);
  crowd_tracks::WriteTracks(t, out);
  return file;
}

}  // namespace crowdsim::testing
