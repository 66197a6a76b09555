#include "crowdsim/bench/plugin_registry.h"

#include <algorithm>
#include <boost/dll/shared_library.hpp>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "install_location.h"
#include "loader/blas_kernel.h"
#include "loader/elf_check.h"
#include "loader/shipped_plugins.h"
#include "spec/schema_check.h"

namespace crowdsim {
namespace fs = std::filesystem;

namespace {

constexpr const char* kPrefix = "crowdsim_";
constexpr const char* kSuffix = ".so";

/// The plugin name a file name gives (crowdsim_<name>.so), or none for another file name.
std::optional<std::string> PluginNameOfFile(const fs::path& path) {
  const std::string file = path.filename().string();
  const std::size_t affixes = std::strlen(kPrefix) + std::strlen(kSuffix);
  if (file.size() <= affixes || !file.starts_with(kPrefix) || !file.ends_with(kSuffix)) {
    return std::nullopt;
  }
  return file.substr(std::strlen(kPrefix), file.size() - affixes);
}

/// CROWDSIM_PLUGIN_PATH's folders first (overriding built-ins, like PATH), then the installed or
/// build plugin folder.
std::vector<fs::path> DefaultSearchDirs() {
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("CROWDSIM_PLUGIN_PATH")) {
    std::stringstream ss(env);
    std::string item;
    while (std::getline(ss, item, ':')) {
      if (!item.empty()) dirs.emplace_back(item);
    }
  }
  dirs.push_back(PluginRegistry::HarnessPluginDir());
  return dirs;
}

// The dynamic loader's own words inside boost.dll's message, whose errno suffix (e.g. "Bad file
// descriptor") has nothing to do with the failure.
std::string DynamicLoaderReason(const std::string& boost_message) {
  const std::string marker = "dlerror system message: ";
  const std::size_t start = boost_message.find(marker);
  const std::size_t end = boost_message.rfind("): ");
  if (start == std::string::npos || end == std::string::npos || end < start) return boost_message;
  return boost_message.substr(start + marker.size(), end - start - marker.size());
}

bool LooksLikePath(const std::string& s) {
  return s.find('/') != std::string::npos || (s.size() > 3 && s.ends_with(kSuffix));
}

// Holds the library alive as long as the object made from it.
template <typename T>
struct Holder {
  std::shared_ptr<boost::dll::shared_library> library;  // destroyed last
  std::unique_ptr<T> object;
};

template <typename T>
std::shared_ptr<T> Wrap(std::shared_ptr<boost::dll::shared_library> lib, std::unique_ptr<T> obj) {
  auto holder = std::make_shared<Holder<T>>();
  holder->library = std::move(lib);
  holder->object = std::move(obj);
  T* raw = holder->object.get();
  return std::shared_ptr<T>(holder, raw);
}

template <typename T, typename Factory>
std::shared_ptr<T> Make(const LoadedPlugin& p, PluginKind kind, Factory factory,
                        const Params& params) {
  const char* name = p.descriptor->name;
  if (p.descriptor->kind != kind || factory == nullptr) {
    throw PluginError("plugin '" + std::string(name) + "' (" + p.path.string() + ") is a " +
                      PluginKindName(p.descriptor->kind) + " plugin, not a " +
                      PluginKindName(kind) + " plugin, or it sets no " + PluginKindName(kind) +
                      " factory. Use it where a " + PluginKindName(p.descriptor->kind) +
                      " is expected, or fix its descriptor.");
  }
  std::unique_ptr<T> obj;
  try {
    obj = factory(params);
  } catch (const std::invalid_argument& e) {  // a parameter the plugin cannot take
    throw PluginError("plugin '" + std::string(name) + "' (" + p.path.string() +
                      ") failed to create its " + PluginKindName(kind) + ": " + e.what() +
                      ". Check its parameters against `crowdsim-bench list-plugins`.");
  } catch (const std::exception& e) {  // a file, a model, ...: the message says what
    throw PluginError("plugin '" + std::string(name) + "' (" + p.path.string() +
                      ") failed to create its " + PluginKindName(kind) + ": " + e.what());
  } catch (...) {
    throw PluginError("plugin '" + std::string(name) + "' (" + p.path.string() +
                      ") threw a non-standard exception from its factory. Fix the plugin.");
  }
  if (!obj) {
    throw PluginError("plugin '" + std::string(name) + "' (" + p.path.string() +
                      ") returned no object from its factory. Fix the plugin.");
  }
  return Wrap<T>(p.library, std::move(obj));
}

/// Adds `file` to what `found` hides, unless it is `found`'s own file or already listed.
void Hide(const fs::path& file, const LoadedPlugin& found, std::vector<fs::path>* hidden) {
  std::error_code ec;
  const auto same = [&](const fs::path& other) { return fs::equivalent(file, other, ec); };
  if (same(found.path) || std::any_of(hidden->begin(), hidden->end(), same)) return;
  hidden->push_back(file);
}

}  // namespace

