#include "crowdsim/bench/suite.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "crowdsim/bench/closest_name.h"
#include "crowdsim/bench/episode_columns.h"
#include "spec/config_text.h"
#include "spec/human_attributes_reader.h"
#include "spec/kinematics_reader.h"
#include "spec/row_reader.h"
#include "spec/spec_head_reader.h"
#include "spec/suite_reader.h"
#include "spec/yaml_edit.h"
#include "spec/yaml_file.h"

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

std::string Suite::ConfigHash() const { return suite_internal::HashConfigText(canonical); }

std::string RowSpec::ConfigHash() const { return suite_internal::HashConfigText(canonical); }

namespace {

using namespace suite_internal;

/// Top-level `isolation` (auto, on, off) and `episode_timeout_s`; a timeout needs isolation (only a
/// worker can be stopped mid-episode).
void ReadIsolation(Reader& r, const YAML::Node& root, Suite* s) {
  const YAML::Node mode = root["isolation"];
  if (Present(mode)) {
    if (auto v = r.String(mode, "isolation")) {
      if (*v == "auto")
        s->isolation = IsolationMode::kAuto;
      else if (*v == "on")
        s->isolation = IsolationMode::kOn;
      else if (*v == "off")
        s->isolation = IsolationMode::kOff;
      else
        r.Error(mode, "isolation", "unknown value '" + *v + "' (valid: auto, on, off)");
    }
  }
  const YAML::Node timeout = root["episode_timeout_s"];
  if (Present(timeout)) {
    if (auto v = r.Number(timeout, "episode_timeout_s", 0.0, 1e7)) s->episode_timeout_s = *v;
  }
  if (s->episode_timeout_s > 0 && s->isolation == IsolationMode::kOff) {
    r.Error(mode, "isolation",
            "episode_timeout_s " + timeout.Scalar() +
                " needs isolated episodes "
                "(a thread cannot be stopped mid-episode); set isolation to auto or on, or remove "
                "episode_timeout_s");
  }
}

}  // namespace

