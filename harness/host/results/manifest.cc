// manifest.json: a run's configuration (suite, plugins, files, sim, hashes, commit) and
// measurements, via nlohmann-json.
#include <cmath>
#include <fstream>
#include <type_traits>
#include <variant>

#include "crowdsim/bench/episode_columns.h"
#include "crowdsim/bench/metrics.h"
#include "crowdsim/bench/results.h"
#include "crowdsim/version.h"
#include "loader/blas_kernel.h"
#include "results/json_file.h"
#include "spec/config_text.h"

namespace crowdsim {
namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

/// A number as JSON allows it: non-finite values (a nav. time with no success) become null.
Json Number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }

Json ParamJson(const ParamValue& v) {
  return std::visit(
      [](const auto& x) -> Json {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, double>) {
          return Number(x);
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          Json list = Json::array();
          for (double d : x) list.push_back(Number(d));
          return list;
        } else {
          return Json(x);  // bool, integer, string
        }
      },
      v);
}

Json PluginJson(const PluginUse& u) {
  Json j;
  j["plugin"] = u.loaded ? u.loaded->descriptor->name : u.plugin;
  if (u.loaded) j["file"] = u.loaded->path.string();
  // A user's plugin file is part of the configuration (the config hash covers its bytes).
  if (const std::string content = suite_internal::PluginFileContent(u); !content.empty()) {
    j["file_content_fnv1a"] = content;
  }
  Json params = Json::object();
  for (const auto& [k, v] : u.params.values()) params[k] = ParamJson(v);
  j["params"] = std::move(params);
  // Every file the plugin reads, with the content hash that the config hash covers.
  const std::vector<suite_internal::InputFile> inputs = suite_internal::InputFiles(u);
  if (!inputs.empty()) {
    Json files = Json::array();
    for (const auto& f : inputs) {
      Json file;
      if (!f.param.empty()) file["param"] = f.param;
      file["path"] = f.name;
      file["content_fnv1a"] = f.content;
      files.push_back(std::move(file));
    }
    j["files"] = std::move(files);
  }
  return j;
}

Json IntervalJson(const Interval& i) { return Json::array({Number(i.low), Number(i.high)}); }

/// Adds a table line's info, metrics (with 95% intervals) and reference to its manifest object.
void AddLineTail(const TableRow& line, MetricFamilies social, Json* j) {
  Json info = Json::object();
  for (const auto& [key, value] : line.Info()) info[key] = value;
  (*j)["info"] = std::move(info);
  const RowMetrics& m = line.metrics;
  Json metrics;
  metrics["episodes"] = m.episodes;
  for (const auto& [key, field] :
       {std::pair{"success_rate", &RowMetrics::success_rate},
        {"collision_rate", &RowMetrics::collision_rate},
        {"collision_human_rate", &RowMetrics::collision_human_rate},
        {"collision_obstacle_rate", &RowMetrics::collision_obstacle_rate},
        {"timeout_rate", &RowMetrics::timeout_rate},
        {"policy_error_rate", &RowMetrics::policy_error_rate},
        {"policy_crash_rate", &RowMetrics::policy_crash_rate},
        {"policy_timeout_rate", &RowMetrics::policy_timeout_rate},
        {"nav_time", &RowMetrics::nav_time},
        {"danger_frequency", &RowMetrics::danger_frequency}}) {
    metrics[key] = Number(m.*field);
  }
  for (const EpisodeColumn& c : kEpisodeColumns) {
    if (c.mean != RowMean::kNone && (!Social(c) || (social & FamilyOf(c)))) {
      metrics[c.name] = Number(RowMeanField(m, c));
      if (Social(c)) metrics[std::string(c.name) + "_se"] = Number(SocialSeField(m, c));
    }
  }
  metrics["success_rate_95"] = IntervalJson(WilsonInterval95(m.successes, m.episodes));
  metrics["collision_rate_95"] = IntervalJson(WilsonInterval95(m.collisions, m.episodes));
  metrics["timeout_rate_95"] = IntervalJson(WilsonInterval95(m.timeouts, m.episodes));
  metrics["nav_time_se"] = Number(m.nav_time_se);
  (*j)["metrics"] = std::move(metrics);
  if (const auto& ref = line.Reference()) {
    Json r;
    for (const auto& [key, value] : {std::pair{"success", ref->success},
                                     {"collision", ref->collision},
                                     {"timeout", ref->timeout},
                                     {"nav_time", ref->nav_time},
                                     {"danger", ref->danger}}) {
      if (value) r[key] = Number(*value);
    }
    r["source"] = ref->source;
    (*j)["reference"] = std::move(r);
  }
}

