#include "spec/row_reader.h"

#include <algorithm>

#include "spec/human_attributes_reader.h"
#include "spec/kinematics_reader.h"

namespace crowdsim::suite_internal {
namespace fs = std::filesystem;

namespace {

constexpr int kMaxHumans = 10000;

/// `count: N`, or where the rules allow it `count: [min, max]`.
void ReadHumanCount(Reader& r, const YAML::Node& n, const std::string& path, bool range,
                    HumansSpec* out) {
  if (range && n.IsSequence()) {
    if (n.size() != 2) {
      r.Error(n, path, "a range is a list of two counts [min, max]");
      return;
    }
    const auto lo = r.Integer(n[0], Reader::Index(path, 0), 0, kMaxHumans);
    const auto hi = r.Integer(n[1], Reader::Index(path, 1), 0, kMaxHumans);
    if (!lo || !hi) return;
    if (*lo > *hi) {
      r.Error(n, path, "min is larger than max");
      return;
    }
    out->count = static_cast<int>(*lo);
    out->count_max = static_cast<int>(*hi);
    return;
  }
  if (n.IsSequence()) {
    r.Error(n, path,
            "a range of counts is for training files (drawn per episode); a suite row "
            "runs one count: give one number, or `sweep: {humans.count: [...]}` for a "
            "row per count");
    return;
  }
  if (auto c = r.Integer(n, path, 0, kMaxHumans))
    out->count = out->count_max = static_cast<int>(*c);
}

void ReadHumans(Reader& r, const YAML::Node& file_level, const YAML::Node& row_level,
                const std::string& path, const RowRules& rules, const SchemaDefaults& schema,
                const fs::path& base, HumansSpec* out) {
  // Row keys override the file's keys one by one.
  auto pick = [&](const char* key) -> std::pair<YAML::Node, std::string> {
    if (Present(row_level) && row_level.IsMap() && Present(row_level[key]))
      return {row_level[key], Reader::Child(path, key)};
    if (Present(file_level) && file_level.IsMap() && Present(file_level[key]))
      return {file_level[key], Reader::Child("humans", key)};
    return {YAML::Node(YAML::NodeType::Undefined), ""};
  };
  if (Present(row_level)) {
    if (r.IsMap(row_level, path, kHumansWhat)) r.CheckKeys(row_level, path, kHumansKeys);
  }
  if (auto [n, p] = pick("count"); Present(n)) ReadHumanCount(r, n, p, rules.humans_range, out);
  if (auto [n, p] = pick("goal_mode"); Present(n)) {
    if (auto s = r.String(n, p)) {
      if (*s == "stay")
        out->goal_mode = HumanGoalMode::kStay;
      else if (*s == "new_goal")
        out->goal_mode = HumanGoalMode::kNewGoal;
      else
        r.Error(n, p, "value '" + *s + "' is not valid; valid: stay, new_goal");
    }
  }
  ReadHumanAttributes(r, pick, out);
  auto [pn, pp] = pick("policy");
  const YAML::Node policy_node =
      Present(pn)
          ? pn
          : YAML::Node(out->count_max > 0 ? schema.humans_policy : schema.humans_policy_without);
  const std::string policy_path =
      Present(pn) ? pp : "humans.policy (default, " + schema.file.string() + ")";
  out->policy.plugin = policy_node.Scalar();
  out->policy.loaded = r.Plugin(policy_node, policy_path, PluginKind::kPolicy);
  auto [params, params_path] = pick("params");
  if (Present(params) && !r.IsMap(params, params_path, "policy parameters")) return;
  if (out->policy.loaded)
    out->policy.params = r.ParamsFor(*out->policy.loaded, params, {}, params_path, base);
}

/// The robot policy, its `params` and `weights` (a shorthand for params.weights).
void ReadRobotPolicy(Reader& r, const YAML::Node& n, const std::string& path, const RowRules& rules,
                     const fs::path& base, PluginUse* policy) {
  if (!Present(n["policy"])) {
    r.Error(n, Reader::Child(path, "policy"), "missing key 'policy' (" + rules.policy_hint + ")");
    return;
  }
  policy->plugin = n["policy"].Scalar();
  policy->loaded = r.Plugin(n["policy"], Reader::Child(path, "policy"), PluginKind::kPolicy);
  const std::string params_path = Reader::Child(path, "params");
  if (n["params"] && !r.IsMap(n["params"], params_path, "policy parameters")) return;
  if (!policy->loaded) return;
  policy->params = r.ParamsFor(*policy->loaded, n["params"], {}, params_path, base);
  if (!n["weights"]) return;
  const std::string weights_path = Reader::Child(path, "weights");
  if (!policy->params.Has("weights")) {
    r.Error(n["weights"], weights_path,
            "policy '" + policy->plugin + "' takes no weights (it has no 'weights' parameter)");
  } else if (auto w = r.String(n["weights"], weights_path)) {
    policy->params.Set("weights", *w);
  }
}

}  // namespace

void ReadRowSpec(Reader& r, const YAML::Node& n, const std::string& path, const RowDefaults& d,
                 const RowRules& rules, const fs::path& base, RowSpec* row) {
  ReadRobotPolicy(r, n, path, rules, base, &row->policy);
  // A row's `sensors`, even an empty one, replaces the file's.
  const YAML::Node sensors = n["sensors"] ? n["sensors"] : d.sensors;
  if (Present(sensors)) {
    ReadSensors(r, sensors, n["sensors"] ? Reader::Child(path, "sensors") : "robot.sensors", base,
                &row->sensors);
  } else if (rules.sensors_required) {
    r.Error(n, Reader::Child(path, "sensors"),
            "missing key 'sensors' (e.g. [person, {type: lidar2d, beams: 45}])");
  }
  if (Present(n["kinematics"])) {
    ReadKinematics(r, n["kinematics"], Reader::Child(path, "kinematics"), &row->kinematics);
  } else if (Present(d.kinematics)) {
    ReadKinematics(r, d.kinematics, "robot.kinematics", &row->kinematics);
  }
  if (n["world"]) {
    ReadWorld(r, n["world"], Reader::Child(path, "world"), base, &row->world);
  } else if (Present(d.world)) {
    ReadWorld(r, d.world, "world", base, &row->world);
  } else {
    r.Error(n, Reader::Child(path, "world"), rules.missing_world);
  }
  ReadHumans(r, d.humans, n["humans"], Reader::Child(path, "humans"), rules, d.schema, base,
             &row->humans);
}

void ReadWorld(Reader& r, const YAML::Node& n, const std::string& path, const fs::path& base,
               PluginUse* out) {
  if (!r.IsMap(n, path, "source: <world plugin> and its parameters")) return;
  if (!n["source"]) {
    r.Error(n, path,
            "missing key 'source' (the world plugin, e.g. random_rect, floorplan, crowdnav)");
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
      r.Error(item, p,
              "a sensor is a plugin name (person) or a map with 'type' and its parameters");
      continue;
    }
    use.plugin = type_node.Scalar();
    use.loaded =
        r.Plugin(type_node, item.IsMap() ? Reader::Child(p, "type") : p, PluginKind::kSensor);
    // Readings are named by plugin: a second sensor of one plugin would never be read.
    const auto same = std::find_if(out->begin(), out->end(), [&](const PluginUse& earlier) {
      return use.loaded && earlier.loaded &&
             std::string(earlier.loaded->descriptor->name) == use.loaded->descriptor->name;
    });
    if (same != out->end()) {
      r.Error(type_node, item.IsMap() ? Reader::Child(p, "type") : p,
              "a second '" + std::string(use.loaded->descriptor->name) +
                  "' sensor: readings are named by their sensor, so only the first would ever "
                  "be read; keep one");
    }
    if (use.loaded)
      use.params =
          r.ParamsFor(*use.loaded, item.IsMap() ? item : YAML::Node(YAML::NodeType::Undefined),
                      {"type"}, p, base);
    out->push_back(std::move(use));
  }
}

}  // namespace crowdsim::suite_internal
