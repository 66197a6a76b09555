#include "crowdsim/cli/args.h"

#include <algorithm>
#include <filesystem>

namespace crowdsim::cli {

Args Args::Parse(const std::vector<std::string>& args, const std::vector<std::string>& with_value,
                 const std::vector<std::string>& flags) {
  auto valid = [&] {
    std::string names;
    for (const auto& o : with_value) names += " " + o;
    for (const auto& o : flags) names += " " + o;
    return "(valid:" + (names.empty() ? std::string(" none") : names) + ")";
  };
  Args a;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& s = args[i];
    // A short option (-j 2, -o DIR) was taken for a file name ("run needs exactly one suite
    // file"); -h asks for the usage as --help does. A lone "-" stays a positional argument.
    if (s == "-h") throw HelpRequested();
    if (s.size() > 1 && s[0] == '-' && s[1] != '-') {
      throw UsageError("unknown option '" + s + "': options are long, with two dashes " + valid());
    }
    if (!s.starts_with("--")) {
      a.positional.push_back(s);
      continue;
    }
    std::string name = s, value;
    bool inline_value = false;
    if (auto eq = s.find('='); eq != std::string::npos) {
      name = s.substr(0, eq);
      value = s.substr(eq + 1);
      inline_value = true;
    }
    if (name == "--help" && !inline_value) throw HelpRequested();
    if (std::find(flags.begin(), flags.end(), name) != flags.end()) {
      if (inline_value) throw UsageError(name + " takes no value");
      a.options[name] = "";
    } else if (std::find(with_value.begin(), with_value.end(), name) != with_value.end()) {
      if (!inline_value) {
        if (i + 1 >= args.size()) throw UsageError(name + " needs a value");
        value = args[++i];
      }
      a.options[name] = value;
      a.repeated[name].push_back(value);
    } else {
      throw UsageError("unknown option '" + name + "' " + valid());
    }
  }
  return a;
}

std::optional<std::string> Args::Get(const std::string& name) const {
  auto it = options.find(name);
  if (it == options.end()) return std::nullopt;
  // An option of one value given twice (--out a ... --out b): the last silently won.
  if (const auto values = repeated.find(name);
      values != repeated.end() && values->second.size() > 1) {
    std::string given;
    for (const std::string& v : values->second) given += (given.empty() ? "'" : "', '") + v;
    throw UsageError(name + " is given " + std::to_string(values->second.size()) + " times (" +
                     given + "'): give it once");
  }
  return it->second;
}

std::string SpecSource(const std::string& file, const std::vector<std::string>& sets) {
  std::string source = file;
  for (std::size_t k = 0; k < sets.size(); ++k)
    source += (k ? " --set " : " with --set ") + sets[k];
  return source;
}

std::vector<std::string> Args::All(const std::string& name) const {
  auto it = repeated.find(name);
  return it == repeated.end() ? std::vector<std::string>{} : it->second;
}

std::int64_t Args::GetInt(const std::string& name, std::int64_t fallback, std::int64_t lo,
                          std::int64_t hi) const {
  auto v = Get(name);
  if (!v) return fallback;
  try {
    size_t used = 0;
    const long long x = std::stoll(*v, &used);
    if (used != v->size() || x < lo || x > hi) throw std::out_of_range("");
    return x;
  } catch (const std::exception&) {
    throw UsageError(name + " must be a whole number in [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "], got '" + *v + "'");
  }
}

double Args::GetNumber(const std::string& name, double fallback) const {
  auto v = Get(name);
  if (!v) return fallback;
  try {
    size_t used = 0;
    const double x = std::stod(*v, &used);
    if (used == v->size()) return x;
  } catch (const std::exception&) {
  }
  throw UsageError(name + " must be a number, got '" + *v + "'");
}

void CreateFolderOf(const std::string& option, const std::string& file) {
  const std::filesystem::path folder = std::filesystem::path(file).parent_path();
  if (folder.empty()) return;
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder)) {
    throw UsageError("cannot create the folder of " + option + " '" + file + "' (" +
                     folder.string() + ": " + (ec ? ec.message() : "not a folder") +
                     "); choose another " + option);
  }
}

}  // namespace crowdsim::cli