fs::path PluginRegistry::BuildPluginDir() { return CROWDSIM_BUILD_PLUGIN_DIR; }

fs::path PluginRegistry::HarnessPluginDir() {
  if (const auto lib = common::InstalledLibDir()) return *lib / "crowdsim-bench" / "plugins";
  return BuildPluginDir();
}

bool PluginRegistry::IsHarnessPlugin(const LoadedPlugin& p) {
  if (p.path.empty()) return false;  // made in memory (e.g. the Python module's policy)
  // Shipped by this build, by name: a user's plugin copied here stays the user's (hashed,
  // isolated).
  if (p.descriptor == nullptr || !IsShippedPluginName(p.descriptor->name)) return false;
  if (p.path.filename() != kPrefix + std::string(p.descriptor->name) + kSuffix) return false;
  std::error_code ec;
  static const fs::path own = fs::weakly_canonical(HarnessPluginDir(), ec);
  return (p.folder.empty() ? fs::weakly_canonical(p.path, ec).parent_path() : p.folder) == own;
}

PluginRegistry::PluginRegistry() : search_dirs_(DefaultSearchDirs()) {}
PluginRegistry::PluginRegistry(std::vector<fs::path> search_dirs)
    : search_dirs_(std::move(search_dirs)) {}

fs::path PluginRegistry::Resolve(const std::string& name_or_path) const {
  if (LooksLikePath(name_or_path)) {
    fs::path p(name_or_path);
    if (!fs::exists(p)) {
      throw PluginError("plugin file '" + name_or_path +
                        "' does not exist. Give the path of a built plugin (.so), or a plugin "
                        "name to search the plugin folders.");
    }
    return p;
  }
  std::string searched;
  for (const auto& dir : search_dirs_) {
    fs::path candidate = dir / (kPrefix + name_or_path + kSuffix);
    if (fs::exists(candidate)) return candidate;
    searched += "\n  " + candidate.string();
  }
  throw PluginError("no plugin named '" + name_or_path + "' was found; looked for:" + searched +
                    "\nRun `crowdsim-bench list-plugins` to see the available plugins, build "
                    "the project, add the folder of yours to CROWDSIM_PLUGIN_PATH, or give the "
                    "path of its .so file.");
}

