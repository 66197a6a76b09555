// Recorded pedestrian tracks: the ETH/UCY scene files (`frame person x y [vx vy]`) and the track
// files our importer derives from them (the same columns, frames renumbered, a citation header).
#pragma once

#include <cstdint>
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "crowdsim/geometry.h"

namespace crowdsim::crowd_tracks {

/// Seconds between annotated frames: 2.5 Hz in all six scenes (../shared/pedestrians/README.md).
inline constexpr double kFramePeriod = 0.4;

/// One person's contiguous track: positions at frames first_frame, first_frame + 1, ...
struct RecordedPerson {
  int id = 0;
  std::int64_t first_frame = 0;  ///< in frame periods from the file's first frame
  std::vector<Vec2> positions;   ///< m, one per frame
  std::int64_t last_frame() const {
    return first_frame + static_cast<std::int64_t>(positions.size()) - 1;
  }
  double first_time() const { return static_cast<double>(first_frame) * kFramePeriod; }
  double last_time() const { return static_cast<double>(last_frame()) * kFramePeriod; }
};

/// A scene's tracks and, for a derived file, its header (`# key: value` lines).
struct Tracks {
  std::string scene;                   ///< `# scene:` (derived files)
  std::string source;                  ///< `# source:` what was recorded, where
  std::string cite;                    ///< `# cite:` the paper to cite
  std::vector<RecordedPerson> people;  ///< in order of first appearance in the file
  std::int64_t frames = 0;             ///< last frame + 1
  double duration() const { return static_cast<double>(frames - 1) * kFramePeriod; }
};

/// A file that cannot be read as tracks: "FILE:LINE: what" (FILE: what for the whole file).
class TrackFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads a scene file or a derived track file. Throws TrackFileError naming the file and line: a
/// missing or empty file, a line of other than 4 or 6 columns, a value that is not a finite
/// number, a frame or id that is not whole, a person whose frames are not contiguous.
Tracks ReadTracks(const std::filesystem::path& path);

/// Writes `tracks` as a derived track file: the header, then `frame person x y` (mm) by frame.
void WriteTracks(const Tracks& tracks, std::ostream& out);

}  // namespace crowdsim::crowd_tracks
