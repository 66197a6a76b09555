// The plugin ABI: each plugin exports one descriptor via a Boost.DLL alias; the host reads
// `abi_version` (first field) before the rest.
#pragma once

#include <boost/dll/alias.hpp>
#include <concepts>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "crowdsim/export.h"
#include "crowdsim/params.h"
#include "crowdsim/policy.h"
#include "crowdsim/sensor.h"
#include "crowdsim/world_source.h"

namespace crowdsim {

/// Bump when any interface or this descriptor changes layout: the host refuses a plugin built for
/// another version.
inline constexpr std::uint32_t kPluginAbiVersion = 10;

/// Name of the exported alias.
inline constexpr const char* kPluginAliasName = "crowdsim_plugin_v1";

enum class PluginKind : std::uint32_t { kPolicy = 1, kSensor = 2, kWorld = 3 };

CROWDSIM_SDK_API const char* PluginKindName(PluginKind k);

/// The one object a plugin exports. Only the factory matching `kind` is set.
struct CROWDSIM_SDK_API PluginDescriptor {
  std::uint32_t abi_version;  ///< must stay the first member
  PluginKind kind;
  const char* name;         ///< unique name used in suites (e.g. "orca")
  const char* description;  ///< one line
  ParamSchema (*schema)();
  std::unique_ptr<Policy> (*make_policy)(const Params&);
  std::unique_ptr<Sensor> (*make_sensor)(const Params&);
  std::unique_ptr<WorldSource> (*make_world)(const Params&);
  /// Files a configuration reads that no parameter names (e.g. default layouts); hashed into the
  /// config hash. Null when none.
  std::vector<std::filesystem::path> (*data_files)(const Params&);
};

/// `&T::DataFiles` when the plugin's class declares
/// `static std::vector<std::filesystem::path> DataFiles(const Params&)`, else null.
template <typename T>
constexpr auto DataFilesOf() -> std::vector<std::filesystem::path> (*)(const Params&) {
  if constexpr (requires(const Params& p) {
                  { T::DataFiles(p) } -> std::same_as<std::vector<std::filesystem::path>>;
                }) {
    return &T::DataFiles;
  } else {
    return nullptr;
  }
}

/// The factory of a plugin whose object `T` is constructed from its validated Params.
template <typename Interface, typename T>
std::unique_ptr<Interface> ConstructFromParams(const Params& params) {
  return std::make_unique<T>(params);
}

/// The descriptor of a policy plugin whose class `T` takes `const Params&`:
///   const PluginDescriptor kDescriptor = PolicyPlugin<MyPolicy>("mine", "what it does", &Schema);
template <typename T>
constexpr PluginDescriptor PolicyPlugin(const char* name, const char* description,
                                        ParamSchema (*schema)()) {
  return {kPluginAbiVersion,
          PluginKind::kPolicy,
          name,
          description,
          schema,
          &ConstructFromParams<Policy, T>,
          nullptr,
          nullptr,
          DataFilesOf<T>()};
}

/// The descriptor of a sensor plugin whose class `T` takes `const Params&`.
template <typename T>
constexpr PluginDescriptor SensorPlugin(const char* name, const char* description,
                                        ParamSchema (*schema)()) {
  return {kPluginAbiVersion,
          PluginKind::kSensor,
          name,
          description,
          schema,
          nullptr,
          &ConstructFromParams<Sensor, T>,
          nullptr,
          DataFilesOf<T>()};
}

/// The descriptor of a world plugin whose class `T` takes `const Params&`.
template <typename T>
constexpr PluginDescriptor WorldPlugin(const char* name, const char* description,
                                       ParamSchema (*schema)()) {
  return {kPluginAbiVersion,
          PluginKind::kWorld,
          name,
          description,
          schema,
          nullptr,
          nullptr,
          &ConstructFromParams<WorldSource, T>,
          DataFilesOf<T>()};
}

}  // namespace crowdsim

/// Exports `descriptor` (a namespace-scope crowdsim::PluginDescriptor with external linkage) under
/// the ABI alias, once per library.
#define CROWDSIM_EXPORT_PLUGIN(descriptor) BOOST_DLL_ALIAS(descriptor, crowdsim_plugin_v1)
