#include "crowdsim/bench/episode_log.h"

#include <zlib.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "atomic_file.h"
#include "crowdsim/bench/social_metrics.h"

namespace crowdsim {

namespace {

using Json = nlohmann::ordered_json;  // keys in the order written: format first
namespace fs = std::filesystem;

constexpr const char* kFormat = "crowdsim-episode-log";
constexpr EpisodeStatus kEnds[] = {
    EpisodeStatus::kSuccess,      EpisodeStatus::kCollisionHuman, EpisodeStatus::kCollisionObstacle,
    EpisodeStatus::kTimeout,      EpisodeStatus::kPolicyError,    EpisodeStatus::kPolicyCrash,
    EpisodeStatus::kPolicyTimeout};

Json RectJson(const Rect& r) { return Json::array({r.min.x(), r.min.y(), r.max.x(), r.max.y()}); }

Json StateJson(const EpisodeFrame& f) {
  const AgentState& r = f.robot;
  Json people = Json::array();
  for (size_t i = 0; i < f.humans.size(); ++i) {
    if (!f.Present(i)) continue;  // a recorded person before or after its track
    const AgentState& h = f.humans[i];
    people.push_back({{"id", i},
                      {"x", h.position.x()},
                      {"y", h.position.y()},
                      {"vx", h.velocity.x()},
                      {"vy", h.velocity.y()},
                      {"radius", h.radius}});
    if (h.group >= 0) people.back()["group"] = h.group;  // absent: walks alone
  }
  return {{"t", f.time},
          {"robot",
           {{"x", r.position.x()},
            {"y", r.position.y()},
            {"vx", r.velocity.x()},
            {"vy", r.velocity.y()},
            {"heading", r.heading},
            {"radius", r.radius},
            {"goal", Json::array({r.goal.x(), r.goal.y()})}}},
          {"people", std::move(people)}};
}

std::string Gzip(const std::string& text) {
  z_stream z{};
  // 15 + 16: a gzip wrapper, so `zcat` and Python's gzip read the file.
  if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("zlib cannot start compressing");
  std::string out(deflateBound(&z, static_cast<uLong>(text.size())), '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  z.avail_in = static_cast<uInt>(text.size());
  z.next_out = reinterpret_cast<Bytef*>(out.data());
  z.avail_out = static_cast<uInt>(out.size());
  const int rc = deflate(&z, Z_FINISH);
  out.resize(z.total_out);
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw std::runtime_error("zlib could not compress an episode log");
  return out;
}

// The file's text: gunzipped when it starts with gzip's magic bytes, else as it is.
std::string ReadText(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error("cannot open the episode log " + path.string());
  std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  if (bytes.size() < 2 || static_cast<unsigned char>(bytes[0]) != 0x1f ||
      static_cast<unsigned char>(bytes[1]) != 0x8b)
    return bytes;
  z_stream z{};
  if (inflateInit2(&z, 15 + 16) != Z_OK) throw std::runtime_error("zlib cannot start reading");
  z.next_in = reinterpret_cast<Bytef*>(bytes.data());
  z.avail_in = static_cast<uInt>(bytes.size());
  std::string out;
  char buf[1 << 16];
  int rc = Z_OK;
  while (rc == Z_OK) {
    z.next_out = reinterpret_cast<Bytef*>(buf);
    z.avail_out = sizeof(buf);
    rc = inflate(&z, Z_NO_FLUSH);
    out.append(buf, sizeof(buf) - z.avail_out);
  }
  inflateEnd(&z);
  if (rc != Z_STREAM_END)
    throw std::runtime_error(path.string() + ": the gzip data is damaged or cut short");
  return out;
}

// Reads the fields of one line, each error naming file:line and the field.
class LineReader {
 public:
  LineReader(const fs::path& path, int line, const Json& j) : path_(path), line_(line), j_(j) {}

  [[noreturn]] void Fail(const std::string& field, const std::string& what) const {
    throw std::runtime_error(path_.string() + ":" + std::to_string(line_) + ": " +
                             (field.empty() ? "" : "'" + field + "' ") + what);
  }
  const Json& Field(const Json& obj, const std::string& key, const std::string& where) const {
    if (!obj.is_object() || !obj.contains(key)) Fail(where + key, "is missing");
    return obj[key];
  }
  double Number(const Json& obj, const std::string& key, const std::string& where = "") const {
    const Json& v = Field(obj, key, where);
    if (!v.is_number() || !std::isfinite(v.get<double>())) Fail(where + key, "is not a number");
    return v.get<double>();
  }
  Vec2 Pair(const Json& v, const std::string& field) const {
    if (!v.is_array() || v.size() != 2 || !v[0].is_number() || !v[1].is_number())
      Fail(field, "is not [x, y]");
    return Vec2(v[0].get<double>(), v[1].get<double>());
  }
  Rect RectOf(const Json& v, const std::string& field) const {
    if (!v.is_array() || v.size() != 4) Fail(field, "is not [x_min, y_min, x_max, y_max]");
    for (const Json& x : v) {
      if (!x.is_number()) Fail(field, "is not [x_min, y_min, x_max, y_max]");
    }
    return Rect::FromCorners(v[0], v[1], v[2], v[3]);
  }
  const Json& j() const { return j_; }

 private:
  const fs::path& path_;
  int line_;
  const Json& j_;
};

void ReadHeader(const LineReader& in, EpisodeLog* log) {
  const Json& j = in.j();
  if (!j.is_object() || j.value("format", "") != kFormat)
    in.Fail("format", std::string("is not '") + kFormat + "': this is no episode log");
  const Json& version = in.Field(j, "version", "");
  if (!version.is_number_integer()) in.Fail("version", "is not a whole number");
  if (version.get<int>() > kEpisodeLogVersion)
    in.Fail("version", "is " + std::to_string(version.get<int>()) + ", newer than this build's " +
                           std::to_string(kEpisodeLogVersion) + ": update crowdsim-bench");
  const Json& units = in.Field(j, "units", "");
  for (const auto& [key, unit] : {std::pair{"length", "m"}, {"time", "s"}, {"angle", "rad"}}) {
    const Json& u = in.Field(units, key, "units.");
    if (!u.is_string() || u.get<std::string>() != unit)
      in.Fail(std::string("units.") + key,
              "is " + u.dump() + ", not '" + unit + "': convert the log to " + unit);
  }
  log->source = j.value("source", "");
  log->dt = in.Number(j, "dt");
  if (log->dt <= 0) in.Fail("dt", "must be > 0");
  const Json& robot = in.Field(j, "robot", "");
  const Json& holonomic = in.Field(robot, "holonomic", "robot.");
  if (!holonomic.is_boolean()) in.Fail("robot.holonomic", "is not true or false");
  log->holonomic = holonomic.get<bool>();
  log->goal_radius = in.Number(robot, "goal_radius", "robot.");
  const Json& map = in.Field(j, "map", "");
  log->map.bounds = in.RectOf(in.Field(map, "bounds", "map."), "map.bounds");
  const Json& rects = in.Field(map, "rectangles", "map.");
  if (!rects.is_array()) in.Fail("map.rectangles", "is not a list");
  for (size_t i = 0; i < rects.size(); ++i)
    log->map.rectangles.push_back(in.RectOf(rects[i], "map.rectangles[" + std::to_string(i) + "]"));
}

EpisodeFrame ReadState(const LineReader& in) {
  const Json& j = in.j();
  EpisodeFrame f;
  f.time = in.Number(j, "t");
  const Json& r = in.Field(j, "robot", "");
  f.robot.position = Vec2(in.Number(r, "x", "robot."), in.Number(r, "y", "robot."));
  f.robot.velocity = Vec2(in.Number(r, "vx", "robot."), in.Number(r, "vy", "robot."));
  f.robot.heading = in.Number(r, "heading", "robot.");
  f.robot.radius = in.Number(r, "radius", "robot.");
  f.robot.goal = in.Pair(in.Field(r, "goal", "robot."), "robot.goal");
  const Json& people = in.Field(j, "people", "");
  if (!people.is_array()) in.Fail("people", "is not a list");
  for (size_t i = 0; i < people.size(); ++i) {
    const std::string at = "people[" + std::to_string(i) + "].";
    AgentState h;
    h.position = Vec2(in.Number(people[i], "x", at), in.Number(people[i], "y", at));
    h.velocity = Vec2(in.Number(people[i], "vx", at), in.Number(people[i], "vy", at));
    h.radius = in.Number(people[i], "radius", at);
    if (people[i].is_object() && people[i].contains("group")) {
      const double group = in.Number(people[i], "group", at);
      if (!(group >= 0.0) || group != std::floor(group) || group > 1e9)
        in.Fail(at + "group", "is not a whole number >= 0 (leave it out for a person alone)");
      h.group = static_cast<int>(group);
    }
    f.humans.push_back(h);
  }
  return f;
}

}  // namespace

void WriteEpisodeLog(const fs::path& path, const EpisodeLog& log) {
  Json rects = Json::array();
  for (const Rect& r : log.map.rectangles) rects.push_back(RectJson(r));
  const Json header = {{"format", kFormat},
                       {"version", kEpisodeLogVersion},
                       {"units", {{"length", "m"}, {"time", "s"}, {"angle", "rad"}}},
                       {"source", log.source},
                       {"dt", log.dt},
                       {"robot", {{"holonomic", log.holonomic}, {"goal_radius", log.goal_radius}}},
                       {"map", {{"bounds", RectJson(log.map.bounds)}, {"rectangles", rects}}}};
  std::string text = header.dump() + "\n";
  for (const EpisodeFrame& f : log.frames) text += StateJson(f).dump() + "\n";
  if (log.status) text += Json{{"outcome", EpisodeStatusName(*log.status)}}.dump() + "\n";
  common::WriteFileAtomically(path, Gzip(text));
}

EpisodeLog ReadEpisodeLog(const fs::path& path) {
  std::istringstream text(ReadText(path));
  EpisodeLog log;
  std::string line;
  int number = 0;
  while (std::getline(text, line)) {
    ++number;
    if (line.empty()) continue;
    if (log.status) {
      throw std::runtime_error(path.string() + ":" + std::to_string(number) +
                               ": a line after the outcome line");
    }
    const Json j = Json::parse(line, nullptr, false);
    const LineReader in(path, number, j);
    if (j.is_discarded() || !j.is_object()) in.Fail("", "is not a JSON object");
    if (number == 1) {
      ReadHeader(in, &log);
    } else if (j.contains("outcome")) {
      const std::string name = j["outcome"].is_string() ? j["outcome"].get<std::string>() : "";
      for (EpisodeStatus s : kEnds) {
        if (name == EpisodeStatusName(s)) log.status = s;
      }
      if (!log.status) in.Fail("outcome", "is not an end status (success, timeout, ...)");
    } else {
      EpisodeFrame f = ReadState(in);
      // States come every dt from time 0: a gap or a step back is a damaged or foreign log.
      const double expected = static_cast<double>(log.frames.size()) * log.dt;
      if (std::abs(f.time - expected) > 1e-6 * std::max(1.0, expected))
        in.Fail("t", "is " + std::to_string(f.time) + ", expected " + std::to_string(expected) +
                         " (states every dt = " + std::to_string(log.dt) + " s from 0)");
      log.frames.push_back(std::move(f));
    }
  }
  if (number == 0) throw std::runtime_error(path.string() + ": the episode log is empty");
  if (log.frames.empty())
    throw std::runtime_error(path.string() + ": the episode log has no state lines");
  if (!log.status) {
    throw std::runtime_error(path.string() +
                             ": no outcome line: the log is cut short, and a partial episode is "
                             "not scored as a complete one");
  }
  return log;
}

SocialMetrics ScoreEpisodeLog(const EpisodeLog& log) {
  SocialMetricsAccumulator social(log.dt, log.holonomic, log.goal_radius);
  for (const EpisodeFrame& f : log.frames) social.Observe(f.robot, f.humans);
  return social.Finish(log.status == EpisodeStatus::kSuccess,
                       ShortestFreePath(log.map, log.frames.front().robot));
}

}  // namespace crowdsim
