// Internal: the YAML reader of specs and world parameters, collecting every error (file:line:col,
// key path) to report all at once.
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/bench/suite.h"
#include "crowdsim/params.h"

namespace crowdsim::suite_internal {

/// The items separated by `sep` (for lists of valid choices in messages).
std::string Join(const std::vector<std::string>& v, const char* sep = ", ");

/// True for a node that holds something (a missing key and an explicit null do not).
inline bool Present(const YAML::Node& n) { return n.IsDefined() && !n.IsNull(); }

/// How a node is quoted in messages: the scalar text, or its kind.
std::string Scalar(const YAML::Node& n);

/// Collects errors while walking a spec document.
class Reader {
 public:
  Reader(std::string file, PluginRegistry& registry)
      : file_(std::move(file)), registry_(registry) {}

  std::vector<SuiteError> errors;

  void Error(const YAML::Node& at, const std::string& path, const std::string& message);

  /// Unknown keys are errors (a typo never becomes a silent default).
  void CheckKeys(const YAML::Node& map, const std::string& path,
                 const std::vector<std::string>& valid);

  static std::string Child(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }
  static std::string Index(const std::string& path, size_t i) {
    return path + "[" + std::to_string(i) + "]";
  }

  bool IsMap(const YAML::Node& n, const std::string& path, const char* what);

  std::optional<double> Number(const YAML::Node& n, const std::string& path, double lo, double hi,
                               bool lo_open = false);
  std::optional<std::int64_t> Integer(const YAML::Node& n, const std::string& path, std::int64_t lo,
                                      std::int64_t hi);
  std::optional<bool> Bool(const YAML::Node& n, const std::string& path);
  std::optional<std::string> String(const YAML::Node& n, const std::string& path);

  /// The required top-level `name`, a folder name (letters, digits, '_', '-', '.'); `folder`: which
  /// folder, for messages.
  std::string Name(const YAML::Node& root, const std::string& folder);

  /// Loads a plugin of `kind`; on failure records the error with the choices.
  const LoadedPlugin* Plugin(const YAML::Node& n, const std::string& path, PluginKind kind);

  /// Validates `node`'s keys (minus `skip`) against the plugin's schema.
  Params ParamsFor(const LoadedPlugin& p, const YAML::Node& node, const std::set<std::string>& skip,
                   const std::string& path, const std::filesystem::path& base_dir);

  /// One parameter value checked against its spec (type, range, choices).
  std::optional<ParamValue> Value(const ParamSpec& spec, const YAML::Node& n,
                                  const std::string& path);

 private:
  std::vector<std::string> Available(PluginKind kind);
  /// Where a plugin name is looked for, and how a folder of yours is searched too.
  std::string NotSearchedHint(const std::string& name) const;

  std::string file_;
  PluginRegistry& registry_;
  bool discovered_ = false;
  PluginRegistry::Found found_;
};

}  // namespace crowdsim::suite_internal
