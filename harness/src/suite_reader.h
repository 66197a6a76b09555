// Internal to the core: the YAML reader behind suites, shared by training files
// (harness/src/training/). It collects every error with file:line:col and the key path.
#pragma once

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "crowdsim/params.h"
#include "crowdsim/plugin_registry.h"
#include "crowdsim/sim_config.h"
#include "crowdsim/suite.h"

namespace crowdsim::suite_internal {

namespace fs = std::filesystem;

/// The items separated by `sep` (for lists of valid choices in messages).
inline std::string Join(const std::vector<std::string>& v, const char* sep = ", ") {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? sep : "") + v[i];
  return s;
}

/// True for a node that holds something (a missing key and an explicit null do not).
inline bool Present(const YAML::Node& n) { return n.IsDefined() && !n.IsNull(); }

/// How a node is quoted in messages: the scalar text, or its kind.
inline std::string Scalar(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a map";
  return "nothing";
}

/// Collects errors while walking the suite document.
class Reader {
 public:
  Reader(std::string file, PluginRegistry& registry) : file_(std::move(file)), registry_(registry) {}

  std::vector<SuiteError> errors;

  void Error(const YAML::Node& at, const std::string& path, const std::string& message) {
    SuiteError e;
    e.file = file_;
    const YAML::Mark m = at.Mark();
    if (m.line >= 0) {
      e.line = m.line + 1;
      e.column = m.column + 1;
    }
    e.key_path = path;
    e.message = message;
    errors.push_back(std::move(e));
  }

  /// Unknown keys are errors (a typo never becomes a silent default).
  void CheckKeys(const YAML::Node& map, const std::string& path, const std::vector<std::string>& valid) {
    for (const auto& kv : map) {
      const std::string key = kv.first.Scalar();
      if (std::find(valid.begin(), valid.end(), key) == valid.end()) {
        Error(kv.first, Child(path, key), "unknown key '" + key + "' (valid keys: " + Join(valid) + ")");
      }
    }
  }

  static std::string Child(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }
  static std::string Index(const std::string& path, size_t i) {
    return path + "[" + std::to_string(i) + "]";
  }

  bool IsMap(const YAML::Node& n, const std::string& path, const char* what) {
    if (n.IsMap()) return true;
    Error(n, path, std::string("must be a map (") + what + "), found " + Scalar(n));
    return false;
  }

  std::optional<double> Number(const YAML::Node& n, const std::string& path, double lo, double hi,
                               bool lo_open = false) {
    double v = 0;
    try {
      if (!n.IsScalar()) throw YAML::Exception(n.Mark(), "");
      v = n.as<double>();
    } catch (const YAML::Exception&) {
      Error(n, path, "must be a number, found " + Scalar(n));
      return std::nullopt;
    }
    if (!std::isfinite(v) || v < lo || v > hi || (lo_open && v == lo)) {
      std::ostringstream os;
      os << "value " << n.Scalar() << " is out of range; valid: " << (lo_open ? "(" : "[") << lo
         << ", " << hi << "]";
      Error(n, path, os.str());
      return std::nullopt;
    }
    return v;
  }

  std::optional<std::int64_t> Integer(const YAML::Node& n, const std::string& path,
                                      std::int64_t lo, std::int64_t hi) {
    std::int64_t v = 0;
    try {
      if (!n.IsScalar()) throw YAML::Exception(n.Mark(), "");
      v = n.as<std::int64_t>();
    } catch (const YAML::Exception&) {
      Error(n, path, "must be a whole number, found " + Scalar(n));
      return std::nullopt;
    }
    if (v < lo || v > hi) {
      Error(n, path, "value " + n.Scalar() + " is out of range; valid: [" + std::to_string(lo) +
                         ", " + std::to_string(hi) + "]");
      return std::nullopt;
    }
    return v;
  }

  std::optional<bool> Bool(const YAML::Node& n, const std::string& path) {
    try {
      if (!n.IsScalar()) throw YAML::Exception(n.Mark(), "");
      return n.as<bool>();
    } catch (const YAML::Exception&) {
      Error(n, path, "must be true or false, found " + Scalar(n));
      return std::nullopt;
    }
  }

  std::optional<std::string> String(const YAML::Node& n, const std::string& path) {
    if (!n.IsScalar()) {
      Error(n, path, "must be a text value, found " + Scalar(n));
      return std::nullopt;
    }
    return n.Scalar();
  }

