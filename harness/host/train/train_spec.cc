#include "crowdsim/bench/training/train_spec.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <limits>
#include <sstream>

#include "spec/config_text.h"
#include "spec/human_attributes_reader.h"
#include "spec/kinematics_reader.h"
#include "spec/row_reader.h"
#include "spec/schema_defaults.h"
#include "spec/spec_head_reader.h"
#include "spec/suite_reader.h"
#include "spec/yaml_edit.h"
#include "spec/yaml_file.h"

namespace crowdsim::training {
namespace fs = std::filesystem;
using suite_internal::Present;
using suite_internal::Reader;

std::string TrainSpec::ConfigHash() const { return suite_internal::HashConfigText(canonical); }

namespace {

/// A training file's row: sensors and world required, humans may be a per-episode range.
const suite_internal::RowRules kTrainingRowRules{
    "the policy to train: cadrl or sarl",
    "missing key 'world' (e.g. {source: random_rect, obstacles: 1, split: train})",
    /*sensors_required=*/true, /*humans_range=*/true};

/// The world trains on its train split: `split` defaults to train, test is refused.
void UseTrainSplit(Reader& r, const YAML::Node& n, PluginUse* world) {
  if (!world->loaded || !world->params.Has("split")) return;
  if (!Present(n["split"])) {
    world->params.Set("split", std::string("train"));
  } else if (world->params.GetString("split") != "train") {
    r.Error(
        n["split"], "world.split",
        "training uses the world's train split (the test split is for suites); set split: train");
  }
}

// A one-of-a-few-words `training:` key: sets *out or reports the valid words.
template <typename E>
void ReadChoice(Reader& r, const YAML::Node& training, const std::string& key,
                const std::vector<std::pair<std::string, E>>& choices, E* out) {
  const YAML::Node node = training[key];
  if (!Present(node)) return;
  const std::string v = node.IsScalar() ? node.Scalar() : "";
  std::string expected;
  for (size_t i = 0; i < choices.size(); ++i) {
    if (choices[i].first == v) {
      *out = choices[i].second;
      return;
    }
    expected += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i].first;
  }
  r.Error(node, "training." + key,
          "expected " + expected + ", got " + suite_internal::Scalar(node));
}

/// Teacher parameters from schema defaults unless `il_params` sets them (CrowdNav: more clearance).
void DefaultTeacherParams(Reader& r, const YAML::Node& given,
                          const suite_internal::SchemaDefaults& schema, TrainSpec* s) {
  const YAML::Node& defaults =
      s->sim.robot_visible ? schema.il_params_robot_visible : schema.il_params_robot_invisible;
  const auto& specs = s->teacher.loaded->schema;
  for (const auto& kv : defaults) {
    const std::string key = kv.first.Scalar();
    if (Present(given) && given.IsMap() && Present(given[key])) continue;
    const auto spec =
        std::find_if(specs.begin(), specs.end(), [&](const ParamSpec& p) { return p.name == key; });
    if (spec == specs.end()) continue;
    // A node without the defaults file's marks: an error names the key and that file.
    const YAML::Node value =
        kv.second.IsScalar() ? YAML::Node(kv.second.Scalar()) : YAML::Node(kv.second);
    const std::string path =
        "training.il_params." + key + " (default, " + schema.file.string() + ")";
    if (auto v = r.Value(*spec, value, path)) s->teacher.params.Set(key, *v);
  }
}

void ReadTraining(Reader& r, const YAML::Node& n, const suite_internal::SchemaDefaults& schema,
                  const fs::path& base, TrainSpec* s) {
  TrainingSettings& t = s->training;
  struct IntField {
    const char* key;
    int* target;
    int lo, hi;
  };
  struct RealField {
    const char* key;
    double* target;
    double lo, hi;
  };
  const std::vector<IntField> ints = {
      {"il_episodes", &t.il_episodes, 0, 10'000'000},
      {"il_epochs", &t.il_epochs, 0, 100'000},
      {"rl_episodes", &t.rl_episodes, 0, 10'000'000},
      {"epsilon_decay_episodes", &t.epsilon_decay_episodes, 0, 10'000'000},
      {"target_update_interval", &t.target_update_interval, 1, 10'000'000},
      {"capacity", &t.capacity, 1, 100'000'000},
      {"batch_size", &t.batch_size, 1, 1'000'000},
      {"train_batches", &t.train_batches, 0, 1'000'000},
      {"validation_interval", &t.validation_interval, 0, 10'000'000},
      {"validation_episodes", &t.validation_episodes, 0, 1'000'000},
      {"checkpoint_interval", &t.checkpoint_interval, 1, 10'000'000},
  };
  const std::vector<RealField> reals = {
      {"il_learning_rate", &t.il_learning_rate, 0.0, 10.0},
      {"rl_learning_rate", &t.rl_learning_rate, 0.0, 10.0},
      {"momentum", &t.momentum, 0.0, 1.0},
      {"epsilon_start", &t.epsilon_start, 0.0, 1.0},
      {"epsilon_end", &t.epsilon_end, 0.0, 1.0},
  };
  std::vector<std::string> keys = {"il_policy", "il_params", "store_timeouts", "exploration"};
  for (const auto& f : ints) keys.push_back(f.key);
  for (const auto& f : reals) keys.push_back(f.key);
  const bool map = Present(n) && r.IsMap(n, "training", "imitation and RL settings");
  if (map) {
    r.CheckKeys(n, "training", keys);
    for (const auto& f : ints) {
      if (Present(n[f.key])) {
        if (auto v = r.Integer(n[f.key], Reader::Child("training", f.key), f.lo, f.hi))
          *f.target = static_cast<int>(*v);
      }
    }
    for (const auto& f : reals) {
      if (Present(n[f.key])) {
        if (auto v = r.Number(n[f.key], Reader::Child("training", f.key), f.lo, f.hi))
          *f.target = *v;
      }
    }
    ReadChoice(r, n, "store_timeouts",
               {{"off", StoreTimeouts::kOff},
                {"terminal", StoreTimeouts::kTerminal},
                {"bootstrap", StoreTimeouts::kBootstrap}},
               &t.store_timeouts);
    ReadChoice(r, n, "exploration",
               {{"uniform", ExplorationRule::kUniform},
                {"collision_free", ExplorationRule::kCollisionFree}},
               &t.exploration);
    if (t.validation_interval > 0 && t.validation_episodes == 0) {
      // Validations of no episode: every one "success 0 (best so far)".
      r.Error(Present(n["validation_episodes"]) ? n["validation_episodes"] : n,
              "training.validation_episodes",
              "0 episodes validate nothing every " + std::to_string(t.validation_interval) +
                  " RL episodes: give at least 1, or validation_interval: 0 for no validation");
    }
  }
  const bool named = map && Present(n["il_policy"]);
  const YAML::Node teacher = named ? n["il_policy"] : YAML::Node(schema.il_policy);
  const std::string teacher_path =
      named ? "training.il_policy" : "training.il_policy (default, " + schema.file.string() + ")";
  const YAML::Node teacher_params = map ? n["il_params"] : YAML::Node(YAML::NodeType::Undefined);
  if (Present(teacher_params) &&
      !r.IsMap(teacher_params, "training.il_params", "policy parameters"))
    return;
  s->teacher.plugin = teacher.Scalar();
  s->teacher.loaded = r.Plugin(teacher, teacher_path, PluginKind::kPolicy);
  if (!s->teacher.loaded) return;
  s->teacher.params =
      r.ParamsFor(*s->teacher.loaded, teacher_params, {}, "training.il_params", base);
  DefaultTeacherParams(r, teacher_params, schema, s);
}

std::string Canonical(const TrainSpec& s) {
  const RowSpec& row = s.row;
  std::ostringstream os;
  os << "seed=" << s.seed << "\n";
  suite_internal::CanonicalSim(s.sim, os);
  os << "policy:";
  suite_internal::Canonical(row.policy, os);
  os << "\nsensors:";
  for (const auto& sen : row.sensors) suite_internal::Canonical(sen, os);
  suite_internal::CanonicalKinematics(row.kinematics, os);
  os << "\nworld:";
  suite_internal::Canonical(row.world, os);
  os << "\nhumans:" << row.humans.count << "-" << row.humans.count_max << ",";
  // Written only when not the default, so existing trainings' hashes stay valid.
  if (row.humans.goal_mode != HumanGoalMode::kStay) os << "goal_mode=new_goal,";
  suite_internal::CanonicalHumanAttributes(row.humans, os);
  suite_internal::Canonical(row.humans.policy, os);
  os << "\nteacher:";
  suite_internal::Canonical(s.teacher, os);
  const TrainingSettings& t = s.training;
  // In the order of kTrainingLineFields (train_spec.h), which names them in messages.
  // Numbers exactly (FormatParamValue), as parameters and sim settings are.
  os << "\ntraining:" << t.il_episodes << "," << t.il_epochs << ","
     << FormatParamValue(t.il_learning_rate) << "," << t.rl_episodes << ","
     << FormatParamValue(t.rl_learning_rate) << "," << FormatParamValue(t.momentum) << ","
     << FormatParamValue(t.epsilon_start) << "," << FormatParamValue(t.epsilon_end) << ","
     << t.epsilon_decay_episodes << "," << t.target_update_interval << "," << t.capacity << ","
     << t.batch_size << "," << t.train_batches << "," << t.validation_interval << ","
     << t.validation_episodes << ",store_timeouts=" << ToString(t.store_timeouts);
  // Written only when not the default, so existing trainings' hashes stay valid.
  if (t.exploration != ExplorationRule::kUniform) os << ",exploration=" << ToString(t.exploration);
  os << "\n";
  return os.str();
}

}  // namespace

const char* ToString(ExplorationRule e) {
  return e == ExplorationRule::kCollisionFree ? "collision_free" : "uniform";
}

const char* ToString(StoreTimeouts s) {
  switch (s) {
    case StoreTimeouts::kTerminal:
      return "terminal";
    case StoreTimeouts::kBootstrap:
      return "bootstrap";
    case StoreTimeouts::kOff:
      break;
  }
  return "off";
}

std::string TrainSpec::ConfigHashWithRlEpisodes(int rl_episodes) const {
  TrainSpec other = *this;
  other.training.rl_episodes = rl_episodes;
  other.canonical = Canonical(other);
  return other.ConfigHash();
}

void OverrideSeed(TrainSpec& spec, std::uint64_t seed) {
  spec.seed = seed;
  spec.canonical = Canonical(spec);
}

std::vector<std::string> TrainSpecWarnings(const TrainSpec& spec) {
  std::vector<std::string> w;
  const TrainingSettings& t = spec.training;
  if (t.rl_episodes > 0 && t.epsilon_decay_episodes > t.rl_episodes &&
      t.epsilon_start != t.epsilon_end) {
    w.push_back("training.epsilon_decay_episodes (" + std::to_string(t.epsilon_decay_episodes) +
                ") exceeds rl_episodes (" + std::to_string(t.rl_episodes) +
                "): epsilon never reaches " +
                "epsilon_end; shorten the decay or lengthen the RL phase");
  }
  if (t.rl_episodes > 0 && t.epsilon_end >= 0.3 && t.store_timeouts == StoreTimeouts::kOff) {
    w.push_back("exploration stays at epsilon >= " + std::to_string(t.epsilon_end).substr(0, 4) +
                " and timeout episodes are not stored: the RL phase is known to make models worse "
                "than their imitation start this way (docs/training.md)");
  }
  return w;
}

TrainSpecLoadResult LoadTrainSpec(const fs::path& file, PluginRegistry& registry,
                                  const std::vector<std::string>& overrides) {
  TrainSpecLoadResult result;
  std::vector<std::string> set_paths;  // each --set's path, list items by index
  YAML::Node root = suite_internal::LoadYamlFile(file, "training file", &result.errors);
  if (!result.errors.empty()) return result;
  if (root.IsMap()) {
    suite_internal::ApplyOverrides(root, overrides, &result.errors, &set_paths);
    if (!result.errors.empty()) return result;
  }
  if (!root.IsMap()) {
    result.errors.push_back(
        {file.string(), 0, 0, "",
         "a training file is a YAML map with name, policy, sensors, world, humans and training"});
    return result;
  }
  const std::optional<suite_internal::SchemaDefaults> schema =
      suite_internal::LoadSchemaDefaults(&result.errors);
  if (!schema) return result;
  Reader r(file.string(), registry);
  TrainSpec s;
  s.file = file;
  const fs::path base = file.has_parent_path() ? file.parent_path() : fs::path(".");
  std::vector<std::string> keys = suite_internal::kSpecHeadKeys;
  keys.insert(keys.end(), suite_internal::kRowSpecKeys.begin(), suite_internal::kRowSpecKeys.end());
  keys.push_back("training");
  r.CheckKeys(root, "", keys);
  suite_internal::SpecHead head = suite_internal::ReadSpecHead(r, root, "results/train/<name>/");
  s.name = std::move(head.name);
  s.description = std::move(head.description);
  s.seed = head.seed;
  s.sim = head.sim;
  suite_internal::ReadRowSpec(r, root, "", suite_internal::RowDefaults{*schema}, kTrainingRowRules,
                              base, &s.row);
  s.row.label = s.name;
  UseTrainSplit(r, root["world"], &s.row.world);
  ReadTraining(r, root["training"], *schema, base, &s);
  if (!r.errors.empty()) {
    suite_internal::LocateOverrideErrors(overrides, &r.errors, set_paths);
    result.errors = std::move(r.errors);
    return result;
  }
  s.canonical = Canonical(s);
  result.spec = std::move(s);
  return result;
}

}  // namespace crowdsim::training
