#include "crowdsim/results.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <functional>
#include <iomanip>
#include <sstream>

#include "crowdsim/csv.h"
#include "crowdsim/version.h"

namespace crowdsim {
namespace fs = std::filesystem;

namespace {

std::string Fixed(double x, int digits) {
  if (!std::isfinite(x)) return "";
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%.*f", digits, x);
  return buf;
}

EpisodeStatus ParseStatus(const std::string& s) {
  for (auto st : {EpisodeStatus::kSuccess, EpisodeStatus::kCollisionHuman,
                  EpisodeStatus::kCollisionObstacle, EpisodeStatus::kTimeout,
                  EpisodeStatus::kPolicyError}) {
    if (s == EpisodeStatusName(st)) return st;
  }
  return EpisodeStatus::kRunning;
}

std::string JsonString(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof(buf), "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  return out + "\"";
}

/// Strict JSON number: non-finite values become null.
std::string JsonNumber(double x) {
  if (!std::isfinite(x)) return "null";
  std::ostringstream os;
  os << std::setprecision(10) << x;
  return os.str();
}

std::string JsonParam(const ParamValue& v) {
  return std::visit(
      [](const auto& x) -> std::string {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, bool>) {
          return x ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::int64_t>) {
          return std::to_string(x);
        } else if constexpr (std::is_same_v<T, double>) {
          return JsonNumber(x);
        } else if constexpr (std::is_same_v<T, std::string>) {
          return JsonString(x);
        } else {
          std::string s = "[";
          for (size_t i = 0; i < x.size(); ++i) s += (i ? ", " : "") + JsonNumber(x[i]);
          return s + "]";
        }
      },
      v);
}

std::string JsonPlugin(const PluginUse& u) {
  std::string s = "{\"plugin\": " + JsonString(u.loaded ? u.loaded->descriptor->name : u.plugin);
  if (u.loaded) s += ", \"file\": " + JsonString(u.loaded->path.string());
  s += ", \"params\": {";
  bool first = true;
  for (const auto& [k, v] : u.params.values()) {
    s += (first ? "" : ", ") + JsonString(k) + ": " + JsonParam(v);
    first = false;
  }
  return s + "}}";
}

std::string SensorsLabel(const RowSpec& row) {
  std::string s;
  for (size_t i = 0; i < row.sensors.size(); ++i) s += (i ? "+" : "") + row.sensors[i].plugin;
  return s.empty() ? "-" : s;
}

struct Column {
  std::string header;
  std::function<std::string(const TableRow&)> value;
};

std::vector<Column> Columns(const Suite& suite) {
  std::vector<Column> cols;
  cols.push_back({"row", nullptr});
  cols.push_back({"label", [](const TableRow& r) { return r.spec->label; }});
  for (const auto& name : suite.info_columns) {
    cols.push_back({name, [name](const TableRow& r) {
                      for (const auto& [k, v] : r.spec->info) {
                        if (k == name) return v;
                      }
                      return std::string("");
                    }});
  }
  cols.push_back({"sensors", [](const TableRow& r) { return SensorsLabel(*r.spec); }});
  auto metric = [](const char* h, double RowMetrics::*field, int digits) {
    return Column{h, [field, digits](const TableRow& r) { return Fixed(r.metrics.*field, digits); }};
  };
  cols.push_back(metric("success rate", &RowMetrics::success_rate, 4));
  cols.push_back(metric("collision rate", &RowMetrics::collision_rate, 4));
  cols.push_back(metric("timeout rate", &RowMetrics::timeout_rate, 4));
  cols.push_back(metric("nav. time", &RowMetrics::nav_time, 4));
  cols.push_back(metric("danger freq.", &RowMetrics::danger_frequency, 4));
  cols.push_back(metric("coll. human", &RowMetrics::collision_human_rate, 4));
  cols.push_back(metric("coll. obstacle", &RowMetrics::collision_obstacle_rate, 4));
  cols.push_back(metric("path length", &RowMetrics::path_length, 3));
  cols.push_back(metric("min. dist.", &RowMetrics::min_human_distance, 3));
  cols.push_back(metric("return", &RowMetrics::discounted_return, 4));
  cols.push_back(metric("decision µs", &RowMetrics::decision_time_us, 1));
  cols.push_back({"errors", [](const TableRow& r) { return Fixed(r.metrics.policy_error_rate, 4); }});
  cols.push_back({"episodes", [](const TableRow& r) { return std::to_string(r.metrics.episodes); }});
  return cols;
}

}  // namespace

std::string EpisodeCsvHeader() {
  return "row,episode,seed,layout,status,time,steps,danger_steps,path_length,"
         "min_human_distance,discounted_return,decision_time_us,humans_at_goal,error";
}

