// Internal to the core: the canonical text of a configuration (what decides results or trained
// weights) and the config hash made from it. Suites, their rows and training files all hash
// their canonical text with HashConfigText, so one stored hash means one configuration.
#pragma once

#include <ostream>
#include <string>

#include "crowdsim/bench/suite.h"
#include "crowdsim/sim_config.h"

namespace crowdsim::suite_internal {

/// The config hash of a canonical text: 16 hex digits.
std::string HashConfigText(const std::string& canonical);

/// Writes a plugin use (name and every parameter value, with the content hash of every file a
/// parameter names) into a canonical config text.
void Canonical(const PluginUse& u, std::ostream& os);

/// Appends the canonical text of the simulation settings (one line).
void CanonicalSim(const SimConfig& sim, std::ostream& os);

}  // namespace crowdsim::suite_internal
