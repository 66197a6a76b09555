#include "crowdsim/world_file.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "atomic_file.h"
#include "crowdsim/input_file.h"
#include "yaml_document.h"

namespace crowdsim {
namespace {

std::string Where(const std::string& file, const YAML::Node& n) {
  const YAML::Mark m = n.Mark();
  if (m.line < 0) return file;
  return file + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
}

[[noreturn]] void Fail(const std::string& file, const YAML::Node& n, const std::string& what) {
  throw WorldFileError(Where(file, n) + ": " + what);
}

// A scalar's text. A list or map here is our error naming file and key, not yaml-cpp's.
std::string Text(const std::string& file, const YAML::Node& n, const std::string& key) {
  if (!n.IsScalar()) Fail(file, n, "'" + key + "' must be a single text value, not a list or map");
  return n.Scalar();
}

double Number(const std::string& file, const YAML::Node& x, const std::string& key) {
  double v = 0.0;
  try {
    v = x.as<double>();
  } catch (const YAML::Exception&) {
    Fail(file, x, "'" + key + "' holds a value that is not a number");
  }
  // .inf or .nan would silently drop out of every geometric test.
  if (!std::isfinite(v))
    Fail(file, x, "'" + key + "' holds '" + x.Scalar() + "', not a finite number");
  return v;
}

std::vector<double> Numbers(const std::string& file, const YAML::Node& n, size_t count,
                            const std::string& key) {
  if (!n.IsSequence() || n.size() != count) {
    Fail(file, n, "'" + key + "' must be a list of " + std::to_string(count) + " numbers");
  }
  std::vector<double> v;
  for (const auto& x : n) v.push_back(Number(file, x, key));
  return v;
}

Rect ToRect(const std::string& file, const YAML::Node& n, const std::string& key) {
  auto v = Numbers(file, n, 4, key);
  if (!(v[0] < v[2] && v[1] < v[3])) {
    Fail(file, n, "'" + key + "' must be [xmin, ymin, xmax, ymax] with xmin < xmax, ymin < ymax");
  }
  return Rect::FromCorners(v[0], v[1], v[2], v[3]);
}

// A pair's start or goal outside the bounds or in a rectangle makes no episode: refused on reading.
void CheckPairPoint(const std::string& file, const YAML::Node& n, const std::string& key,
                    const char* what, const Vec2& p, const WorldFile& w) {
  char point[64];
  std::snprintf(point, sizeof(point), "(%.4f, %.4f)", p.x(), p.y());
  const std::string fix =
      ": every start and goal must lie in free space (fix the pair, or import "
      "the plan again with `crowdsim-bench floorplan import`)";
  if (w.bounds.Area() > 0.0 && !w.bounds.Contains(p)) {
    Fail(file, n, "'" + key + "': its " + what + " " + point + " lies outside 'bounds'" + fix);
  }
  for (std::size_t k = 0; k < w.rectangles.size(); ++k) {
    const Rect& r = w.rectangles[k];
    if (p.x() > r.min.x() && p.x() < r.max.x() && p.y() > r.min.y() && p.y() < r.max.y()) {
      Fail(file, n,
           "'" + key + "': its " + what + " " + point + " lies inside rectangles[" +
               std::to_string(k) + "]" + fix);
    }
  }
}

// The pairs of `key` (robot_pairs.train or .test), checked against bounds and rectangles.
std::vector<StartGoal> Pairs(const std::string& file, const YAML::Node& n, const std::string& key,
                             const WorldFile& w) {
  std::vector<StartGoal> out;
  if (!n) return out;
  if (!n.IsSequence()) Fail(file, n, "'" + key + "' must be a list of [sx, sy, gx, gy]");
  for (const auto& p : n) {
    auto v = Numbers(file, p, 4, key);
    const std::string item = key + "[" + std::to_string(out.size()) + "]";
    out.push_back({Vec2(v[0], v[1]), Vec2(v[2], v[3])});
    CheckPairPoint(file, p, item, "start", out.back().start, w);
    CheckPairPoint(file, p, item, "goal", out.back().goal, w);
  }
  return out;
}

// parent[key] as a whole number >= 1; `path` names it in messages.
int PositiveInt(const std::string& file, const YAML::Node& parent, const char* key,
                const std::string& path) {
  const YAML::Node n = parent[key];
  if (!n) Fail(file, parent, "missing key '" + path + "' (a whole number >= 1)");
  int v = 0;
  try {
    v = n.as<int>();
  } catch (const YAML::Exception&) {
    Fail(file, n, "'" + path + "' must be a whole number >= 1");
  }
  if (v < 1) Fail(file, n, "'" + path + "' must be a whole number >= 1, got " + std::to_string(v));
  return v;
}

// Largest mask: 10,000 x 10,000 cells (a 500 m building at 5 cm); more is a typo.
constexpr long kMaxMaskCells = 100'000'000;

// One run-length row (world_file.h): appends its `width` cells to `cells`.
void ParseMaskRow(const std::string& file, const YAML::Node& n, int row, int width,
                  std::vector<unsigned char>* cells) {
  const std::string key = "mask.rows[" + std::to_string(row) + "]";
  std::string text;
  try {
    text = n.as<std::string>();
  } catch (const YAML::Exception&) {
    Fail(file, n, "'" + key + "' must be a string of run lengths, e.g. \"5 12 3 7\"");
  }
  // Whole numbers separated by single spaces, nothing else.
  bool well_formed = !text.empty() && text.front() != ' ' && text.back() != ' ';
  for (size_t i = 0; well_formed && i < text.size(); ++i) {
    const bool digit = text[i] >= '0' && text[i] <= '9';
    well_formed = digit || (text[i] == ' ' && text[i - 1] != ' ');
  }
  if (!well_formed) {
    Fail(file, n,
         "'" + key +
             "' must be whole numbers separated by single spaces (run lengths "
             "alternating blocked, navigable, ...), got \"" +
             text + "\"");
  }
  long sum = 0;
  int runs = 0;
  for (size_t i = 0; i < text.size(); ++i, ++runs) {
    long run = 0;
    for (; i < text.size() && text[i] != ' '; ++i) {
      run = std::min<long>(10 * run + (text[i] - '0'), long(width) + 1);  // no overflow
    }
    if (run == 0 && runs > 0) {
      Fail(file, n,
           "'" + key + "': run " + std::to_string(runs + 1) +
               " is 0 (only the first run, blocked, may be 0)");
    }
    sum += run;
    if (sum > width) break;
    cells->insert(cells->end(), static_cast<size_t>(run), runs % 2 == 0 ? 0 : 1);
  }
  if (sum != width) {
    Fail(file, n,
         "'" + key + "': the runs add up to " +
             (sum > width ? "more than" : std::to_string(sum) + " cells, not") +
             " the mask width " + std::to_string(width));
  }
}

std::shared_ptr<const NavigableMask> ParseMask(const std::string& file, const YAML::Node& n) {
  if (!n.IsMap()) {
    Fail(file, n, "'mask' must be a map with resolution, origin, width, height, rows");
  }
  for (const auto& kv : n) {
    const std::string key = Text(file, kv.first, "mask key");
    if (key != "resolution" && key != "origin" && key != "width" && key != "height" &&
        key != "rows") {
      Fail(file, kv.first,
           "unknown key 'mask." + key + "' (valid: resolution, origin, width, height, rows)");
    }
  }
  auto m = std::make_shared<NavigableMask>();
  const YAML::Node res = n["resolution"];
  if (!res) Fail(file, n, "missing key 'mask.resolution' (m per cell)");
  try {
    m->resolution = res.as<double>();
  } catch (const YAML::Exception&) {
    m->resolution = 0.0;
  }
  if (!(m->resolution > 0.0)) {
    Fail(file, res, "'mask.resolution' must be a number > 0 (m per cell)");
  }
  if (!n["origin"]) Fail(file, n, "missing key 'mask.origin' ([x, y] of the lower-left corner)");
  const auto origin = Numbers(file, n["origin"], 2, "mask.origin");
  m->origin = Vec2(origin[0], origin[1]);
  m->width = PositiveInt(file, n, "width", "mask.width");
  m->height = PositiveInt(file, n, "height", "mask.height");
  if (static_cast<long>(m->width) * m->height > kMaxMaskCells) {
    Fail(file, n,
         "'mask' of " + std::to_string(m->width) + " x " + std::to_string(m->height) +
             " cells is larger than " + std::to_string(kMaxMaskCells) +
             " cells; check mask.width and mask.height (or use a coarser resolution)");
  }
  const YAML::Node rows = n["rows"];
  if (!rows || !rows.IsSequence() || rows.size() != static_cast<size_t>(m->height)) {
    Fail(file, rows ? rows : n,
         "'mask.rows' must be a list of " + std::to_string(m->height) +
             " run-length strings (one per row, mask.height)" +
             (rows && rows.IsSequence() ? ", got " + std::to_string(rows.size()) : std::string()));
  }
  std::vector<unsigned char> cells;
  cells.reserve(static_cast<size_t>(m->width) * m->height);
  for (int r = 0; r < m->height; ++r) ParseMaskRow(file, rows[r], r, m->width, &cells);
  m->cells = std::move(cells);
  return m;
}

WorldFile ParseWorld(const std::string& file, const YAML::Node& root) {
  if (!root.IsMap()) Fail(file, root, "a world must be a map with bounds and rectangles");
  static const char* kKeys[] = {"format",      "name",        "attribution", "bounds", "rectangles",
                                "robot_pairs", "free_points", "stats",       "mask"};
  for (const auto& kv : root) {
    const std::string key = Text(file, kv.first, "key");
    bool known = false;
    for (const char* k : kKeys) known = known || key == k;
    if (!known) {
      Fail(file, kv.first,
           "unknown key '" + key +
               "' (valid: format, name, attribution, bounds, "
               "rectangles, robot_pairs, free_points, stats, mask)");
    }
  }
  WorldFile w;
  if (root["name"]) w.name = Text(file, root["name"], "name");
  if (root["attribution"]) w.attribution = Text(file, root["attribution"], "attribution");
  if (!root["bounds"]) Fail(file, root, "missing key 'bounds' ([xmin, ymin, xmax, ymax])");
  w.bounds = ToRect(file, root["bounds"], "bounds");
  if (const auto rects = root["rectangles"]) {
    if (!rects.IsSequence()) Fail(file, rects, "'rectangles' must be a list");
    for (const auto& r : rects) w.rectangles.push_back(ToRect(file, r, "rectangles"));
  }
  if (const auto pairs = root["robot_pairs"]) {
    if (!pairs.IsMap())
      Fail(file, pairs, "'robot_pairs' must be a map {train: [...], test: [...]}");
    w.train_pairs = Pairs(file, pairs["train"], "robot_pairs.train", w);
    w.test_pairs = Pairs(file, pairs["test"], "robot_pairs.test", w);
  }
  if (const auto pts = root["free_points"]) {
    if (!pts.IsSequence()) Fail(file, pts, "'free_points' must be a list of [x, y]");
    for (const auto& p : pts) {
      auto v = Numbers(file, p, 2, "free_points");
      w.free_points.emplace_back(v[0], v[1]);
    }
  }
  if (const auto stats = root["stats"]) {
    if (!stats.IsMap()) Fail(file, stats, "'stats' must be a map of names to numbers");
    for (const auto& kv : stats) {
      const std::string key = Text(file, kv.first, "stats key");
      w.stats.emplace_back(key, Number(file, kv.second, "stats." + key));
    }
  }
  if (const auto mask = root["mask"]) w.mask = ParseMask(file, mask);
  return w;
}

// Refuses a floor-plan image (PNG, PGM) given as a world file, saying how to import it.
void RefuseImage(const std::filesystem::path& path) {
  if (!NotARegularFile(path).empty()) return;  // the loader says what it is, unopened
  std::ifstream in(path, std::ios::binary);
  char head[8] = {};
  in.read(head, sizeof(head));
  const std::string start(head, static_cast<std::size_t>(in.gcount()));
  const bool png = start.starts_with("\x89PNG");
  const bool pgm = start.size() >= 3 && start[0] == 'P' && (start[1] == '2' || start[1] == '5') &&
                   std::isspace(static_cast<unsigned char>(start[2]));
  if (!png && !pgm) return;
  throw WorldFileError(path.string() + ": is a " + (png ? "PNG" : "PGM") +
                       " image, not a world file: import the floor plan first (`crowdsim-bench "
                       "floorplan import " +
                       path.string() +
                       " --resolution M_PER_PX --out WORLD.yaml`) and give WORLD.yaml");
}

YAML::Node LoadYaml(const std::filesystem::path& path) {
  RefuseImage(path);
  std::vector<yaml::Problem> problems;
  YAML::Node root = yaml::LoadDocument(path, "world file", &problems);
  if (!problems.empty()) throw WorldFileError(problems.front().Format());
  return root;
}

std::string Num(double x) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.4f", x);
  std::string s(buf);
  if (s == "-0.0000") s = "0.0000";
  return s;
}

std::string Quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// The mask section (world_file.h): one run-length string per row, top row first.
void EmitMask(const NavigableMask& m, const std::string& world, const std::string& indent,
              std::ostream& os) {
  if (m.width < 1 || m.height < 1 || m.cells.size() != static_cast<size_t>(m.width) * m.height) {
    throw WorldFileError("world '" + world + "': mask of " + std::to_string(m.width) + " x " +
                         std::to_string(m.height) + " cells holds " +
                         std::to_string(m.cells.size()) + " values");
  }
  os << indent << "mask:\n";
  os << indent << "  resolution: " << Num(m.resolution) << "\n";
  os << indent << "  origin: [" << Num(m.origin.x()) << ", " << Num(m.origin.y()) << "]\n";
  os << indent << "  width: " << m.width << "\n";
  os << indent << "  height: " << m.height << "\n";
  os << indent << "  rows:\n";
  for (int r = 0; r < m.height; ++r) {
    os << indent << "    - \"";
    bool navigable = false;  // the first run counts blocked cells
    int run = 0;
    for (int c = 0; c < m.width; ++c) {
      if (m.Navigable(r, c) == navigable) {
        ++run;
        continue;
      }
      os << run << ' ';
      navigable = !navigable;
      run = 1;
    }
    os << run << "\"\n";
  }
}

void Emit(const WorldFile& w, const std::string& indent, bool first_dash, std::ostream& os) {
  // first line may carry the list dash of a world set
  std::string lead = first_dash ? indent.substr(0, indent.size() - 2) + "- " : indent;
  os << lead << "name: " << Quote(w.name) << "\n";
  if (!w.attribution.empty()) os << indent << "attribution: " << Quote(w.attribution) << "\n";
  os << indent << "bounds: [" << Num(w.bounds.min.x()) << ", " << Num(w.bounds.min.y()) << ", "
     << Num(w.bounds.max.x()) << ", " << Num(w.bounds.max.y()) << "]\n";
  os << indent << "rectangles:" << (w.rectangles.empty() ? " []" : "") << "\n";
  for (const auto& r : w.rectangles) {
    os << indent << "  - [" << Num(r.min.x()) << ", " << Num(r.min.y()) << ", " << Num(r.max.x())
       << ", " << Num(r.max.y()) << "]\n";
  }
  if (!w.train_pairs.empty() || !w.test_pairs.empty()) {
    os << indent << "robot_pairs:\n";
    for (const auto& [key, pairs] :
         {std::pair{"train", &w.train_pairs}, std::pair{"test", &w.test_pairs}}) {
      os << indent << "  " << key << ":" << (pairs->empty() ? " []" : "") << "\n";
      for (const auto& p : *pairs) {
        os << indent << "    - [" << Num(p.start.x()) << ", " << Num(p.start.y()) << ", "
           << Num(p.goal.x()) << ", " << Num(p.goal.y()) << "]\n";
      }
    }
  }
  if (!w.free_points.empty()) {
    os << indent << "free_points:\n";
    for (const auto& p : w.free_points) {
      os << indent << "  - [" << Num(p.x()) << ", " << Num(p.y()) << "]\n";
    }
  }
  if (!w.stats.empty()) {
    os << indent << "stats:\n";
    for (const auto& [k, v] : w.stats) os << indent << "  " << k << ": " << Num(v) << "\n";
  }
  if (w.mask) EmitMask(*w.mask, w.name, indent, os);
}

void WriteText(const std::string& text, const std::filesystem::path& path) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  try {
    common::WriteFileAtomically(path, text);
  } catch (const std::runtime_error& e) {
    throw WorldFileError(std::string(e.what()) + " (check the folder exists and is writable)");
  }
}

}  // namespace