std::string FormatEpisodeLine(const EpisodeLine& e) {
  std::ostringstream os;
  const auto& r = e.record;
  os << CsvField(e.row) << "," << e.episode << "," << e.seed << "," << CsvField(e.layout) << ","
     << EpisodeStatusName(r.status) << "," << Fixed(r.time, 2) << "," << r.steps << ","
     << r.danger_steps << "," << Fixed(r.path_length, 6) << ","
     << Fixed(r.min_human_distance, 6) << "," << Fixed(r.discounted_return, 8) << ","
     << Fixed(r.decision_time_us, 3) << "," << e.humans_at_goal << "," << CsvField(e.error);
  return os.str();
}

std::vector<EpisodeLine> ReadEpisodesCsv(const fs::path& path) {
  std::vector<EpisodeLine> out;
  std::ifstream f(path);
  if (!f) return out;
  std::string line;
  std::getline(f, line);  // header
  while (std::getline(f, line)) {
    if (line.empty() || f.eof()) {
      // A last line without its newline may be cut short by a crash: skip it.
      if (f.eof() && !line.empty()) break;
      continue;
    }
    auto v = SplitCsvLine(line);
    if (v.size() != 14) continue;
    try {
      EpisodeLine e;
      e.row = v[0];
      e.episode = std::stoi(v[1]);
      e.seed = std::stoull(v[2]);
      e.layout = v[3];
      e.record.status = ParseStatus(v[4]);
      if (e.record.status == EpisodeStatus::kRunning) continue;
      e.record.time = std::stod(v[5]);
      e.record.steps = std::stoi(v[6]);
      e.record.danger_steps = std::stoi(v[7]);
      e.record.path_length = std::stod(v[8]);
      e.record.min_human_distance = v[9].empty() ? kInfinity : std::stod(v[9]);
      e.record.discounted_return = std::stod(v[10]);
      e.record.decision_time_us = std::stod(v[11]);
      e.humans_at_goal = std::stoi(v[12]);
      e.error = v[13];
      out.push_back(std::move(e));
    } catch (const std::exception&) {
      continue;  // damaged line: the episode simply runs again
    }
  }
  return out;
}

namespace {

/// A table cell's text for Markdown: '|' escaped (it would start a new cell), line breaks as spaces.
std::string MarkdownCell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c == '\n' || c == '\r' ? ' ' : c;
  }
  return out;
}

}  // namespace

std::string FormatTableMarkdown(const Suite& suite, const std::vector<TableRow>& rows) {
  const auto cols = Columns(suite);
  std::ostringstream os;
  os << "| ";
  for (const auto& c : cols) os << MarkdownCell(c.header) << " | ";
  os << "\n|";
  for (size_t i = 0; i < cols.size(); ++i) os << (i < 2 + suite.info_columns.size() + 1 ? "---|" : "---:|");
  os << "\n";
  for (size_t r = 0; r < rows.size(); ++r) {
    os << "| ";
    for (const auto& c : cols) os << MarkdownCell(c.value ? c.value(rows[r]) : std::to_string(r + 1)) << " | ";
    os << "\n";
  }
  return os.str();
}

std::string FormatTableCsv(const Suite& suite, const std::vector<TableRow>& rows) {
  const auto cols = Columns(suite);
  std::ostringstream os;
  for (size_t i = 0; i < cols.size(); ++i) os << (i ? "," : "") << CsvField(cols[i].header);
  os << "\n";
  for (size_t r = 0; r < rows.size(); ++r) {
    for (size_t i = 0; i < cols.size(); ++i) {
      os << (i ? "," : "") << CsvField(cols[i].value ? cols[i].value(rows[r]) : std::to_string(r + 1));
    }
    os << "\n";
  }
  return os.str();
}

