#include "spec/config_text.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <variant>

#include "crowdsim/bench/plugin_registry.h"
#include "crowdsim/data_root.h"
#include "crowdsim/input_file.h"
#include "crowdsim/rng.h"

namespace crowdsim::suite_internal {
namespace fs = std::filesystem;

std::string HashConfigText(const std::string& canonical) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : canonical) {
    h ^= c;
    h *= 0x100000001b3ULL;
  }
  char buf[17];
  std::snprintf(buf, sizeof(buf), "%016llx", static_cast<unsigned long long>(SplitMix64(h)));
  return buf;
}

void CanonicalSim(const SimConfig& sim, std::ostream& os) {
  os << "sim=";
  for (const SimField& f : kSimFields) {
    os << (&f == kSimFields ? "" : ",");
    std::visit(
        [&](auto member) {
          if constexpr (std::is_same_v<decltype(member), double SimConfig::*>) {
            os << FormatParamValue(sim.*member);  // exact, as parameters are
          } else {
            os << sim.*member;  // a bool as 0 or 1
          }
        },
        f.member);
  }
  os << "\n";
}

namespace {

/// FNV-1a of a file's bytes, as 16 hex digits ("unreadable" when it cannot be read).
std::string FileContentHash(const fs::path& file) {
  if (!NotARegularFile(file).empty()) return "unreadable";  // never opened: a pipe would block
  std::ifstream in(file, std::ios::binary);
  if (!in) return "unreadable";
  std::uint64_t h = 0xcbf29ce484222325ULL;
  char buf[1 << 16];
  while (in.read(buf, sizeof(buf)) || in.gcount() > 0) {
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      h ^= static_cast<unsigned char>(buf[i]);
      h *= 0x100000001b3ULL;
    }
  }
  char out[17];
  std::snprintf(out, sizeof(out), "%016llx", static_cast<unsigned long long>(h));
  return out;
}

/// A data file's canonical name: relative to the data root when under it, else its file name, so
/// the hash ignores where the project sits.
std::string DataFileName(const fs::path& file) {
  std::error_code ec;
  const fs::path path = fs::weakly_canonical(file, ec);
  const fs::path root = fs::weakly_canonical(DataRoot(), ec);
  const fs::path relative = path.lexically_relative(root);
  if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
  return path.filename().string();
}

}  // namespace

std::vector<InputFile> InputFiles(const PluginUse& u) {
  std::vector<InputFile> files;
  std::set<fs::path> seen;  // canonical paths of the files already listed
  std::error_code ec;
  // A file a parameter names counts by its content: a replaced file is another configuration.
  for (const auto& [k, v] : u.params.values()) {
    const auto* text = std::get_if<std::string>(&v);
    if (!text || text->empty()) continue;
    const fs::path file = u.params.ResolvePath(*text);
    if (!fs::is_regular_file(file, ec)) continue;
    files.push_back({k, *text, FileContentHash(file), file});
    seen.insert(fs::weakly_canonical(file, ec));
  }
  // The files the plugin reads that no parameter names (a world's default frozen layouts).
  if (u.loaded && u.loaded->descriptor->data_files) {
    for (const fs::path& file : u.loaded->descriptor->data_files(u.params)) {
      if (!fs::is_regular_file(file, ec) || !seen.insert(fs::weakly_canonical(file, ec)).second)
        continue;
      files.push_back({"", DataFileName(file), FileContentHash(file), file});
    }
  }
  return files;
}

std::string PluginFileContent(const PluginUse& u) {
  if (!u.loaded || u.loaded->path.empty() || PluginRegistry::IsHarnessPlugin(*u.loaded)) return "";
  // Many rows share a plugin: read each file once, again only when its size or time changes.
  struct Seen {
    std::uintmax_t size;
    fs::file_time_type time;
    std::string content;
  };
  static std::mutex mutex;
  static std::map<fs::path, Seen> seen;
  std::error_code ec;
  const fs::path& path = u.loaded->path;
  const std::uintmax_t size = fs::file_size(path, ec);
  const fs::file_time_type time = fs::last_write_time(path, ec);
  std::lock_guard<std::mutex> lock(mutex);
  const auto it = seen.find(path);
  if (it != seen.end() && it->second.size == size && it->second.time == time) {
    return it->second.content;
  }
  std::string content = FileContentHash(path);
  seen[path] = {size, time, content};
  return content;
}

