#include "crowdsim/suite.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <variant>

#include "crowdsim/rng.h"
#include "suite_reader.h"
#include "yaml_edit.h"
#include "yaml_file.h"

namespace crowdsim {
namespace fs = std::filesystem;

std::string SuiteError::Format() const {
  std::ostringstream os;
  os << file;
  if (line > 0) os << ":" << line << ":" << column;
  os << ": ";
  if (!key_path.empty()) os << key_path << ": ";
  os << message;
  return os.str();
}

namespace {

std::string HashText(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  char buf[17];
  std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(SplitMix64(h)));
  return buf;
}

}  // namespace

std::string Suite::ConfigHash() const { return HashText(canonical); }

std::string RowSpec::ConfigHash() const { return HashText(canonical); }

namespace suite_internal {

namespace {

/// The top-level `isolation` (auto, on, off) and `episode_timeout_s`; a timeout needs
/// isolation (only a worker process can be stopped mid-episode).
void ReadIsolation(Reader& r, const YAML::Node& root, Suite* s) {
  const YAML::Node mode = root["isolation"];
  if (Present(mode)) {
    if (auto v = r.String(mode, "isolation")) {
      if (*v == "auto") s->isolation = IsolationMode::kAuto;
      else if (*v == "on") s->isolation = IsolationMode::kOn;
      else if (*v == "off") s->isolation = IsolationMode::kOff;
      else r.Error(mode, "isolation", "unknown value '" + *v + "' (valid: auto, on, off)");
    }
  }
  const YAML::Node timeout = root["episode_timeout_s"];
  if (Present(timeout)) {
    if (auto v = r.Number(timeout, "episode_timeout_s", 0.0, 1e7)) s->episode_timeout_s = *v;
  }
  if (s->episode_timeout_s > 0 && s->isolation == IsolationMode::kOff) {
    r.Error(mode, "isolation", "episode_timeout_s " + timeout.Scalar() + " needs isolated episodes "
            "(a thread cannot be stopped mid-episode); set isolation to auto or on, or remove "
            "episode_timeout_s");
  }
}

}  // namespace

void ReadSim(Reader& r, const YAML::Node& n, SimConfig* sim) {
  if (!r.IsMap(n, "sim", "simulation settings")) return;
  std::vector<std::string> keys;
  for (const SimField& f : kSimFields) keys.push_back(f.key);
  r.CheckKeys(n, "sim", keys);
  for (const SimField& f : kSimFields) {
    if (!n[f.key]) continue;
    const std::string path = Reader::Child("sim", f.key);
    if (const auto* number = std::get_if<double SimConfig::*>(&f.member)) {
      if (auto v = r.Number(n[f.key], path, f.lo, f.hi, f.lo_open)) sim->**number = *v;
    } else if (auto b = r.Bool(n[f.key], path)) {
      sim->*std::get<bool SimConfig::*>(f.member) = *b;
    }
  }
  // A step count beyond any real episode is a typo (time_step: 1e-300 ran forever).
  constexpr double kMaxSteps = 1e6;
  if (sim->time_limit / sim->time_step > kMaxSteps) {
    r.Error(n["time_step"] ? n["time_step"] : n, "sim.time_step",
            "time_limit / time_step = " + std::to_string(sim->time_limit / sim->time_step) +
                " steps per episode, more than 1,000,000; raise time_step or lower time_limit");
  }
}

void ReadWorld(Reader& r, const YAML::Node& n, const std::string& path, const fs::path& base,
               PluginUse* out) {
  if (!r.IsMap(n, path, "source: <world plugin> and its parameters")) return;
  if (!n["source"]) {
    r.Error(n, path, "missing key 'source' (the world plugin, e.g. random_rect, floorplan, crowdnav)");
    return;
  }
  out->plugin = n["source"].Scalar();
  out->loaded = r.Plugin(n["source"], Reader::Child(path, "source"), PluginKind::kWorld);
  if (out->loaded) out->params = r.ParamsFor(*out->loaded, n, {"source"}, path, base);
}

void ReadSensors(Reader& r, const YAML::Node& n, const std::string& path, const fs::path& base,
                 std::vector<PluginUse>* out) {
  if (!n.IsSequence()) {
    r.Error(n, path, "must be a list of sensors, e.g. [person, {type: lidar2d, beams: 45}]");
    return;
  }
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string p = Reader::Index(path, i);
    const YAML::Node item = n[i];
    PluginUse use;
    YAML::Node type_node;
    if (item.IsScalar()) {
      type_node = item;
    } else if (item.IsMap() && item["type"]) {
      type_node = item["type"];
    } else {
      r.Error(item, p, "a sensor is a plugin name (person) or a map with 'type' and its parameters");
      continue;
    }
    use.plugin = type_node.Scalar();
    use.loaded = r.Plugin(type_node, item.IsMap() ? Reader::Child(p, "type") : p, PluginKind::kSensor);
    if (use.loaded) use.params = r.ParamsFor(*use.loaded, item.IsMap() ? item : YAML::Node(YAML::NodeType::Undefined), {"type"}, p, base);
    out->push_back(std::move(use));
  }
}

