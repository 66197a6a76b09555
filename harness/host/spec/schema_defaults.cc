#include "spec/schema_defaults.h"

#include "crowdsim/bench/plugin_registry.h"
#include "spec/yaml_file.h"

namespace crowdsim::suite_internal {
namespace fs = std::filesystem;

fs::path SchemaDefaultsFile() { return DataRoot() / "suites" / "schema" / "defaults.yaml"; }

namespace {

/// The text at `section.key`, or "" with an error naming the file, the key and the fix.
std::string Text(const YAML::Node& root, const fs::path& file, const char* section, const char* key,
                 std::vector<SuiteError>* errors) {
  const YAML::Node n = root[section] ? root[section][key] : YAML::Node(YAML::NodeType::Undefined);
  if (n.IsDefined() && n.IsScalar() && !n.Scalar().empty()) return n.Scalar();
  errors->push_back({file.string(), 0, 0, std::string(section) + "." + key,
                     "missing or not a plugin name: the schema defaults need it (restore the "
                     "file from the source tree, or set CROWDSIM_DATA_DIR to the project's root "
                     "folder)"});
  return "";
}

/// The map at `section.key` (empty when absent), or an error when it is not a map.
YAML::Node Map(const YAML::Node& root, const fs::path& file, const char* section, const char* key,
               std::vector<SuiteError>* errors) {
  const YAML::Node n = root[section] ? root[section][key] : YAML::Node(YAML::NodeType::Undefined);
  if (!n.IsDefined() || n.IsNull()) return YAML::Node(YAML::NodeType::Map);
  if (n.IsMap()) return n;
  errors->push_back({file.string(), n.Mark().line + 1, n.Mark().column + 1,
                     std::string(section) + "." + key, "must be a map of parameter: value"});
  return YAML::Node(YAML::NodeType::Map);
}

}  // namespace

std::optional<SchemaDefaults> LoadSchemaDefaults(std::vector<SuiteError>* errors) {
  SchemaDefaults d;
  d.file = SchemaDefaultsFile();
  const size_t before = errors->size();
  const YAML::Node root = LoadYamlFile(d.file, "schema defaults file", errors);
  if (errors->size() != before) {
    for (size_t i = before; i < errors->size(); ++i) {
      (*errors)[i].message +=
          " (every suite and training file needs it: restore "
          "suites/schema/defaults.yaml from the source tree, or set "
          "CROWDSIM_DATA_DIR to the project's root folder)";
    }
    return std::nullopt;
  }
  if (!root.IsMap()) {
    errors->push_back({d.file.string(), 0, 0, "",
                       "the schema defaults are a YAML map with humans "
                       "and training (restore the file from the source tree)"});
    return std::nullopt;
  }
  d.humans_policy = Text(root, d.file, "humans", "policy", errors);
  d.humans_policy_without = Text(root, d.file, "humans", "policy_without_humans", errors);
  d.il_policy = Text(root, d.file, "training", "il_policy", errors);
  d.il_params_robot_invisible = Map(root, d.file, "training", "il_params_robot_invisible", errors);
  d.il_params_robot_visible = Map(root, d.file, "training", "il_params_robot_visible", errors);
  if (errors->size() != before) return std::nullopt;
  return d;
}

}  // namespace crowdsim::suite_internal
