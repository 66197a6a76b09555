#include "spec/suite_reader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <sstream>

#include "crowdsim/bench/closest_name.h"
#include "loader/shipped_plugins.h"

namespace crowdsim::suite_internal {

namespace fs = std::filesystem;

std::string Join(const std::vector<std::string>& v, const char* sep) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) {
    if (i) s += sep;
    s += v[i];
  }
  return s;
}

std::string Scalar(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsSequence()) return "a list";
  if (n.IsMap()) return "a map";
  return "nothing";
}

void Reader::Error(const YAML::Node& at, const std::string& path, const std::string& message) {
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

void Reader::CheckKeys(const YAML::Node& map, const std::string& path,
                       const std::vector<std::string>& valid) {
  for (const auto& kv : map) {
    const std::string key = kv.first.Scalar();
    if (std::find(valid.begin(), valid.end(), key) == valid.end()) {
      Error(kv.first, Child(path, key),
            "unknown key '" + key + "' (valid keys: " + Join(valid) + ")" + DidYouMean(key, valid));
    }
  }
}

bool Reader::IsMap(const YAML::Node& n, const std::string& path, const char* what) {
  if (n.IsMap()) return true;
  Error(n, path, std::string("must be a map (") + what + "), found " + Scalar(n));
  return false;
}

namespace {

// Whether a scalar is wholly a number (any strtod notation; overflow: +-inf), and its value;
// `underflow`: below a double (1e-400).
bool WrittenAsNumber(const YAML::Node& n, double* value, bool* underflow = nullptr) {
  if (!n.IsScalar() || n.Scalar().empty()) return false;
  const std::string& text = n.Scalar();
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || std::isnan(v)) return false;
  const bool out_of_range = errno == ERANGE;
  *value = out_of_range && std::abs(v) > 1.0 ? std::copysign(HUGE_VAL, v) : v;
  if (underflow != nullptr) *underflow = out_of_range && std::abs(v) <= 1.0;
  return true;
}

}  // namespace

std::optional<double> Reader::Number(const YAML::Node& n, const std::string& path, double lo,
                                     double hi, bool lo_open) {
  double v = 0;
  try {
    if (!n.IsScalar()) throw YAML::Exception(n.Mark(), "");
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    // A number beyond a double (1e400) is out of range, not "not a number".
    if (!WrittenAsNumber(n, &v)) {
      Error(n, path, "must be a number, found " + Scalar(n));
      return std::nullopt;
    }
  }
  if (!std::isfinite(v) || v < lo || v > hi || (lo_open && v == lo)) {
    // An infinite bound is open: inf itself is never valid.
    std::ostringstream os;
    os << "value " << n.Scalar()
       << " is out of range; valid: " << (lo_open || std::isinf(lo) ? "(" : "[") << lo << ", " << hi
       << (std::isinf(hi) ? ")" : "]");
    Error(n, path, os.str());
    return std::nullopt;
  }
  return v;
}

std::optional<std::int64_t> Reader::Integer(const YAML::Node& n, const std::string& path,
                                            std::int64_t lo, std::int64_t hi) {
  std::int64_t v = 0;
  try {
    if (!n.IsScalar()) throw YAML::Exception(n.Mark(), "");
    v = n.as<std::int64_t>();
  } catch (const YAML::Exception&) {
    // A whole number in another notation (1e3) counts; beyond 64 bits it is out of range.
    double d = 0;
    bool underflow = false;
    if (!WrittenAsNumber(n, &d, &underflow) || underflow ||
        (std::isfinite(d) && d != std::floor(d))) {
      Error(n, path, "must be a whole number, found " + Scalar(n));
      return std::nullopt;
    }
    // [-2^63, 2^63): the doubles that convert to an int64_t.
    if (!std::isfinite(d) || d < -9223372036854775808.0 || d >= 9223372036854775808.0) {
      Error(n, path,
            "value " + n.Scalar() + " is out of range; valid: [" + std::to_string(lo) + ", " +
                std::to_string(hi) + "]");
      return std::nullopt;
    }
    v = static_cast<std::int64_t>(d);
  }
  if (v < lo || v > hi) {
    Error(n, path,
          "value " + n.Scalar() + " is out of range; valid: [" + std::to_string(lo) + ", " +
              std::to_string(hi) + "]");
    return std::nullopt;
  }
  return v;
}