void CanonicalSim(const SimConfig& sim, std::ostream& os) {
  os << "sim=";
  for (const SimField& f : kSimFields) {
    os << (&f == kSimFields ? "" : ",");
    std::visit([&](auto member) { os << sim.*member; }, f.member);  // a bool as 0 or 1
  }
  os << "\n";
}

namespace {

/// FNV-1a of a file's bytes, as 16 hex digits ("unreadable" when it cannot be read).
std::string FileContentHash(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return "unreadable";
  std::uint64_t h = 0xcbf29ce484222325ULL;
  char buf[1 << 16];
  while (in.read(buf, sizeof(buf)) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      h ^= static_cast<unsigned char>(buf[i]);
      h *= 0x100000001b3ULL;
    }
  }
  char out[17];
  std::snprintf(out, sizeof(out), "%016llx", static_cast<unsigned long long>(h));
  return out;
}

}  // namespace

void Canonical(const PluginUse& u, std::ostream& os) {
  os << (u.loaded ? u.loaded->descriptor->name : u.plugin) << "{";
  for (const auto& [k, v] : u.params.values()) {
    os << k << "=" << FormatParamValue(v);
    // A parameter that names a file (weights, a world file) counts with its content: replacing
    // the file at the same path is another configuration, never resumed as the old one.
    if (const auto* text = std::get_if<std::string>(&v); text && !text->empty()) {
      std::error_code ec;
      const fs::path file = u.params.ResolvePath(*text);
      if (fs::is_regular_file(file, ec)) os << "#content:" << FileContentHash(file);
    }
    os << ";";
  }
  os << "}";
}

}  // namespace suite_internal

