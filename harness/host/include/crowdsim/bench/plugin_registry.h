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
  /// The folder the file is found in or given from (own symlink not followed).
  std::filesystem::path folder;
  std::shared_ptr<boost::dll::shared_library> library;
  const PluginDescriptor* descriptor = nullptr;
  ParamSchema schema;
};

/// Loads plugins by name (crowdsim_NAME.so) or .so path, once each; objects keep their library.
class PluginRegistry {
 public:
  /// Search folders: CROWDSIM_PLUGIN_PATH's, then the installed plugins (beside the core library)
  /// or the build's.
  PluginRegistry();
  explicit PluginRegistry(std::vector<std::filesystem::path> search_dirs);

  const std::vector<std::filesystem::path>& search_dirs() const { return search_dirs_; }

  /// Loads `name_or_path` and checks it is of `kind`. Throws PluginError.
  const LoadedPlugin& Load(const std::string& name_or_path, PluginKind kind);
  /// Loads without a kind check (list-plugins).
  const LoadedPlugin& LoadAny(const std::string& name_or_path);

  /// Every crowdsim_*.so in the search folders (first wins per name), with load problems.
  struct Found {
    std::vector<const LoadedPlugin*> plugins;
    std::vector<std::string> problems;
    /// Per plugin found: the same-named files in later folders, which it hides.
    std::map<const LoadedPlugin*, std::vector<std::filesystem::path>> hidden;
  };
  Found Discover();

  /// Object factories; results keep the library loaded. Throw PluginError on a throw or null.
  std::shared_ptr<Policy> MakePolicy(const LoadedPlugin& p, const Params& params) const;
  std::shared_ptr<Sensor> MakeSensor(const LoadedPlugin& p, const Params& params) const;
  std::shared_ptr<WorldSource> MakeWorld(const LoadedPlugin& p, const Params& params) const;

  /// Folder with the plugins built with this harness.
  static std::filesystem::path BuildPluginDir();
  /// The harness's own plugins: the install's plugin folder, or BuildPluginDir() in a build tree.
  static std::filesystem::path HarnessPluginDir();
  /// Whether `p` lies in HarnessPluginDir(); suites isolate the others by default.
  static bool IsHarnessPlugin(const LoadedPlugin& p);

 private:
  std::filesystem::path Resolve(const std::string& name_or_path) const;
  const LoadedPlugin& LoadPath(const std::filesystem::path& path);

  std::vector<std::filesystem::path> search_dirs_;
  std::map<std::string, std::unique_ptr<LoadedPlugin>>
      loaded_;  // by folder (resolved) and file name
};

}  // namespace crowdsim
