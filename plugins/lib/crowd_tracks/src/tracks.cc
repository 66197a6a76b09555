#include "crowd_tracks/tracks.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <unordered_map>

namespace crowdsim::crowd_tracks {

namespace {

// One data line as read, with its line number for errors.
struct Row {
  std::int64_t frame = 0;
  int person = 0;
  Vec2 position = Vec2::Zero();
  int line = 0;
};

[[noreturn]] void Fail(const std::filesystem::path& path, int line, const std::string& what) {
  throw TrackFileError(path.string() + (line > 0 ? ":" + std::to_string(line) : "") + ": " + what);
}

// A whole finite number of column `column` (1-based), or an error naming line and column.
double Number(const std::string& token, const std::filesystem::path& path, int line, int column) {
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(token.c_str(), &end);
  if (end == token.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(v)) {
    Fail(path, line,
         "column " + std::to_string(column) + " is '" + token +
             "', not a finite number (columns: frame person x y [vx vy])");
  }
  return v;
}

std::int64_t Whole(double v, const char* what, const std::filesystem::path& path, int line) {
  if (std::abs(v - std::round(v)) > 1e-6 || std::abs(v) > 1e15) {
    Fail(path, line, std::string(what) + " " + std::to_string(v) + " is not a whole number");
  }
  return static_cast<std::int64_t>(std::llround(v));
}

// `# key: value` header lines of a derived file.
void ReadHeader(const std::string& text, Tracks* t) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) return;
  std::string key = text.substr(1, colon - 1);
  key.erase(0, key.find_first_not_of(' '));
  std::string value = text.substr(colon + 1);
  value.erase(0, value.find_first_not_of(' '));
  if (key == "scene") t->scene = value;
  if (key == "source") t->source = value;
  if (key == "cite") t->cite = value;
}

std::vector<Row> ReadRows(const std::filesystem::path& path, Tracks* t) {
  std::ifstream in(path);
  if (!in) {
    Fail(path, 0, std::filesystem::exists(path) ? "cannot be read" : "not found (no such file)");
  }
  std::vector<Row> rows;
  std::string text;
  std::vector<std::string> tokens;
  for (int line = 1; std::getline(in, text); ++line) {
    const std::size_t first = text.find_first_not_of(" \t\r");
    if (first == std::string::npos) continue;
    if (text[first] == '#') {
      ReadHeader(text.substr(first), t);
      continue;
    }
    std::istringstream fields(text);
    tokens.clear();
    for (std::string token; fields >> token;) tokens.push_back(token);
    if (tokens.size() != 4 && tokens.size() != 6) {
      Fail(path, line,
           std::to_string(tokens.size()) +
               " columns, expected 4 (frame person x y) or 6 (frame person x y vx vy)");
    }
    double v[4];
    for (int c = 0; c < 4; ++c) v[c] = Number(tokens[c], path, line, c + 1);
    for (int c = 4; c < static_cast<int>(tokens.size()); ++c) Number(tokens[c], path, line, c + 1);
    rows.push_back(Row{Whole(v[0], "frame", path, line),
                       static_cast<int>(Whole(v[1], "person id", path, line)), Vec2(v[2], v[3]),
                       line});
  }
  if (rows.empty())
    Fail(path, 0, "holds no tracks (an empty file: expected frame person x y lines)");
  return rows;
}

}  // namespace

Tracks ReadTracks(const std::filesystem::path& path) {
  Tracks t;
  const std::vector<Row> rows = ReadRows(path, &t);
  // The frame step: the smallest gap between annotated frames (6 in ETH's numbering, 10 else).
  std::vector<std::int64_t> frames;
  frames.reserve(rows.size());
  for (const Row& r : rows) frames.push_back(r.frame);
  std::sort(frames.begin(), frames.end());
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  std::int64_t step = 0;
  for (std::size_t k = 1; k < frames.size(); ++k) {
    const std::int64_t gap = frames[k] - frames[k - 1];
    if (step == 0 || gap < step) step = gap;
  }
  if (step == 0) step = 1;
  // Each annotated frame's period from the first. A gap off the grid (ETH's numbering restarts
  // its phase after two gaps nobody spans) is rounded to whole periods.
  std::vector<std::int64_t> period(frames.size(), 0);
  for (std::size_t k = 1; k < frames.size(); ++k) {
    const double gap = static_cast<double>(frames[k] - frames[k - 1]) / static_cast<double>(step);
    period[k] = period[k - 1] + std::llround(gap);
  }
  std::unordered_map<int, std::size_t> index;
  std::vector<std::int64_t> last_frame;  // per person, in the file's numbering
  for (const Row& r : rows) {
    const auto at = std::lower_bound(frames.begin(), frames.end(), r.frame) - frames.begin();
    const std::int64_t k = period[static_cast<std::size_t>(at)];
    const auto [it, added] = index.try_emplace(r.person, t.people.size());
    if (added) {
      t.people.push_back(RecordedPerson{r.person, k, {}});
      last_frame.push_back(r.frame);
    } else if (r.frame != last_frame[it->second] + step) {
      Fail(path, r.line,
           "person " + std::to_string(r.person) + " jumps from frame " +
               std::to_string(last_frame[it->second]) + " to " + std::to_string(r.frame) +
               " (frames advance by " + std::to_string(step) +
               "): a person's frames must be contiguous");
    }
    last_frame[it->second] = r.frame;
    t.people[it->second].positions.push_back(r.position);
    t.frames = std::max(t.frames, k + 1);
  }
  return t;
}

void WriteTracks(const Tracks& tracks, std::ostream& out) {
  out << "# scene: " << tracks.scene << "\n# source: " << tracks.source
      << "\n# cite: " << tracks.cite
      << "\n# columns: frame person x y; frame counts 0.4 s periods from the recording's first "
         "frame, x and y in m (written by `crowdsim-bench crowds import`, tools/crowds)\n";
  struct Line {
    std::int64_t frame;
    std::size_t person;
    std::size_t k;
  };
  std::vector<Line> lines;
  for (std::size_t p = 0; p < tracks.people.size(); ++p) {
    for (std::size_t k = 0; k < tracks.people[p].positions.size(); ++k) {
      lines.push_back(Line{tracks.people[p].first_frame + static_cast<std::int64_t>(k), p, k});
    }
  }
  std::stable_sort(lines.begin(), lines.end(),
                   [](const Line& a, const Line& b) { return a.frame < b.frame; });
  char buf[96];
  for (const Line& l : lines) {
    const RecordedPerson& p = tracks.people[l.person];
    const Vec2& x = p.positions[l.k];
    // Millimetres: far below the recordings' accuracy; "+ 0.0" writes -0 as 0.
    std::snprintf(buf, sizeof(buf), "%lld %d %.3f %.3f\n", static_cast<long long>(l.frame), p.id,
                  std::round(x.x() * 1000.0) / 1000.0 + 0.0,
                  std::round(x.y() * 1000.0) / 1000.0 + 0.0);
    out << buf;
  }
}

}  // namespace crowdsim::crowd_tracks