std::string FormatManifestJson(const Suite& suite, const std::vector<TableRow>& rows,
                               const RunFacts& facts) {
  std::ostringstream os;
  os << "{\n";
  os << "  \"format\": \"crowdsim-results/1\",\n";
  os << "  \"suite\": " << JsonString(suite.name) << ",\n";
  os << "  \"suite_file\": " << JsonString(suite.file.string()) << ",\n";
  os << "  \"description\": " << JsonString(suite.description) << ",\n";
  os << "  \"crowdsim_version\": " << JsonString(Version()) << ",\n";
  os << "  \"git_commit\": " << JsonString(GitCommit()) << ",\n";
  os << "  \"compiler\": " << JsonString(std::string(__VERSION__)) << ",\n";
  os << "  \"config_hash\": " << JsonString(suite.ConfigHash()) << ",\n";
  os << "  \"seed\": " << suite.seed << ",\n";
  os << "  \"episodes\": " << facts.episodes << ",\n";
  if (!facts.shard.empty()) os << "  \"shard\": " << JsonString(facts.shard) << ",\n";
  os << "  \"jobs\": " << facts.jobs << ",\n";
  os << "  \"started_utc\": " << JsonString(facts.started_utc) << ",\n";
  os << "  \"finished_utc\": " << JsonString(facts.finished_utc) << ",\n";
  os << "  \"wall_seconds\": " << JsonNumber(facts.wall_seconds) << ",\n";
  const SimConfig& s = suite.sim;
  os << "  \"sim\": {\"time_step\": " << JsonNumber(s.time_step)
     << ", \"time_limit\": " << JsonNumber(s.time_limit)
     << ", \"goal_radius\": " << JsonNumber(s.goal_radius)
     << ", \"discomfort_dist\": " << JsonNumber(s.discomfort_dist)
     << ", \"robot_radius\": " << JsonNumber(s.robot_radius)
     << ", \"robot_v_pref\": " << JsonNumber(s.robot_v_pref)
     << ", \"human_radius\": " << JsonNumber(s.human_radius)
     << ", \"human_v_pref\": " << JsonNumber(s.human_v_pref)
     << ", \"robot_visible\": " << (s.robot_visible ? "true" : "false")
     << ", \"success_reward\": " << JsonNumber(s.success_reward)
     << ", \"collision_penalty\": " << JsonNumber(s.collision_penalty)
     << ", \"discomfort_penalty_factor\": " << JsonNumber(s.discomfort_penalty_factor)
     << ", \"gamma\": " << JsonNumber(s.gamma) << "},\n";
  os << "  \"rows\": [\n";
  for (size_t i = 0; i < rows.size(); ++i) {
    const RowSpec& r = *rows[i].spec;
    const RowMetrics& m = rows[i].metrics;
    os << "    {\"label\": " << JsonString(r.label) << ",\n";
    os << "     \"policy\": " << JsonPlugin(r.policy) << ",\n";
    os << "     \"sensors\": [";
    for (size_t k = 0; k < r.sensors.size(); ++k) os << (k ? ", " : "") << JsonPlugin(r.sensors[k]);
    os << "],\n";
    auto wid = facts.world_identities.find(r.label);
    os << "     \"world\": " << JsonPlugin(r.world) << ",\n";
    os << "     \"world_identity\": "
       << JsonString(wid == facts.world_identities.end() ? "" : wid->second) << ",\n";
    os << "     \"humans\": {\"count\": " << r.humans.count << ", \"goal_mode\": \""
       << (r.humans.goal_mode == HumanGoalMode::kStay ? "stay" : "new_goal")
       << "\", \"policy\": " << JsonPlugin(r.humans.policy) << "},\n";
    os << "     \"info\": {";
    for (size_t k = 0; k < r.info.size(); ++k) {
      os << (k ? ", " : "") << JsonString(r.info[k].first) << ": " << JsonString(r.info[k].second);
    }
    os << "},\n";
    os << "     \"metrics\": {\"episodes\": " << m.episodes
       << ", \"success_rate\": " << JsonNumber(m.success_rate)
       << ", \"collision_rate\": " << JsonNumber(m.collision_rate)
       << ", \"collision_human_rate\": " << JsonNumber(m.collision_human_rate)
       << ", \"collision_obstacle_rate\": " << JsonNumber(m.collision_obstacle_rate)
       << ", \"timeout_rate\": " << JsonNumber(m.timeout_rate)
       << ", \"policy_error_rate\": " << JsonNumber(m.policy_error_rate)
       << ", \"nav_time\": " << JsonNumber(m.nav_time)
       << ", \"danger_frequency\": " << JsonNumber(m.danger_frequency)
       << ", \"path_length\": " << JsonNumber(m.path_length)
       << ", \"min_human_distance\": " << JsonNumber(m.min_human_distance)
       << ", \"discounted_return\": " << JsonNumber(m.discounted_return)
       << ", \"decision_time_us\": " << JsonNumber(m.decision_time_us) << "}}"
       << (i + 1 < rows.size() ? "," : "") << "\n";
  }
  os << "  ]\n}\n";
  return os.str();
}

std::string ReadManifestField(const fs::path& path, const std::string& field) {
  std::ifstream f(path);
  std::string line;
  const std::string key = "\"" + field + "\": \"";
  while (std::getline(f, line)) {
    const auto p = line.find(key);
    if (p != std::string::npos) {
      const auto start = p + key.size();
      return line.substr(start, line.find('"', start) - start);
    }
  }
  return "";
}

long ReadManifestInteger(const fs::path& path, const std::string& field) {
  std::ifstream f(path);
  std::string line;
  const std::string key = "\"" + field + "\": ";
  while (std::getline(f, line)) {
    const auto p = line.find(key);
    if (p != std::string::npos) return std::strtol(line.c_str() + p + key.size(), nullptr, 10);
  }
  return -1;
}

void WriteFileAtomically(const fs::path& path, const std::string& text) {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary);
    f << text;
    if (!f) throw std::runtime_error("cannot write " + tmp.string());
  }
  fs::rename(tmp, path);
}

std::string NowUtc() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof(buf), "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

}  // namespace crowdsim