StaticMap WorldFile::ToStaticMap() const {
  StaticMap m;
  m.name = name;
  m.bounds = bounds;
  m.rectangles = rectangles;
  m.attribution = attribution;
  m.mask = mask;
  return m;
}

WorldFile ReadWorldFile(const std::filesystem::path& path) {
  const std::string file = path.string();
  YAML::Node root = LoadYaml(path);
  if (!root.IsMap()) Fail(file, root, "a world must be a map with bounds and rectangles");
  if (root["format"] && Text(file, root["format"], "format") != "crowdsim-world/1") {
    Fail(file, root["format"],
         "unsupported format '" + root["format"].Scalar() + "' (expected crowdsim-world/1)");
  }
  return ParseWorld(file, root);
}

std::vector<WorldFile> ReadWorldSet(const std::filesystem::path& path) {
  const std::string file = path.string();
  YAML::Node root = LoadYaml(path);
  if (!root.IsMap() || !root["worlds"] || !root["worlds"].IsSequence()) {
    Fail(file, root, "a world set needs 'format: crowdsim-world-set/1' and a 'worlds' list");
  }
  std::vector<WorldFile> out;
  for (const auto& w : root["worlds"]) out.push_back(ParseWorld(file, w));
  return out;
}

void WriteWorldFile(const WorldFile& world, const std::filesystem::path& path) {
  std::ostringstream os;
  os << "format: crowdsim-world/1\n";
  Emit(world, "", false, os);
  WriteText(os.str(), path);
}

void WriteWorldSet(const std::vector<WorldFile>& worlds, const std::string& comment,
                   const std::filesystem::path& path) {
  std::ostringstream os;
  std::istringstream lines(comment);
  for (std::string line; std::getline(lines, line);) os << "# " << line << "\n";
  os << "format: crowdsim-world-set/1\nworlds:\n";
  for (const auto& w : worlds) Emit(w, "    ", true, os);
  WriteText(os.str(), path);
}

}  // namespace crowdsim