namespace {

using namespace suite_internal;

struct Defaults {
  YAML::Node world{YAML::NodeType::Undefined};
  YAML::Node humans{YAML::NodeType::Undefined};
  YAML::Node sensors{YAML::NodeType::Undefined};
};

/// A label names a row in episodes.csv and the tables: control characters (a line break, a tab)
/// would be turned into spaces there and could make two rows one.
void CheckLabel(Reader& r, const YAML::Node& n, const std::string& path) {
  const std::string& label = n.Scalar();
  if (label.empty()) r.Error(n, path, "must not be empty");
  if (std::any_of(label.begin(), label.end(), [](char c) { return std::iscntrl(static_cast<unsigned char>(c)); })) {
    r.Error(n, path, "must not contain control characters (line breaks, tabs): they would become "
                     "spaces in episodes.csv and the tables");
  }
}

void ReadInfo(Reader& r, const YAML::Node& info, const std::string& path,
              std::vector<std::pair<std::string, std::string>>* out) {
  if (!r.IsMap(info, path, "extra table columns")) return;
  for (const auto& kv : info) {
    if (!kv.second.IsScalar()) {
      r.Error(kv.second, Reader::Child(path, kv.first.Scalar()), "must be a single value");
      continue;
    }
    out->emplace_back(kv.first.Scalar(), kv.second.Scalar());
  }
}

/// `reference: {success: 0.67, collision: 0.20, timeout: 0.13, nav_time: 12.9, danger: 0.09,
/// source: "..."}`: published values, any subset of them (at least one).
std::optional<PublishedReference> ReadReference(Reader& r, const YAML::Node& n, const std::string& path) {
  if (!r.IsMap(n, path, "published values: success, collision, timeout, nav_time, danger, source")) return std::nullopt;
  r.CheckKeys(n, path, {"success", "collision", "timeout", "nav_time", "danger", "source"});
  PublishedReference ref;
  const size_t errors_before = r.errors.size();
  for (auto [key, target] : {std::pair{"success", &ref.success}, std::pair{"collision", &ref.collision},
                             std::pair{"timeout", &ref.timeout}, std::pair{"danger", &ref.danger}}) {
    if (n[key]) *target = r.Number(n[key], Reader::Child(path, key), 0.0, 1.0);
  }
  if (n["nav_time"]) ref.nav_time = r.Number(n["nav_time"], Reader::Child(path, "nav_time"), 0.0, 1e6, true);
  if (n["source"]) {
    if (auto src = r.String(n["source"], Reader::Child(path, "source"))) ref.source = *src;
  }
  if (r.errors.size() != errors_before) return std::nullopt;
  if (!ref.success && !ref.collision && !ref.timeout && !ref.nav_time && !ref.danger) {
    r.Error(n, path, "gives no value: name at least one of success, collision, timeout, nav_time, danger");
    return std::nullopt;
  }
  return ref;
}

void ReadHumans(Reader& r, const YAML::Node& suite_level, const YAML::Node& row_level,
                const std::string& path, const fs::path& base, HumansSpec* out) {
  // Row keys override suite keys one by one.
  const std::vector<std::string> keys = {"count", "policy", "params", "goal_mode"};
  auto pick = [&](const char* key) -> std::pair<YAML::Node, std::string> {
    if (Present(row_level) && row_level.IsMap() && Present(row_level[key])) return {row_level[key], Reader::Child(path, key)};
    if (Present(suite_level) && suite_level.IsMap() && Present(suite_level[key])) return {suite_level[key], Reader::Child("humans", key)};
    return {YAML::Node(YAML::NodeType::Undefined), ""};
  };
  if (Present(row_level)) {
    if (r.IsMap(row_level, path, "count, policy, params, goal_mode")) r.CheckKeys(row_level, path, keys);
  }
  if (auto [n, p] = pick("count"); Present(n)) {
    if (auto c = r.Integer(n, p, 0, 10000)) out->count = static_cast<int>(*c);
  }
  if (auto [n, p] = pick("goal_mode"); Present(n)) {
    if (auto s = r.String(n, p)) {
      if (*s == "stay") out->goal_mode = HumanGoalMode::kStay;
      else if (*s == "new_goal") out->goal_mode = HumanGoalMode::kNewGoal;
      else r.Error(n, p, "value '" + *s + "' is not valid; valid: stay, new_goal");
    }
  }
  auto [pn, pp] = pick("policy");
  YAML::Node default_policy(out->count > 0 ? "orca" : "linear");
  const YAML::Node policy_node = Present(pn) ? pn : default_policy;
  out->policy.plugin = policy_node.Scalar();
  out->policy.loaded = r.Plugin(policy_node, Present(pn) ? pp : std::string("humans.policy (default)"), PluginKind::kPolicy);
  auto [params, params_path] = pick("params");
  if (Present(params) && !r.IsMap(params, params_path, "policy parameters")) return;
  if (out->policy.loaded) out->policy.params = r.ParamsFor(*out->policy.loaded, params, {}, params_path, base);
}

void ReadRow(Reader& r, const YAML::Node& n, size_t index, const Defaults& d, const fs::path& base,
             RowSpec* row) {
  const std::string path = Reader::Index("rows", index);
  if (!r.IsMap(n, path, "policy, sensors, ...")) return;
  r.CheckKeys(n, path, {"label", "policy", "params", "weights", "sensors", "world", "humans", "info", "reference"});
  if (!n["policy"]) {
    r.Error(n, path, "missing key 'policy' (a policy plugin name such as linear or orca, or a .so path)");
  } else {
    row->policy.plugin = n["policy"].Scalar();
    row->policy.loaded = r.Plugin(n["policy"], Reader::Child(path, "policy"), PluginKind::kPolicy);
  }
  row->label = n["label"] ? n["label"].Scalar() : row->policy.plugin;
  if (n["label"]) CheckLabel(r, n["label"], Reader::Child(path, "label"));
  if (n["params"] && !r.IsMap(n["params"], Reader::Child(path, "params"), "policy parameters")) return;
  if (row->policy.loaded) {
    row->policy.params = r.ParamsFor(*row->policy.loaded, n["params"], {}, Reader::Child(path, "params"), base);
    if (n["weights"]) {
      const auto& schema = row->policy.loaded->schema;
      const bool takes = std::any_of(schema.begin(), schema.end(), [](const ParamSpec& s) { return s.name == "weights"; });
      if (!takes) {
        r.Error(n["weights"], Reader::Child(path, "weights"),
                "policy '" + row->policy.plugin + "' takes no weights (it has no 'weights' parameter)");
      } else if (auto w = r.String(n["weights"], Reader::Child(path, "weights"))) {
        row->policy.params.Set("weights", *w);
      }
    }
  }
  const YAML::Node sensors = n["sensors"] ? n["sensors"] : d.sensors;
  if (Present(sensors)) ReadSensors(r, sensors, n["sensors"] ? Reader::Child(path, "sensors") : "robot.sensors", base, &row->sensors);
  if (n["world"]) {
    ReadWorld(r, n["world"], Reader::Child(path, "world"), base, &row->world);
  } else if (Present(d.world)) {
    ReadWorld(r, d.world, "world", base, &row->world);
  } else {
    r.Error(n, path, "no world: give 'world' at the top of the suite or in this row");
  }
  ReadHumans(r, d.humans, n["humans"], Reader::Child(path, "humans"), base, &row->humans);
  if (const auto info = n["info"]) ReadInfo(r, info, Reader::Child(path, "info"), &row->info);
  if (const auto ref = n["reference"]) row->reference = ReadReference(r, ref, Reader::Child(path, "reference"));
}

/// `summaries:` entries: label, rows (labels of earlier rows), optional info and reference.
void ReadSummaries(Reader& r, const YAML::Node& n, const std::vector<RowSpec>& rows,
                   std::vector<SummarySpec>* out) {
  if (!n.IsSequence()) {
    r.Error(n, "summaries", "must be a list, e.g. [{label: avg, rows: [easy, medium, hard]}]");
    return;
  }
  std::string valid;
  for (const RowSpec& row : rows) valid += (valid.empty() ? "" : ", ") + row.label;
  std::set<std::string> labels;
  for (const RowSpec& row : rows) labels.insert(row.label);
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string path = Reader::Index("summaries", i);
    const YAML::Node item = n[i];
    if (!r.IsMap(item, path, "label, rows, info, reference")) continue;
    r.CheckKeys(item, path, {"label", "rows", "info", "reference"});
    SummarySpec summary;
    if (auto label = item["label"] ? r.String(item["label"], Reader::Child(path, "label")) : std::nullopt) {
      summary.label = *label;
      CheckLabel(r, item["label"], Reader::Child(path, "label"));
      if (!labels.insert(summary.label).second) {
        r.Error(item["label"], Reader::Child(path, "label"),
                "label '" + summary.label + "' is already a row's or summary's; labels must be unique");
      }
    } else if (!item["label"]) {
      r.Error(item, path, "missing key 'label' (the summary line's name, e.g. avg)");
    }
    const YAML::Node members = item["rows"];
    if (!members || !members.IsSequence() || members.size() == 0) {
      r.Error(members ? members : item, Reader::Child(path, "rows"),
              "must be a non-empty list of row labels to average (valid: " + valid + ")");
    } else {
      for (size_t k = 0; k < members.size(); ++k) {
        const std::string label = members[k].Scalar();
        const bool found = std::any_of(rows.begin(), rows.end(), [&](const RowSpec& row) { return row.label == label; });
        if (!found) {
          r.Error(members[k], Reader::Index(Reader::Child(path, "rows"), k),
                  "no row is labelled '" + label + "' (valid: " + valid + ")");
        } else if (std::find(summary.rows.begin(), summary.rows.end(), label) != summary.rows.end()) {
          r.Error(members[k], Reader::Index(Reader::Child(path, "rows"), k), "row '" + label + "' is named twice");
        } else {
          summary.rows.push_back(label);
        }
      }
    }
    if (const auto info = item["info"]) ReadInfo(r, info, Reader::Child(path, "info"), &summary.info);
    if (const auto ref = item["reference"]) summary.reference = ReadReference(r, ref, Reader::Child(path, "reference"));
    out->push_back(std::move(summary));
  }
}

}  // namespace