Json SimJson(const SimConfig& sim) {
  Json j = Json::object();
  for (const SimField& f : kSimFields) {
    std::visit([&](auto member) { j[f.key] = sim.*member; }, f.member);
  }
  return j;
}

Json RowJson(const TableRow& line, MetricFamilies social, const RunFacts& facts) {
  const RowSpec& r = *line.spec;
  Json j;
  j["label"] = r.label;
  j["policy"] = PluginJson(r.policy);
  Json sensors = Json::array();
  for (const PluginUse& s : r.sensors) sensors.push_back(PluginJson(s));
  j["sensors"] = std::move(sensors);
  j["world"] = PluginJson(r.world);
  const auto identity = facts.world_identities.find(r.label);
  j["world_identity"] = identity == facts.world_identities.end() ? "" : identity->second;
  j["humans"] = {{"count", r.humans.count},
                 {"goal_mode", r.humans.goal_mode == HumanGoalMode::kStay ? "stay" : "new_goal"},
                 {"policy", PluginJson(r.humans.policy)}};
  // Written only when set, as in the config hash.
  auto range = [&](const char* key, const std::optional<AttributeRange>& a) {
    if (a) j["humans"][key] = a->lo == a->hi ? Json(a->lo) : Json::array({a->lo, a->hi});
  };
  range("radius", r.humans.radius);
  range("v_pref", r.humans.v_pref);
  if (r.humans.distracted > 0.0) j["humans"]["distracted"] = r.humans.distracted;
  if (const auto& g = r.humans.groups) {
    j["humans"]["groups"] = {{"share", g->share},
                             {"size", Json::array({g->size_min, g->size_max})}};
  }
  AddLineTail(line, social, &j);
  return j;
}

}  // namespace

std::string FormatJson(const nlohmann::ordered_json& json) {
  // Labels and paths are the user's bytes: invalid UTF-8 is replaced rather than refused.
  return json.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

std::string FormatManifestJson(const Suite& suite, const std::vector<TableRow>& rows,
                               const RunFacts& facts) {
  Json j;
  j["format"] = "crowdsim-results/1";
  j["suite"] = suite.name;
  j["suite_file"] = suite.file.string();
  if (!suite.overrides.empty()) j["overrides"] = suite.overrides;
  j["description"] = suite.description;
  j["crowdsim_version"] = Version();
  j["git_commit"] = GitCommit();
  j["compiler"] = __VERSION__;
  j["cpu"] = CpuModel();
  j["blas_coretype"] = BlasCoreType();
  j["config_hash"] = suite.ConfigHash();
  // Each row's own hash (HASH LABEL): a later run resumes the rows whose hash is unchanged.
  Json row_hashes = Json::array();
  for (const RowSpec& r : suite.rows) row_hashes.push_back(r.ConfigHash() + " " + r.label);
  j["row_hashes"] = std::move(row_hashes);
  j["seed"] = suite.seed;
  j["episodes"] = facts.episodes;
  if (!facts.shard.empty()) j["shard"] = facts.shard;
  if (facts.merged) j["merged"] = true;
  j["jobs"] = facts.jobs;
  j["isolated"] = facts.isolated;
  j["started_utc"] = facts.started_utc;
  j["finished_utc"] = facts.finished_utc;
  j["wall_seconds"] = Number(facts.wall_seconds);
  j["sim"] = SimJson(suite.sim);
  Json row_lines = Json::array(), summary_lines = Json::array();
  for (const TableRow& line : rows) {
    if (line.spec) {
      row_lines.push_back(RowJson(line, suite.social_metrics, facts));
    } else {
      Json s;
      s["label"] = line.summary->label;
      s["rows"] = line.summary->rows;
      AddLineTail(line, suite.social_metrics, &s);
      summary_lines.push_back(std::move(s));
    }
  }
  j["rows"] = std::move(row_lines);
  if (!summary_lines.empty()) j["summaries"] = std::move(summary_lines);
  return FormatJson(j);
}

nlohmann::ordered_json ReadJsonFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Json::object();
  Json j = Json::parse(in, nullptr, /*allow_exceptions=*/false);
  return j.is_object() ? j : Json::object();
}

