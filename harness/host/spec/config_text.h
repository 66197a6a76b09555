// Internal: the canonical text of a configuration (what decides results or weights) and its hash:
// one hash, one configuration.
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
  std::filesystem::path path;  ///< where it was found
};

/// Every file a plugin use reads (named by string parameters, then declared data files): what the
/// config hash and manifest cover.
std::vector<InputFile> InputFiles(const PluginUse& u);

/// Content hash of a user's plugin file, else "": a rebuilt plugin is another configuration.
/// git_commit covers the harness's own.
std::string PluginFileContent(const PluginUse& u);

/// Writes a plugin use (name, every parameter value, every InputFiles content hash) into a
/// canonical config text.
void Canonical(const PluginUse& u, std::ostream& os);

/// Appends the canonical text of the simulation settings (one line).
void CanonicalSim(const SimConfig& sim, std::ostream& os);

/// What two canonical texts set differently, for errors: per line its key and changed parameters
/// ("humans: count 5 -> 3"), else both lines; "" when equal. `positional` names unnamed values.
std::string DescribeConfigDifference(
    const std::string& before, const std::string& now,
    const std::map<std::string, std::vector<std::string>>& positional = {});

}  // namespace crowdsim::suite_internal
