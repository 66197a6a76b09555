// Internal to the core: the canonical text of a configuration (what decides results or trained
// weights) and the config hash made from it. Suites, their rows and training files all hash
// their canonical text with HashConfigText, so one stored hash means one configuration.
#pragma once

#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "crowdsim/bench/suite.h"
#include "crowdsim/sim_config.h"

namespace crowdsim::suite_internal {

/// The config hash of a canonical text: 16 hex digits.
std::string HashConfigText(const std::string& canonical);

/// A file a plugin use reads, with its content hash (FNV-1a of the bytes, 16 hex digits).
struct InputFile {
  std::string param;    ///< the parameter that names it; empty for a plugin's data file
  std::string name;     ///< the parameter's value, or the data file relative to the data root
  std::string content;  ///< content hash ("unreadable" when it cannot be read)
};

/// Every file a plugin use reads: those its string parameters name (resolved as the plugins
/// resolve them), then the data files it declares (PluginDescriptor::data_files) not already
/// among them. What the config hash and the manifest's "files" cover.
std::vector<InputFile> InputFiles(const PluginUse& u);

/// The content hash of the plugin file itself when it is not one of the harness's own (a
/// user's plugin, loaded by path or from CROWDSIM_PLUGIN_PATH), else "": rebuilding such a
/// plugin is another configuration, never resumed as the old one. The harness's own plugins
/// are covered by the commit that built them (manifest.json's git_commit).
std::string PluginFileContent(const PluginUse& u);

/// Writes a plugin use (name and every parameter value, with the content hash of every file it
/// reads, InputFiles) into a canonical config text.
void Canonical(const PluginUse& u, std::ostream& os);

/// Appends the canonical text of the simulation settings (one line).
void CanonicalSim(const SimConfig& sim, std::ostream& os);

/// What two canonical texts set differently, for an error message: per differing line its key
/// and, for a plugin's parameters, each value that changed ("humans: count 5 -> 3; orca
/// safety_space=0 -> 0.1"), else both lines. Empty when they are equal; comment lines ignored.
/// `positional` names the comma-separated values of lines written without names (a training's
/// "training:3000,50,0.01,..." line: "il_epochs 50 -> 40" instead of both lines' digits).
std::string DescribeConfigDifference(
    const std::string& before, const std::string& now,
    const std::map<std::string, std::vector<std::string>>& positional = {});

}  // namespace crowdsim::suite_internal
