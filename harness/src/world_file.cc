#include "crowdsim/world_file.h"

#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <fstream>
#include <sstream>

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

std::vector<double> Numbers(const std::string& file, const YAML::Node& n, size_t count,
                            const std::string& key) {
  if (!n.IsSequence() || n.size() != count) {
    Fail(file, n, "'" + key + "' must be a list of " + std::to_string(count) + " numbers");
  }
  std::vector<double> v;
  for (const auto& x : n) {
    try {
      v.push_back(x.as<double>());
    } catch (const YAML::Exception&) {
      Fail(file, x, "'" + key + "' holds a value that is not a number");
    }
  }
  return v;
}

Rect ToRect(const std::string& file, const YAML::Node& n, const std::string& key) {
  auto v = Numbers(file, n, 4, key);
  if (!(v[0] < v[2] && v[1] < v[3])) {
    Fail(file, n, "'" + key + "' must be [xmin, ymin, xmax, ymax] with xmin < xmax, ymin < ymax");
  }
  return Rect::FromCorners(v[0], v[1], v[2], v[3]);
}

std::vector<StartGoal> Pairs(const std::string& file, const YAML::Node& n, const std::string& key) {
  std::vector<StartGoal> out;
  if (!n) return out;
  if (!n.IsSequence()) Fail(file, n, "'" + key + "' must be a list of [sx, sy, gx, gy]");
  for (const auto& p : n) {
    auto v = Numbers(file, p, 4, key);
    out.push_back({Vec2(v[0], v[1]), Vec2(v[2], v[3])});
  }
  return out;
}

WorldFile ParseWorld(const std::string& file, const YAML::Node& root) {
  if (!root.IsMap()) Fail(file, root, "a world must be a map with bounds and rectangles");
  static const char* kKeys[] = {"format", "name", "attribution", "bounds", "rectangles",
                                "robot_pairs", "free_points", "stats"};
  for (const auto& kv : root) {
    const std::string key = kv.first.as<std::string>();
    bool known = false;
    for (const char* k : kKeys) known = known || key == k;
    if (!known) {
      Fail(file, kv.first, "unknown key '" + key + "' (valid: format, name, attribution, bounds, "
                           "rectangles, robot_pairs, free_points, stats)");
    }
  }
  WorldFile w;
  if (root["name"]) w.name = root["name"].as<std::string>();
  if (root["attribution"]) w.attribution = root["attribution"].as<std::string>();
  if (!root["bounds"]) Fail(file, root, "missing key 'bounds' ([xmin, ymin, xmax, ymax])");
  w.bounds = ToRect(file, root["bounds"], "bounds");
  if (const auto rects = root["rectangles"]) {
    if (!rects.IsSequence()) Fail(file, rects, "'rectangles' must be a list");
    for (const auto& r : rects) w.rectangles.push_back(ToRect(file, r, "rectangles"));
  }
  if (const auto pairs = root["robot_pairs"]) {
    w.train_pairs = Pairs(file, pairs["train"], "robot_pairs.train");
    w.test_pairs = Pairs(file, pairs["test"], "robot_pairs.test");
  }
  if (const auto pts = root["free_points"]) {
    for (const auto& p : pts) {
      auto v = Numbers(file, p, 2, "free_points");
      w.free_points.emplace_back(v[0], v[1]);
    }
  }
  if (const auto stats = root["stats"]) {
    for (const auto& kv : stats) {
      w.stats.emplace_back(kv.first.as<std::string>(), kv.second.as<double>());
    }
  }
  return w;
}

YAML::Node LoadYaml(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) {
    throw WorldFileError(path.string() + ": world file does not exist");
  }
  try {
    return YAML::LoadFile(path.string());
  } catch (const YAML::Exception& e) {
    throw WorldFileError(path.string() + ":" + std::to_string(e.mark.line + 1) + ":" +
                         std::to_string(e.mark.column + 1) + ": not valid YAML: " + e.msg);
  }
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
    for (const auto& [key, pairs] : {std::pair{"train", &w.train_pairs}, std::pair{"test", &w.test_pairs}}) {
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
}

void WriteText(const std::string& text, const std::filesystem::path& path) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  const auto tmp = path.string() + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary);
    if (!f) throw WorldFileError(path.string() + ": cannot write (check the folder exists and is writable)");
    f << text;
    if (!f) throw WorldFileError(path.string() + ": write failed");
  }
  std::filesystem::rename(tmp, path);
}

}  // namespace

StaticMap WorldFile::ToStaticMap() const {
  StaticMap m;
  m.name = name;
  m.bounds = bounds;
  m.rectangles = rectangles;
  m.attribution = attribution;
  return m;
}

WorldFile ReadWorldFile(const std::filesystem::path& path) {
  const std::string file = path.string();
  YAML::Node root = LoadYaml(path);
  if (root["format"] && root["format"].as<std::string>() != "crowdsim-world/1") {
    Fail(file, root["format"], "unsupported format '" + root["format"].as<std::string>() +
                                   "' (expected crowdsim-world/1)");
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