namespace {

/// The value at `key` (top-level, or a JSON pointer starting with '/'); null when absent.
const Json& Field(const Json& j, const std::string& key) {
  static const Json kAbsent;
  if (!key.empty() && key.front() == '/') {
    const Json::json_pointer pointer(key);
    return j.contains(pointer) ? j.at(pointer) : kAbsent;
  }
  const auto it = j.find(key);
  return it == j.end() ? kAbsent : *it;
}

}  // namespace

std::string ReadManifestField(const fs::path& path, const std::string& key) {
  const Json j = ReadJsonFile(path);
  const Json& v = Field(j, key);
  return v.is_string() ? v.get<std::string>() : "";
}

std::vector<std::string> ReadManifestStrings(const fs::path& path, const std::string& key) {
  std::vector<std::string> out;
  const Json j = ReadJsonFile(path);
  const Json& v = Field(j, key);
  if (!v.is_array()) return out;
  for (const Json& s : v) {
    if (s.is_string()) out.push_back(s.get<std::string>());
  }
  return out;
}

long ReadManifestInteger(const fs::path& path, const std::string& key) {
  const Json j = ReadJsonFile(path);
  const Json& v = Field(j, key);
  return v.is_number_integer() ? v.get<long>() : -1;
}

std::optional<bool> ReadManifestBool(const fs::path& path, const std::string& key) {
  const Json j = ReadJsonFile(path);
  const Json& v = Field(j, key);
  return v.is_boolean() ? std::optional<bool>(v.get<bool>()) : std::nullopt;
}

std::string DescribeRunInputsDifference(const std::string& suite_a,
                                        const std::vector<std::string>& set_a,
                                        const std::string& suite_b,
                                        const std::vector<std::string>& set_b) {
  std::string text;
  // One file may be recorded under two spellings: differ only if names or targets differ.
  std::error_code ec;
  const fs::path pa(suite_a), pb(suite_b);
  const bool both_found = fs::exists(pa, ec) && fs::exists(pb, ec);
  if (suite_a != suite_b &&
      (pa.filename() != pb.filename() || (both_found && !fs::equivalent(pa, pb, ec)))) {
    text += "; suite files " + suite_a + " and " + suite_b;
  }
  auto joined = [](const std::vector<std::string>& sets) {
    const std::string all = SetOptionsText(sets);
    return all.empty() ? std::string("no --set") : all;
  };
  if (set_a != set_b) text += "; run with " + joined(set_a) + " and with " + joined(set_b);
  return text;
}

std::string SetOptionsText(const std::vector<std::string>& sets) {
  std::string all;
  for (const std::string& s : sets) all += (all.empty() ? "--set " : " --set ") + s;
  return all;
}

std::string ShardName(const std::string& shard) {
  return shard.empty() ? "a whole run" : "shard " + shard;
}

}  // namespace crowdsim