std::optional<bool> Reader::Bool(const YAML::Node& n, const std::string& path) {
  try {
    if (!n.IsScalar()) throw YAML::Exception(n.Mark(), "");
    return n.as<bool>();
  } catch (const YAML::Exception&) {
    Error(n, path, "must be true or false, found " + Scalar(n));
    return std::nullopt;
  }
}

std::optional<std::string> Reader::String(const YAML::Node& n, const std::string& path) {
  if (!n.IsScalar()) {
    Error(n, path, "must be a text value, found " + Scalar(n));
    return std::nullopt;
  }
  return n.Scalar();
}

std::string Reader::Name(const YAML::Node& root, const std::string& folder) {
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
    Error(n, "name",
          "'" + *name + "' must not start with '.' (it names the folder " + folder + ")");
  }
  return *name;
}

const LoadedPlugin* Reader::Plugin(const YAML::Node& n, const std::string& path, PluginKind kind) {
  auto name = String(n, path);
  if (!name) return nullptr;
  std::string name_or_path = *name;
  // A relative .so path missing from the working folder is the suite folder's, as in
  // Params::ResolvePath.
  const std::filesystem::path given(*name);
  std::error_code ec;
  if ((name->find('/') != std::string::npos || name->ends_with(".so")) && given.is_relative() &&
      !std::filesystem::exists(given, ec)) {
    const std::filesystem::path beside = std::filesystem::path(file_).parent_path() / given;
    if (std::filesystem::exists(beside, ec)) name_or_path = beside.string();
  }
  try {
    return &registry_.Load(name_or_path, kind);
  } catch (const PluginError& e) {
    std::string msg = e.what();
    if (msg.starts_with("no plugin named")) {
      const std::vector<std::string> available = Available(kind);
      const std::string close = DidYouMean(*name, available);
      msg = "unknown " + std::string(PluginKindName(kind)) + " plugin '" + *name +
            "' (valid: " + Join(available) + "; or the path of a plugin .so file)" + close;
      // One of ours this build lacks (learned policies without libtorch), else likely a user plugin
      // in an unsearched folder.
      if (const std::string_view why = LeftOutPluginReason(*name); !why.empty()) {
        msg += "; '" + *name +
               "' is one of crowdsim-bench's own plugins, not in this build: " + std::string(why);
      } else if (close.empty()) {
        msg += "; " + NotSearchedHint(*name);
      }
      // A file that calls itself by this name but is named otherwise is not found by it.
      for (const std::string& problem : found_.problems) {
        if (problem.find("its descriptor calls it '" + *name + "'") != std::string::npos) {
          msg += "; " + problem;
        }
      }
    } else if (msg.find("' does not exist. Give the path") != std::string::npos &&
               given.is_relative()) {
      // A suite named without a folder (`run suite.yaml`) lies in the working folder.
      const std::filesystem::path suite_folder = std::filesystem::path(file_).parent_path();
      msg += suite_folder.empty()
                 ? " (looked from the working folder, which holds the suite)"
                 : " (looked from the working folder and from the suite's folder, " +
                       suite_folder.string() + ")";
    }
    Error(n, path, msg);
    return nullptr;
  }
}

std::string Reader::NotSearchedHint(const std::string& name) const {
  std::vector<std::string> folders;
  for (const auto& dir : registry_.search_dirs()) folders.push_back(dir.string());
  return "looked for crowdsim_" + name + ".so in " + Join(folders) +
         ": put the folder of a plugin you built on CROWDSIM_PLUGIN_PATH (':'-separated)";
}

std::vector<std::string> Reader::Available(PluginKind kind) {
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

Params Reader::ParamsFor(const LoadedPlugin& p, const YAML::Node& node,
                         const std::set<std::string>& skip, const std::string& path,
                         const fs::path& base_dir) {
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
        Error(kv.first, kpath,
              "unknown parameter '" + key + "' for " + PluginKindName(p.descriptor->kind) +
                  " plugin '" + p.descriptor->name +
                  "' (valid: " + (names.empty() ? std::string("none") : Join(names)) + ")" +
                  DidYouMean(key, names));
        continue;
      }
      if (auto v = Value(*it, kv.second, kpath)) values[key] = *v;
    }
  }
  return Params(std::move(values), base_dir);
}

std::optional<ParamValue> Reader::Value(const ParamSpec& spec, const YAML::Node& n,
                                        const std::string& path) {
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

}  // namespace crowdsim::suite_internal