const LoadedPlugin& PluginRegistry::LoadPath(const fs::path& path) {
  std::error_code ec;
  fs::path canonical = fs::weakly_canonical(path, ec);
  if (ec) canonical = path;
  const std::string key = canonical.string();
  // Cached by folder and name (own symlink not followed): reached from two folders, one library is
  // two uses, each judged by its folder.
  const fs::path folder = fs::weakly_canonical(fs::absolute(path, ec).parent_path(), ec);
  const std::string use = (folder / path.filename()).string();
  if (auto it = loaded_.find(use); it != loaded_.end()) return *it->second;

  if (const std::string problem = ElfFileProblem(canonical); !problem.empty()) {
    throw PluginError("cannot load plugin file '" + key + "': it " + problem);
  }
  auto lib = std::make_shared<boost::dll::shared_library>();
  PinBlasKernel();  // before a learned policy's plugin brings OpenBLAS in
  try {
    lib->load(canonical, boost::dll::load_mode::rtld_now | boost::dll::load_mode::rtld_local);
  } catch (const std::exception& e) {
    throw PluginError("cannot load plugin file '" + key + "': " + DynamicLoaderReason(e.what()) +
                      ". It is not a loadable shared library for this machine, or one of its "
                      "dependencies is missing (check with `ldd " +
                      key +
                      "`). Rebuild it "
                      "against this version of crowdsim-bench.");
  }
  if (!lib->has(kPluginAliasName)) {
    throw PluginError(
        "'" + key +
        "' is a shared library but not a crowdsim-bench plugin: it "
        "exports no '" +
        std::string(kPluginAliasName) +
        "' symbol. A plugin "
        "defines a crowdsim::PluginDescriptor and exports it with "
        "CROWDSIM_EXPORT_PLUGIN(descriptor) (docs/plugins.md and examples/my_policy of the "
        "crowdsim-bench sources show one).");
  }
  // Read the version through the alias before touching the rest of the descriptor.
  const auto& version = lib->get_alias<const std::uint32_t>(kPluginAliasName);
  if (version != kPluginAbiVersion) {
    throw PluginError("plugin '" + key + "' was built for plugin ABI version " +
                      std::to_string(version) + ", but this crowdsim-bench expects version " +
                      std::to_string(kPluginAbiVersion) +
                      ". Rebuild the plugin against the headers of this crowdsim-bench.");
  }
  const auto& desc = lib->get_alias<const PluginDescriptor>(kPluginAliasName);
  if (desc.name == nullptr || desc.description == nullptr || desc.schema == nullptr) {
    throw PluginError("plugin '" + key +
                      "' has an incomplete descriptor (name, description "
                      "and schema are required). Fix the plugin's descriptor.");
  }
  // Suites find a plugin by file name, tables and list-plugins by descriptor name: the two must
  // agree.
  if (const auto file_name = PluginNameOfFile(path); file_name && *file_name != desc.name) {
    throw PluginError("plugin file '" + key + "' is named '" + *file_name +
                      "' but its descriptor calls it '" + desc.name +
                      "': suites find a plugin by its file name (crowdsim_<name>.so) and tables "
                      "name it by its descriptor, so the two must agree. Rename the file to " +
                      kPrefix + desc.name + kSuffix + " or the descriptor's name to '" +
                      *file_name + "'.");
  }
  auto loaded = std::make_unique<LoadedPlugin>();
  loaded->path = canonical;
  loaded->folder = folder;
  loaded->library = std::move(lib);
  loaded->descriptor = &desc;
  try {
    loaded->schema = desc.schema();
  } catch (const std::exception& e) {
    throw PluginError("plugin '" + key + "' threw while reporting its parameter schema: " +
                      e.what() + ". Fix the plugin.");
  }
  if (const std::vector<std::string> problems = SchemaProblems(loaded->schema); !problems.empty()) {
    std::string list;
    for (const std::string& problem : problems) list += (list.empty() ? "" : "; ") + problem;
    throw PluginError("plugin '" + key + "' declares parameters the harness cannot use: " + list +
                      ". A default must have its parameter's type and lie within its range "
                      "and choices. Fix the plugin's Schema().");
  }
  const LoadedPlugin& ref = *loaded;
  loaded_[use] = std::move(loaded);
  return ref;
}

const LoadedPlugin& PluginRegistry::LoadAny(const std::string& name_or_path) {
  return LoadPath(Resolve(name_or_path));
}

const LoadedPlugin& PluginRegistry::Load(const std::string& name_or_path, PluginKind kind) {
  const LoadedPlugin& p = LoadAny(name_or_path);
  if (p.descriptor->kind != kind) {
    throw PluginError("plugin '" + name_or_path + "' (" + p.path.string() + ") is a " +
                      PluginKindName(p.descriptor->kind) + " plugin, but a " +
                      PluginKindName(kind) +
                      " plugin is needed here. Run `crowdsim-bench "
                      "list-plugins` to see the " +
                      PluginKindName(kind) + " plugins.");
  }
  return p;
}

PluginRegistry::Found PluginRegistry::Discover() {
  Found found;
  // By name, the first file of that name (null if it failed to load; its problem is listed).
  std::map<std::string, const LoadedPlugin*> first;
  for (const auto& dir : search_dirs_) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) continue;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
      if (PluginNameOfFile(entry.path())) files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
      const std::string name = *PluginNameOfFile(f);
      if (const auto it = first.find(name); it != first.end()) {
        if (it->second != nullptr) Hide(f, *it->second, &found.hidden[it->second]);
        continue;
      }
      first[name] = nullptr;
      try {
        first[name] = &LoadPath(f);
        found.plugins.push_back(first[name]);
      } catch (const PluginError& e) {
        found.problems.push_back(e.what());
      }
    }
  }
  return found;
}

std::shared_ptr<Policy> PluginRegistry::MakePolicy(const LoadedPlugin& p,
                                                   const Params& params) const {
  return Make<Policy>(p, PluginKind::kPolicy, p.descriptor->make_policy, params);
}

std::shared_ptr<Sensor> PluginRegistry::MakeSensor(const LoadedPlugin& p,
                                                   const Params& params) const {
  return Make<Sensor>(p, PluginKind::kSensor, p.descriptor->make_sensor, params);
}

std::shared_ptr<WorldSource> PluginRegistry::MakeWorld(const LoadedPlugin& p,
                                                       const Params& params) const {
  return Make<WorldSource>(p, PluginKind::kWorld, p.descriptor->make_world, params);
}

}  // namespace crowdsim
