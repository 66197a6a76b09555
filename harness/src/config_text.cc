#include "config_text.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
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

}  // namespace crowdsim::suite_internal