void Canonical(const PluginUse& u, std::ostream& os) {
  os << (u.loaded ? u.loaded->descriptor->name : u.plugin) << "{";
  const std::vector<InputFile> files = InputFiles(u);
  for (const auto& [k, v] : u.params.values()) {
    if (u.loaded) {
      const auto& schema = u.loaded->schema;
      const std::string& key = k;  // clang 14 cannot capture a structured binding
      const auto spec = std::find_if(schema.begin(), schema.end(),
                                     [&key](const ParamSpec& s) { return s.name == key; });
      if (spec != schema.end() && !spec->hashed_at_default && v == spec->default_value) continue;
    }
    os << k << "=" << FormatParamValue(v);
    for (const InputFile& f : files) {
      if (f.param == k) os << "#content:" << f.content;
    }
    os << ";";
  }
  for (const InputFile& f : files) {
    if (f.param.empty()) os << "data:" << f.name << "#content:" << f.content << ";";
  }
  if (const std::string plugin = PluginFileContent(u); !plugin.empty()) {
    os << "plugin:" << u.loaded->path.filename().string() << "#content:" << plugin << ";";
  }
  os << "}";
}

namespace {

// A canonical line's key: what comes before its first ':' or '=' ("humans", "seed").
std::string LineKey(const std::string& line) { return line.substr(0, line.find_first_of(":=")); }

// One plugin use of a line: its name ("lidar2d") and items: "k=v" parameters and
// "data:FILE#content:HASH" under "data:FILE".
struct Segment {
  std::string head;
  std::map<std::string, std::string> items;
};

std::vector<Segment> Segments(const std::string& rest) {
  std::vector<Segment> segments;
  std::size_t at = 0;
  while (at < rest.size()) {
    const std::size_t open = rest.find('{', at);
    const std::size_t close = open == std::string::npos ? open : rest.find('}', open);
    if (close == std::string::npos) {
      segments.push_back({rest.substr(at), {}});
      break;
    }
    Segment seg{rest.substr(at, open - at), {}};
    std::istringstream in(rest.substr(open + 1, close - open - 1));
    for (std::string item; std::getline(in, item, ';');) {
      const std::size_t eq = item.find('=');
      if (eq != std::string::npos) {
        seg.items[item.substr(0, eq)] = item.substr(eq + 1);
      } else if (!item.empty()) {
        seg.items[item.substr(0, item.find("#content:"))] = item;
      }
    }
    segments.push_back(std::move(seg));
    at = close + 1;
  }
  return segments;
}

// Both texts from a little before their first difference, so a change in a long value shows.
std::string AroundDifference(const std::string& a, const std::string& b) {
  std::size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
  const std::size_t from = i > 20 ? i - 20 : 0;
  auto cut = [&](const std::string& t) {
    std::string part = t.substr(std::min(from, t.size()), 60);
    return (from > 0 ? "..." : "") + part + (from + 60 < t.size() ? "..." : "");
  };
  return cut(a) + " -> " + cut(b);
}

// What follows a line's key and its separator ("" for a line that is its key alone).
std::string AfterKey(const std::string& line, const std::string& key) {
  return line.size() > key.size() ? line.substr(key.size() + 1) : "";
}

// A line's unnamed values named by `fields` in order; "k=v" values by their own name.
std::map<std::string, std::string> NamedValues(const std::string& rest,
                                               const std::vector<std::string>& fields) {
  std::map<std::string, std::string> values;
  std::istringstream in(rest);
  std::size_t i = 0;
  for (std::string value; std::getline(in, value, ',');) {
    const std::size_t eq = value.find('=');
    if (eq != std::string::npos) {
      values[value.substr(0, eq)] = value.substr(eq + 1);
    } else {
      values[i < fields.size() ? fields[i] : "value " + std::to_string(i + 1)] = value;
      ++i;
    }
  }
  return values;
}

// How a positional line changed: each named value that differs.
std::string PositionalChange(const std::string& key, const std::string& rest_a,
                             const std::string& rest_b, const std::vector<std::string>& fields) {
  const auto a = NamedValues(rest_a, fields), b = NamedValues(rest_b, fields);
  std::string text;
  auto add = [&](const std::string& part) { text += (text.empty() ? "" : ", ") + part; };
  for (const auto& [name, value] : b) {
    const auto it = a.find(name);
    if (it == a.end()) {
      add(name + "=" + value + " (new)");
    } else if (it->second != value) {
      add(name + " " + it->second + " -> " + value);
    }
  }
  for (const auto& [name, value] : a) {
    if (!b.count(name)) add(name + " (gone)");
  }
  return key + ": " + (text.empty() ? AroundDifference(rest_a, rest_b) : text);
}

// How one line changed: per plugin use, the items that differ; else both texts.
std::string LineChange(const std::string& key, const std::string& before, const std::string& now,
                       const std::map<std::string, std::vector<std::string>>& positional) {
  const std::string rest_a = AfterKey(before, key), rest_b = AfterKey(now, key);
  if (const auto fields = positional.find(key); fields != positional.end()) {
    return PositionalChange(key, rest_a, rest_b, fields->second);
  }
  const std::vector<Segment> a = Segments(rest_a);
  const std::vector<Segment> b = Segments(rest_b);
  if (a.size() != b.size()) {  // a plugin use added or removed (a sensor, say)
    return key + ": " + AroundDifference(rest_a, rest_b);
  }
  std::string text;
  auto add = [&](const std::string& part) { text += (text.empty() ? "" : ", ") + part; };
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].head != b[i].head) add(AroundDifference(a[i].head, b[i].head));
    const std::string who = a.size() > 1 ? b[i].head + " " : "";
    for (const auto& [k, v] : b[i].items) {
      const auto it = a[i].items.find(k);
      if (it == a[i].items.end()) {
        add(who + k + "=" + (v.size() <= 60 ? v : v.substr(0, 57) + "...") + " (new)");
      } else if (it->second != v) {
        add(who + k + " " + AroundDifference(it->second, v));
      }
    }
    for (const auto& [k, v] : a[i].items) {
      if (!b[i].items.count(k)) add(who + k + " (gone)");
    }
  }
  return key + ": " + (text.empty() ? AroundDifference(rest_a, rest_b) : text);
}

std::vector<std::string> ConfigLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != '#') lines.push_back(line);
  }
  return lines;
}

}  // namespace

std::string DescribeConfigDifference(
    const std::string& before, const std::string& now,
    const std::map<std::string, std::vector<std::string>>& positional) {
  const std::vector<std::string> a = ConfigLines(before), b = ConfigLines(now);
  std::map<std::string, std::string> old_lines;
  for (const std::string& line : a) old_lines[LineKey(line)] = line;
  std::string text;
  auto add = [&](const std::string& part) { text += (text.empty() ? "" : "; ") + part; };
  std::set<std::string> seen;
  for (const std::string& line : b) {
    const std::string key = LineKey(line);
    seen.insert(key);
    const auto it = old_lines.find(key);
    if (it == old_lines.end()) {
      add(key + ": new");
    } else if (it->second != line) {
      add(LineChange(key, it->second, line, positional));
    }
  }
  for (const auto& [key, line] : old_lines) {
    if (!seen.count(key)) add(key + ": gone");
  }
  return text;
}

}  // namespace crowdsim::suite_internal
