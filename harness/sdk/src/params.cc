#include "crowdsim/params.h"

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "crowdsim/data_root.h"

namespace crowdsim {

const char* ParamTypeName(ParamType t) {
  switch (t) {
    case ParamType::kBool:
      return "bool";
    case ParamType::kInt:
      return "int";
    case ParamType::kDouble:
      return "number";
    case ParamType::kString:
      return "string";
    case ParamType::kDoubleList:
      return "list of numbers";
  }
  return "unknown";
}

namespace {

// A number as six significant digits where they give it back exactly, else as 17, which
// always do: two values that differ never print alike (config hashes tell them apart), and a
// value written with up to six digits prints as it always has.
std::string ExactNumber(double x) {
  char six[32];
  std::snprintf(six, sizeof(six), "%g", x);
  if (std::strtod(six, nullptr) == x || x != x) return six;
  char all[32];
  std::snprintf(all, sizeof(all), "%.17g", x);
  return all;
}

}  // namespace

std::string FormatParamValue(const ParamValue& v) {
  std::ostringstream os;
  std::visit(
      [&os](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, bool>) {
          os << (x ? "true" : "false");
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          os << "[";
          for (size_t i = 0; i < x.size(); ++i) os << (i ? ", " : "") << ExactNumber(x[i]);
          os << "]";
        } else if constexpr (std::is_same_v<T, double>) {
          os << ExactNumber(x);
        } else {
          os << x;
        }
      },
      v);
  return os.str();
}

const ParamValue& Params::Get(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end()) {
    throw std::out_of_range("parameter '" + name + "' is not in the plugin's schema");
  }
  return it->second;
}

bool Params::GetBool(const std::string& name) const { return std::get<bool>(Get(name)); }

std::int64_t Params::GetInt(const std::string& name) const {
  return std::get<std::int64_t>(Get(name));
}

double Params::GetDouble(const std::string& name) const {
  const ParamValue& v = Get(name);
  if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  return std::get<double>(v);
}

const std::string& Params::GetString(const std::string& name) const {
  return std::get<std::string>(Get(name));
}

const std::vector<double>& Params::GetDoubleList(const std::string& name) const {
  return std::get<std::vector<double>>(Get(name));
}

std::filesystem::path Params::ResolvePath(const std::string& value) const {
  std::filesystem::path p(value);
  if (p.is_absolute()) return p;
  if (base_dir_.empty() || std::filesystem::exists(base_dir_ / p)) return base_dir_ / p;
  if (std::filesystem::exists(p)) return p;
  // The data root: installed suites name shipped weights and worlds relative to it.
  if (const std::filesystem::path in_data = DataRoot() / p; std::filesystem::exists(in_data))
    return in_data;
  // In no place: the suite-folder path, so that a "does not exist" names where it looked.
  return base_dir_ / p;
}

std::string Params::MissingFile(const std::string& value) const {
  const std::filesystem::path p(value);
  if (p.is_absolute()) return "'" + value + "' does not exist";
  std::string places;
  if (base_dir_.empty()) {
    places = "the working folder";  // no suite folder: ResolvePath looks only there
  } else if (base_dir_ == ".") {
    places = "the suite's folder (the working folder) and " + DataRoot().string();
  } else {
    places = "the suite's folder " + base_dir_.string() + ", the working folder and " +
             DataRoot().string();
  }
  return "'" + value + "' not found (looked in " + places + ")";
}

Params Params::Defaults(const ParamSchema& schema, std::filesystem::path base_dir) {
  std::map<std::string, ParamValue> values;
  for (const auto& spec : schema) values[spec.name] = spec.default_value;
  return Params(std::move(values), std::move(base_dir));
}

}  // namespace crowdsim
