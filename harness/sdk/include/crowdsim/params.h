// Typed plugin parameters: the schema a plugin declares and the validated values it receives.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/geometry.h"

namespace crowdsim {

enum class ParamType { kBool, kInt, kDouble, kString, kDoubleList };

using ParamValue = std::variant<bool, std::int64_t, double, std::string, std::vector<double>>;

/// One declared parameter: the host validates suite values against it before the factory runs.
struct CROWDSIM_SDK_API ParamSpec {
  std::string name;
  ParamType type = ParamType::kDouble;
  ParamValue default_value = 0.0;
  double min = -kInfinity;           ///< inclusive, numbers (and list items) only
  double max = kInfinity;            ///< inclusive
  std::vector<std::string> choices;  ///< strings only; empty = free text
  std::string doc;                   ///< one line, with units
  /// False: at its default, the parameter stays out of the config hash, so older results stay
  /// resumable.
  bool hashed_at_default = true;
};

using ParamSchema = std::vector<ParamSpec>;

CROWDSIM_SDK_API const char* ParamTypeName(ParamType t);
/// Human-readable value for messages and tables.
CROWDSIM_SDK_API std::string FormatParamValue(const ParamValue& v);

/// Validated parameter values (every schema entry present, defaults filled in).
class CROWDSIM_SDK_API Params {
 public:
  Params() = default;
  Params(std::map<std::string, ParamValue> values, std::filesystem::path base_dir)
      : values_(std::move(values)), base_dir_(std::move(base_dir)) {}

  bool GetBool(const std::string& name) const;
  std::int64_t GetInt(const std::string& name) const;
  double GetDouble(const std::string& name) const;  ///< ints convert
  const std::string& GetString(const std::string& name) const;
  const std::vector<double>& GetDoubleList(const std::string& name) const;
  bool Has(const std::string& name) const { return values_.count(name) != 0; }
  void Set(const std::string& name, ParamValue v) { values_[name] = std::move(v); }
  const std::map<std::string, ParamValue>& values() const { return values_; }

  /// Folder that relative paths in the values are resolved against (the suite's folder).
  const std::filesystem::path& base_dir() const { return base_dir_; }
  /// Resolves a path: absolute as is, else against base_dir, the working folder, DataRoot(); else
  /// the base_dir path (for errors).
  std::filesystem::path ResolvePath(const std::string& value) const;
  /// Error text for a path ResolvePath found nowhere: "'VALUE' not found (looked in the suite's
  /// folder DIR, the working folder and DATA_ROOT)", or "'VALUE' does not exist".
  std::string MissingFile(const std::string& value) const;

  /// Schema defaults only (for tests and tools).
  static Params Defaults(const ParamSchema& schema, std::filesystem::path base_dir = {});

 private:
  const ParamValue& Get(const std::string& name) const;
  std::map<std::string, ParamValue> values_;
  std::filesystem::path base_dir_;
};

}  // namespace crowdsim