  /// The required top-level `name`, used as a folder name (letters, digits, '_', '-', '.');
  /// `folder` says which folder it names, for the message.
  std::string Name(const YAML::Node& root, const std::string& folder) {
    const YAML::Node n = root["name"];
    if (!n.IsDefined() || n.IsNull()) {
      Error(root, "name", "missing key 'name' (names the output folder " + folder + ")");
      return "";
    }
    auto name = String(n, "name");
    if (!name) return "";
    const bool ok = !name->empty() && std::all_of(name->begin(), name->end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    });
    if (!ok) {
      Error(n, "name", "'" + *name + "' must use only letters, digits, '_', '-', '.'");
    } else if ((*name)[0] == '.') {
      // "." and ".." would write into the results folder itself or its parent.
      Error(n, "name", "'" + *name + "' must not start with '.' (it names the folder " + folder + ")");
    }
    return *name;
  }

  /// Loads a plugin of `kind`; on failure records the error with the choices.
  const LoadedPlugin* Plugin(const YAML::Node& n, const std::string& path, PluginKind kind) {
    auto name = String(n, path);
    if (!name) return nullptr;
    try {
      return &registry_.Load(*name, kind);
    } catch (const PluginError& e) {
      std::string msg = e.what();
      if (msg.starts_with("no plugin named")) {
        msg = "unknown " + std::string(PluginKindName(kind)) + " plugin '" + *name +
              "' (valid: " + Join(Available(kind)) + "; or the path of a plugin .so file)";
      }
      Error(n, path, msg);
      return nullptr;
    }
  }

  std::vector<std::string> Available(PluginKind kind) {
    if (!discovered_) {
      found_ = registry_.Discover();
      discovered_ = true;
    }
    std::vector<std::string> names;
    for (const auto* p : found_.plugins) {
      if (p->descriptor->kind == kind) names.push_back(p->descriptor->name);
    }
    return names;
  }

  /// Validates `node`'s keys (minus `skip`) against the plugin's schema.
  Params ParamsFor(const LoadedPlugin& p, const YAML::Node& node, const std::set<std::string>& skip,
                   const std::string& path, const fs::path& base_dir) {
    std::map<std::string, ParamValue> values;
    for (const auto& spec : p.schema) values[spec.name] = spec.default_value;
    if (Present(node) && node.IsMap()) {
      for (const auto& kv : node) {
        const std::string key = kv.first.Scalar();
        if (skip.count(key)) continue;
        const std::string kpath = Child(path, key);
        auto it = std::find_if(p.schema.begin(), p.schema.end(),
                               [&](const ParamSpec& s) { return s.name == key; });
        if (it == p.schema.end()) {
          std::vector<std::string> names;
          for (const auto& s : p.schema) names.push_back(s.name);
          Error(kv.first, kpath, "unknown parameter '" + key + "' for " +
                                     PluginKindName(p.descriptor->kind) + " plugin '" +
                                     p.descriptor->name + "' (valid: " +
                                     (names.empty() ? std::string("none") : Join(names)) + ")");
          continue;
        }
        if (auto v = Value(*it, kv.second, kpath)) values[key] = *v;
      }
    }
    return Params(std::move(values), base_dir);
  }

  std::optional<ParamValue> Value(const ParamSpec& spec, const YAML::Node& n, const std::string& path) {
    switch (spec.type) {
      case ParamType::kBool:
        if (auto b = Bool(n, path)) return ParamValue(*b);
        return std::nullopt;
      case ParamType::kInt: {
        const auto lo = std::isfinite(spec.min) ? static_cast<std::int64_t>(std::ceil(spec.min))
                                                : std::numeric_limits<std::int64_t>::min();
        const auto hi = std::isfinite(spec.max) ? static_cast<std::int64_t>(std::floor(spec.max))
                                                : std::numeric_limits<std::int64_t>::max();
        if (auto i = Integer(n, path, lo, hi)) return ParamValue(*i);
        return std::nullopt;
      }
      case ParamType::kDouble:
        if (auto d = Number(n, path, spec.min, spec.max)) return ParamValue(*d);
        return std::nullopt;
      case ParamType::kString: {
        auto s = String(n, path);
        if (!s) return std::nullopt;
        if (!spec.choices.empty() &&
            std::find(spec.choices.begin(), spec.choices.end(), *s) == spec.choices.end()) {
          Error(n, path, "value '" + *s + "' is not valid; valid: " + Join(spec.choices));
          return std::nullopt;
        }
        return ParamValue(*s);
      }
      case ParamType::kDoubleList: {
        if (!n.IsSequence()) {
          Error(n, path, "must be a list of numbers, found " + Scalar(n));
          return std::nullopt;
        }
        std::vector<double> list;
        for (size_t i = 0; i < n.size(); ++i) {
          auto d = Number(n[i], Index(path, i), spec.min, spec.max);
          if (!d) return std::nullopt;
          list.push_back(*d);
        }
        return ParamValue(list);
      }
    }
    return std::nullopt;
  }

 private:
  std::string file_;
  PluginRegistry& registry_;
  bool discovered_ = false;
  PluginRegistry::Found found_;
};

/// Reads the `sim:` map into `sim` (unknown keys and out-of-range values are errors).
void ReadSim(Reader& r, const YAML::Node& n, SimConfig* sim);

/// Reads a world map (`source:` plus the world plugin's parameters).
void ReadWorld(Reader& r, const YAML::Node& n, const std::string& path, const fs::path& base,
               PluginUse* out);

/// Reads a sensors list (names or maps with `type:` and parameters).
void ReadSensors(Reader& r, const YAML::Node& n, const std::string& path, const fs::path& base,
                 std::vector<PluginUse>* out);

/// Writes a plugin use (name and every parameter value) into a canonical config text.
void Canonical(const PluginUse& u, std::ostream& os);
/// Appends the canonical text of the simulation settings (one line).
void CanonicalSim(const SimConfig& sim, std::ostream& os);

}  // namespace crowdsim::suite_internal