namespace {

// A `columns:` name that no row's or summary's info fills and that is one typo from a social
// metric's name: the metric was meant (an info column of that name would stay empty).
void CheckNamedColumns(Reader& r, const YAML::Node& cols, const Suite& s) {
  if (!cols || !cols.IsSequence()) return;
  std::vector<std::string> metrics;
  for (const EpisodeColumn& c : kEpisodeColumns) {
    if (Social(c)) metrics.push_back(c.name);
  }
  std::set<std::string> filled;
  for (const RowSpec& row : s.rows) {
    for (const auto& [k, v] : row.info) filled.insert(k);
  }
  for (const SummarySpec& summary : s.summaries) {
    for (const auto& [k, v] : summary.info) filled.insert(k);
  }
  for (size_t i = 0; i < cols.size(); ++i) {
    if (!cols[i].IsScalar()) continue;
    const std::string name = cols[i].as<std::string>();
    if (IsSocialMetric(name) || filled.count(name)) continue;
    const std::string hint = DidYouMean(name, metrics);
    if (!hint.empty()) {
      r.Error(cols[i], Reader::Index("columns", i),
              "'" + name + "' is no row's info key and no social metric" + hint);
    }
  }
}

/// A suite row is a row spec with a label, extra table columns and published values.
const RowRules kSuiteRowRules{"a policy plugin name such as linear or orca, or a .so path",
                              "no world: give 'world' at the top of the suite or in this row",
                              /*sensors_required=*/false, /*humans_range=*/false};

// Whether `s` is well-formed UTF-8 (RFC 3629: no overlong forms, surrogates or code points
// past U+10FFFF).
bool ValidUtf8(const std::string& s) {
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const int n = c < 0x80           ? 0
                  : (c >> 5) == 0x6  ? 1
                  : (c >> 4) == 0xE  ? 2
                  : (c >> 3) == 0x1E ? 3
                                     : -1;
    if (n < 0 || i + n >= s.size()) return false;
    std::uint32_t cp = n == 0 ? c : c & (0x3F >> n);
    for (int k = 1; k <= n; ++k) {
      const auto t = static_cast<unsigned char>(s[i + k]);
      if ((t >> 6) != 0x2) return false;
      cp = (cp << 6) | (t & 0x3F);
    }
    static constexpr std::uint32_t kMin[] = {0, 0x80, 0x800, 0x10000};
    if (cp < kMin[n] || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return false;
    i += n + 1;
  }
  return true;
}

/// Labels name rows in episodes.csv and tables, where control characters become spaces and could
/// merge rows.
void CheckLabel(Reader& r, const YAML::Node& n, const std::string& path) {
  const std::string& label = n.Scalar();
  if (!ValidUtf8(label)) {
    r.Error(n, path,
            "is not valid UTF-8 text (the file's encoding?): labels name rows in CSV, SVG and "
            "HTML files; save the suite as UTF-8");
  }
  if (std::all_of(label.begin(), label.end(),
                  [](char c) { return std::isspace(static_cast<unsigned char>(c)); })) {
    r.Error(n, path, "must not be empty or blank");
  }
  if (std::any_of(label.begin(), label.end(),
                  [](char c) { return std::iscntrl(static_cast<unsigned char>(c)); })) {
    r.Error(n, path,
            "must not contain control characters (line breaks, tabs): they would become "
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

/// `reference: {success: 0.67, collision: 0.20, ..., source: "..."}`: any non-empty subset of
/// published values.
std::optional<PublishedReference> ReadReference(Reader& r, const YAML::Node& n,
                                                const std::string& path) {
  if (!r.IsMap(n, path, "published values: success, collision, timeout, nav_time, danger, source"))
    return std::nullopt;
  r.CheckKeys(n, path, {"success", "collision", "timeout", "nav_time", "danger", "source"});
  PublishedReference ref;
  const size_t errors_before = r.errors.size();
  for (auto [key, target] :
       {std::pair{"success", &ref.success}, std::pair{"collision", &ref.collision},
        std::pair{"timeout", &ref.timeout}, std::pair{"danger", &ref.danger}}) {
    if (n[key]) *target = r.Number(n[key], Reader::Child(path, key), 0.0, 1.0);
  }
  if (n["nav_time"])
    ref.nav_time = r.Number(n["nav_time"], Reader::Child(path, "nav_time"), 0.0, 1e6, true);
  if (n["source"]) {
    if (auto src = r.String(n["source"], Reader::Child(path, "source"))) ref.source = *src;
  }
  if (r.errors.size() != errors_before) return std::nullopt;
  if (!ref.success && !ref.collision && !ref.timeout && !ref.nav_time && !ref.danger) {
    r.Error(n, path,
            "gives no value: name at least one of success, collision, timeout, nav_time, danger");
    return std::nullopt;
  }
  return ref;
}

void ReadRow(Reader& r, const YAML::Node& n, size_t index, const RowDefaults& d,
             const fs::path& base, RowSpec* row) {
  const std::string path = Reader::Index("rows", index);
  if (!r.IsMap(n, path, "policy, sensors, ...")) return;
  std::vector<std::string> keys = {"label"};
  keys.insert(keys.end(), kRowSpecKeys.begin(), kRowSpecKeys.end());
  // `sweep` is expanded before rows are read; it is listed among valid keys for misspellings.
  keys.insert(keys.end(), {"sweep", "info", "reference"});
  r.CheckKeys(n, path, keys);
  ReadRowSpec(r, n, path, d, kSuiteRowRules, base, row);
  row->label = row->policy.plugin;
  if (n["label"]) {
    // An empty label (`label:`) is blank; one that is not text gets a type error instead.
    const auto label = n["label"].IsNull() ? std::optional<std::string>("")
                                           : r.String(n["label"], Reader::Child(path, "label"));
    row->label = label.value_or("");
    if (label) CheckLabel(r, n["label"], Reader::Child(path, "label"));
  }
  if (const auto info = n["info"]) ReadInfo(r, info, Reader::Child(path, "info"), &row->info);
  if (const auto ref = n["reference"])
    row->reference = ReadReference(r, ref, Reader::Child(path, "reference"));
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
    if (auto label =
            item["label"] ? r.String(item["label"], Reader::Child(path, "label")) : std::nullopt) {
      summary.label = *label;
      CheckLabel(r, item["label"], Reader::Child(path, "label"));
      if (!labels.insert(summary.label).second) {
        r.Error(
            item["label"], Reader::Child(path, "label"),
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
        // A member that is not text gets a type error, not "no row is labelled ''".
        const auto text = r.String(members[k], Reader::Index(Reader::Child(path, "rows"), k));
        if (!text) continue;
        const std::string& label = *text;
        const bool found = std::any_of(rows.begin(), rows.end(),
                                       [&](const RowSpec& row) { return row.label == label; });
        if (!found) {
          r.Error(members[k], Reader::Index(Reader::Child(path, "rows"), k),
                  "no row is labelled '" + label + "' (valid: " + valid + ")");
        } else if (std::find(summary.rows.begin(), summary.rows.end(), label) !=
                   summary.rows.end()) {
          r.Error(members[k], Reader::Index(Reader::Child(path, "rows"), k),
                  "row '" + label + "' is named twice");
        } else {
          summary.rows.push_back(label);
        }
      }
    }
    if (const auto info = item["info"])
      ReadInfo(r, info, Reader::Child(path, "info"), &summary.info);
    if (const auto ref = item["reference"])
      summary.reference = ReadReference(r, ref, Reader::Child(path, "reference"));
    out->push_back(std::move(summary));
  }
}

}  // namespace

SuiteLoadResult LoadSuite(const fs::path& file, PluginRegistry& registry,
                          const std::vector<std::string>& overrides) {
  SuiteLoadResult result;
  const std::optional<SchemaDefaults> schema = LoadSchemaDefaults(&result.errors);
  if (!schema) return result;
  Reader r(file.string(), registry);
  std::vector<SweptRow> swept;
  std::vector<std::string> set_paths;             // each --set's path, list items by index
  std::vector<std::vector<std::size_t>> row_map;  // each row's index after sweeps
  YAML::Node root = LoadYamlFile(file, "suite file", &result.errors);
  if (!result.errors.empty()) return result;
  if (root.IsMap()) {
    ApplyOverrides(root, overrides, &result.errors, &set_paths);
    ExpandSweeps(root, file.string(), &result.errors, &swept, &row_map);
    RefuseOverridesOfSweptKeys(overrides, set_paths, swept, file.string(), &result.errors);
    LocateOverrideErrors(overrides, &result.errors, set_paths, row_map);
    if (!result.errors.empty()) return result;
  }
  if (!root.IsMap()) {
    result.errors.push_back(
        {file.string(), 0, 0, "", "a suite is a YAML map with name, episodes, world and rows"});
    return result;
  }
  Suite s;
  s.file = file;
  s.overrides = overrides;
  const fs::path base = file.has_parent_path() ? file.parent_path() : fs::path(".");
  std::vector<std::string> keys = kSpecHeadKeys;
  keys.insert(keys.end(), {"episodes", "isolation", "episode_timeout_s", "world", "humans", "robot",
                           "columns", "rows", "summaries"});
  r.CheckKeys(root, "", keys);
  SpecHead spec_head = ReadSpecHead(r, root, "runs/<name>/");
  s.name = std::move(spec_head.name);
  s.description = std::move(spec_head.description);
  s.seed = spec_head.seed;
  s.sim = spec_head.sim;
  if (root["episodes"]) {
    if (auto e = r.Integer(root["episodes"], "episodes", 1, 10'000'000))
      s.episodes = static_cast<int>(*e);
  }
  ReadIsolation(r, root, &s);
  RowDefaults d{*schema};
  d.world = root["world"];
  d.humans = root["humans"];
  if (Present(d.humans)) {
    if (r.IsMap(d.humans, "humans", kHumansWhat)) r.CheckKeys(d.humans, "humans", kHumansKeys);
  }
  if (const auto robot = root["robot"]) {
    if (r.IsMap(robot, "robot", "sensors, kinematics")) {
      r.CheckKeys(robot, "robot", {"sensors", "kinematics"});
      // Assigning yaml-cpp's placeholder for a missing key throws InvalidNode (`robot: {}`).
      if (robot["sensors"]) d.sensors = robot["sensors"];
      if (robot["kinematics"]) d.kinematics = robot["kinematics"];
    }
  }
  if (const auto cols = root["columns"]) {
    if (!cols.IsSequence()) {
      r.Error(cols, "columns", "must be a list of info column and social metric names");
    } else {
      for (size_t i = 0; i < cols.size(); ++i) {
        const auto name = r.String(cols[i], Reader::Index("columns", i));
        if (!name) continue;
        auto& list = IsSocialMetric(*name) ? s.metric_columns : s.info_columns;
        if (std::find(list.begin(), list.end(), *name) != list.end()) {
          r.Error(cols[i], Reader::Index("columns", i),
                  "'" + *name + "' is named twice; the table would show the column twice");
          continue;
        }
        list.push_back(*name);
      }
    }
  }
  if (!root["rows"] || !root["rows"].IsSequence() || root["rows"].size() == 0) {
    r.Error(root["rows"] ? root["rows"] : root, "rows",
            "missing or empty 'rows' list (each row: policy, sensors, ...)");
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
  CheckNamedColumns(r, root["columns"], s);
  if (!r.errors.empty()) {
    // Suite-level sections (world, humans, robot sensors) are read once per row: report each
    // problem once.
    LocateOverrideErrors(overrides, &r.errors, set_paths, row_map);
    LocateSweepErrors(swept, file.string(), &r.errors);
    // One problem at one place is one error, whichever row's copy of a section found it.
    std::set<std::string> seen;
    for (auto& e : r.errors) {
      const std::string key = e.line > 0 ? e.file + ":" + std::to_string(e.line) + ":" +
                                               std::to_string(e.column) + ":" + e.message
                                         : e.Format();
      if (seen.insert(key).second) result.errors.push_back(std::move(e));
    }
    return result;
  }
  std::ostringstream head;
  head << "seed=" << s.seed << "\n";
  CanonicalSim(s.sim, head);
  for (const std::string& name : s.metric_columns) s.social_metrics |= MetricFamilyOf(name);
  // Other files; absent, old hashes hold.
  if (s.social_metrics & kCoreMetrics) head << "social_metrics\n";
  if (s.social_metrics & kGroupMetrics) head << "group_metrics\n";
  if (s.social_metrics & kEffectMetrics) head << "effect_metrics\n";
  s.canonical = head.str();
  for (auto& row : s.rows) {
    std::ostringstream os;
    os << "row " << row.label << ": ";
    Canonical(row.policy, os);
    os << " sensors:";
    for (const auto& sen : row.sensors) Canonical(sen, os);
    CanonicalKinematics(row.kinematics, os);
    os << " world:";
    Canonical(row.world, os);
    os << " humans:" << row.humans.count << "," << static_cast<int>(row.humans.goal_mode) << ",";
    CanonicalHumanAttributes(row.humans, os);
    Canonical(row.humans.policy, os);
    os << "\n";
    row.canonical = head.str() + os.str();
    s.canonical += os.str();
  }
  result.suite = std::move(s);
  return result;
}

}  // namespace crowdsim
