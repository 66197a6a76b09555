#include "config_text.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <variant>

#include "crowdsim/data_root.h"
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
    std::visit([&](auto member) { os << sim.*member; }, f.member);  // a bool as 0 or 1
  }
  os << "\n";
}

namespace {

/// FNV-1a of a file's bytes, as 16 hex digits ("unreadable" when it cannot be read).
std::string FileContentHash(const fs::path& file) {
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

/// How a data file is named in the canonical text: relative to the data root when it lies
/// there, else by its file name, so that the hash does not depend on where the project sits.
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
  // A parameter that names a file (weights, a world file) counts with its content: replacing
  // the file at the same path is another configuration, never resumed as the old one.
  for (const auto& [k, v] : u.params.values()) {
    const auto* text = std::get_if<std::string>(&v);
    if (!text || text->empty()) continue;
    const fs::path file = u.params.ResolvePath(*text);
    if (!fs::is_regular_file(file, ec)) continue;
    files.push_back({k, *text, FileContentHash(file)});
    seen.insert(fs::weakly_canonical(file, ec));
  }
  // The files the plugin reads that no parameter names (a world's default frozen layouts).
  if (u.loaded && u.loaded->descriptor->data_files) {
    for (const fs::path& file : u.loaded->descriptor->data_files(u.params)) {
      if (!fs::is_regular_file(file, ec) || !seen.insert(fs::weakly_canonical(file, ec)).second)
        continue;
      files.push_back({"", DataFileName(file), FileContentHash(file)});
    }
  }
  return files;
}

void Canonical(const PluginUse& u, std::ostream& os) {
  os << (u.loaded ? u.loaded->descriptor->name : u.plugin) << "{";
  const std::vector<InputFile> files = InputFiles(u);
  for (const auto& [k, v] : u.params.values()) {
    if (u.loaded) {
      const auto& schema = u.loaded->schema;
      const auto spec = std::find_if(schema.begin(), schema.end(),
                                     [&k](const ParamSpec& s) { return s.name == k; });
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
  os << "}";
}

namespace {

// A canonical line's key: what comes before its first ':' or '=' ("humans", "seed").
std::string LineKey(const std::string& line) { return line.substr(0, line.find_first_of(":=")); }

// The "k=v;" pairs inside a line's braces (a plugin's parameters), in order.
std::vector<std::pair<std::string, std::string>> BracedParams(const std::string& line) {
  std::vector<std::pair<std::string, std::string>> params;
  const std::size_t open = line.find('{'), close = line.rfind('}');
  if (open == std::string::npos || close == std::string::npos || close < open) return params;
  std::istringstream in(line.substr(open + 1, close - open - 1));
  for (std::string item; std::getline(in, item, ';');) {
    const std::size_t eq = item.find('=');
    if (eq != std::string::npos) params.emplace_back(item.substr(0, eq), item.substr(eq + 1));
  }
  return params;
}

std::string Shortened(const std::string& text) {
  return text.size() <= 60 ? text : text.substr(0, 57) + "...";
}

// How one line changed: the parameters that differ when both have braces, else both values.
std::string LineChange(const std::string& key, const std::string& before, const std::string& now) {
  const auto a = BracedParams(before), b = BracedParams(now);
  const std::string head_a = before.substr(0, before.find('{'));
  const std::string head_b = now.substr(0, now.find('{'));
  if (a.empty() && b.empty()) {
    return key + ": " + Shortened(before.substr(key.size() + 1)) + " -> " +
           Shortened(now.substr(key.size() + 1));
  }
  std::string text;
  auto add = [&](const std::string& part) { text += (text.empty() ? "" : ", ") + part; };
  if (head_a != head_b) {
    add(Shortened(head_a.substr(key.size() + 1)) + " -> " +
        Shortened(head_b.substr(key.size() + 1)));
  }
  const std::map<std::string, std::string> old_values(a.begin(), a.end());
  const std::map<std::string, std::string> new_values(b.begin(), b.end());
  for (const auto& [k, v] : new_values) {
    const auto it = old_values.find(k);
    if (it == old_values.end()) {
      add(k + "=" + Shortened(v) + " (new)");
    } else if (it->second != v) {
      add(k + " " + Shortened(it->second) + " -> " + Shortened(v));
    }
  }
  for (const auto& [k, v] : old_values) {
    if (!new_values.count(k)) add(k + "=" + Shortened(v) + " (gone)");
  }
  return key + ": " + text;
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

std::string DescribeConfigDifference(const std::string& before, const std::string& now) {
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
      add(LineChange(key, it->second, line));
    }
  }
  for (const auto& [key, line] : old_lines) {
    if (!seen.count(key)) add(key + ": gone");
  }
  return text;
}

}  // namespace crowdsim::suite_internal
