// Finds, loads and checks plugin shared libraries (Boost.DLL), and makes objects from them.
#pragma once

#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "crowdsim/data_root.h"
#include "crowdsim/plugin_abi.h"

namespace boost::dll {
class shared_library;
}

namespace crowdsim {

/// A plugin problem; what() is one paragraph naming the file, what is wrong and the fix.
class PluginError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A loaded, ABI-checked plugin library.
struct LoadedPlugin {
  std::filesystem::path path;  ///< the file, symlinks resolved
  /// The folder the file was found in or given from (its own symlink not followed: an install
  /// whose plugin files link into a store is still the harness's own folder).
  std::filesystem::path folder;
  std::shared_ptr<boost::dll::shared_library> library;
  const PluginDescriptor* descriptor = nullptr;
  ParamSchema schema;
};

/// Loads plugins by name (crowdsim_NAME.so in the search folders) or by explicit .so path,
/// once each; objects it makes keep their library loaded while they live.
class PluginRegistry {
 public:
  /// Search folders: each folder of CROWDSIM_PLUGIN_PATH, then the installed plugins
  /// (PREFIX/lib/crowdsim-bench/plugins, found next to the core library) or the build's.
  PluginRegistry();
  explicit PluginRegistry(std::vector<std::filesystem::path> search_dirs);

  const std::vector<std::filesystem::path>& search_dirs() const { return search_dirs_; }

  /// Loads `name_or_path` and checks it is of `kind`. Throws PluginError.
  const LoadedPlugin& Load(const std::string& name_or_path, PluginKind kind);
  /// Loads without a kind check (list-plugins).
  const LoadedPlugin& LoadAny(const std::string& name_or_path);

  /// Every crowdsim_*.so in the search folders (first folder wins per name), with the
  /// problem of each file that fails to load.
  struct Found {
    std::vector<const LoadedPlugin*> plugins;
    std::vector<std::string> problems;
    /// By plugin found: the files of its name in later folders, which it hides (a suite naming
    /// it gets the one found).
    std::map<const LoadedPlugin*, std::vector<std::filesystem::path>> hidden;
  };
  Found Discover();

  /// Object factories; the result keeps the plugin library loaded. Throw PluginError when
  /// the factory throws or returns null.
  std::shared_ptr<Policy> MakePolicy(const LoadedPlugin& p, const Params& params) const;
  std::shared_ptr<Sensor> MakeSensor(const LoadedPlugin& p, const Params& params) const;
  std::shared_ptr<WorldSource> MakeWorld(const LoadedPlugin& p, const Params& params) const;

  /// Folder with the plugins built with this harness.
  static std::filesystem::path BuildPluginDir();
  /// The harness's own plugins: the installed copy's plugin folder, or BuildPluginDir() in a
  /// build tree (the last of the default search folders).
  static std::filesystem::path HarnessPluginDir();
  /// Whether `p` is one of the harness's own plugins (its file lies in HarnessPluginDir()),
  /// not one loaded by path or from CROWDSIM_PLUGIN_PATH: suites run the others isolated in
  /// worker processes by default (isolation: auto).
  static bool IsHarnessPlugin(const LoadedPlugin& p);

 private:
  std::filesystem::path Resolve(const std::string& name_or_path) const;
  const LoadedPlugin& LoadPath(const std::filesystem::path& path);

  std::vector<std::filesystem::path> search_dirs_;
  std::map<std::string, std::unique_ptr<LoadedPlugin>>
      loaded_;  // by folder (resolved) and file name
};

}  // namespace crowdsim