SuiteLoadResult LoadSuite(const fs::path& file, PluginRegistry& registry,
                          const std::vector<std::string>& overrides) {
  SuiteLoadResult result;
  Reader r(file.string(), registry);
  YAML::Node root = LoadYamlFile(file, "suite file", &result.errors);
  if (!result.errors.empty()) return result;
  if (root.IsMap()) {
    ApplyOverrides(root, overrides, &result.errors);
    ExpandSweeps(root, file.string(), &result.errors);
    LocateOverrideErrors(overrides, &result.errors);
    if (!result.errors.empty()) return result;
  }
  if (!root.IsMap()) {
    result.errors.push_back({file.string(), 0, 0, "", "a suite is a YAML map with name, episodes, world and rows"});
    return result;
  }
  Suite s;
  s.file = file;
  s.overrides = overrides;
  const fs::path base = file.has_parent_path() ? file.parent_path() : fs::path(".");
  r.CheckKeys(root, "", {"name", "description", "episodes", "seed", "isolation", "episode_timeout_s", "sim", "world", "humans", "robot", "columns", "rows", "summaries"});
  s.name = r.Name(root, "results/<name>/");
  if (root["description"]) s.description = root["description"].Scalar();
  if (root["episodes"]) {
    if (auto e = r.Integer(root["episodes"], "episodes", 1, 10'000'000)) s.episodes = static_cast<int>(*e);
  }
  if (root["seed"]) {
    if (auto e = r.Integer(root["seed"], "seed", 0, std::numeric_limits<std::int64_t>::max())) s.seed = static_cast<std::uint64_t>(*e);
  }
  ReadIsolation(r, root, &s);
  if (root["sim"]) ReadSim(r, root["sim"], &s.sim);
  Defaults d;
  d.world = root["world"];
  d.humans = root["humans"];
  if (Present(d.humans)) {
    if (r.IsMap(d.humans, "humans", "count, policy, params, goal_mode")) r.CheckKeys(d.humans, "humans", {"count", "policy", "params", "goal_mode"});
  }
  if (const auto robot = root["robot"]) {
    if (r.IsMap(robot, "robot", "sensors")) {
      r.CheckKeys(robot, "robot", {"sensors"});
      // Assigning yaml-cpp's placeholder for a missing key throws InvalidNode (`robot: {}`).
      if (robot["sensors"]) d.sensors = robot["sensors"];
    }
  }
  if (const auto cols = root["columns"]) {
    if (!cols.IsSequence()) {
      r.Error(cols, "columns", "must be a list of info column names");
    } else {
      for (const auto& c : cols) s.info_columns.push_back(c.Scalar());
    }
  }
  if (!root["rows"] || !root["rows"].IsSequence() || root["rows"].size() == 0) {
    r.Error(root["rows"] ? root["rows"] : root, "rows", "missing or empty 'rows' list (each row: policy, sensors, ...)");
  } else {
    std::set<std::string> labels;
    for (size_t i = 0; i < root["rows"].size(); ++i) {
      RowSpec row;
      ReadRow(r, root["rows"][i], i, d, base, &row);
      if (!row.label.empty() && !labels.insert(row.label).second) {
        r.Error(root["rows"][i], Reader::Index("rows", i) + ".label",
                "label '" + row.label + "' is used by an earlier row; labels must be unique");
      }
      for (const auto& [k, v] : row.info) {
        if (std::find(s.info_columns.begin(), s.info_columns.end(), k) == s.info_columns.end()) {
          s.info_columns.push_back(k);
        }
      }
      s.rows.push_back(std::move(row));
    }
  }
  if (const auto summaries = root["summaries"]) {
    ReadSummaries(r, summaries, s.rows, &s.summaries);
    for (const SummarySpec& summary : s.summaries) {
      for (const auto& [k, v] : summary.info) {
        if (std::find(s.info_columns.begin(), s.info_columns.end(), k) == s.info_columns.end()) {
          s.info_columns.push_back(k);
        }
      }
    }
  }
  if (!r.errors.empty()) {
    // Suite-level sections (world, humans, robot sensors) are read once per row: report each
    // problem once.
    LocateOverrideErrors(overrides, &r.errors);
    std::set<std::string> seen;
    for (auto& e : r.errors) {
      if (seen.insert(e.Format()).second) result.errors.push_back(std::move(e));
    }
    return result;
  }
  std::ostringstream head;
  head << "seed=" << s.seed << "\n";
  CanonicalSim(s.sim, head);
  s.canonical = head.str();
  for (auto& row : s.rows) {
    std::ostringstream os;
    os << "row " << row.label << ": ";
    Canonical(row.policy, os);
    os << " sensors:";
    for (const auto& sen : row.sensors) Canonical(sen, os);
    os << " world:";
    Canonical(row.world, os);
    os << " humans:" << row.humans.count << "," << static_cast<int>(row.humans.goal_mode) << ",";
    Canonical(row.humans.policy, os);
    os << "\n";
    row.canonical = head.str() + os.str();
    s.canonical += os.str();
  }
  result.suite = std::move(s);
  return result;
}

}  // namespace crowdsim
