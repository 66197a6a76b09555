// Internal: a row's per-person attributes (`humans: {radius, v_pref, distracted}`) and their
// canonical text.
#pragma once

#include <yaml-cpp/yaml.h>

#include <functional>
#include <ostream>
#include <string>
#include <utility>

#include "crowdsim/bench/suite.h"
#include "spec/suite_reader.h"

namespace crowdsim::suite_internal {

/// Reads `radius`, `v_pref` (a number or [lo, hi]), `distracted` (a probability) and `groups`
/// from a `humans:` map (after `count`); `pick` finds a key in the row, else the file.
void ReadHumanAttributes(Reader& r,
                         const std::function<std::pair<YAML::Node, std::string>(const char*)>& pick,
                         HumansSpec* out);

/// Appends "radius=lo:hi,v_pref=lo:hi,distracted=p,groups=share:min:max," for what is set:
/// nothing for the sim's people, so old config hashes hold.
void CanonicalHumanAttributes(const HumansSpec& humans, std::ostream& os);

}  // namespace crowdsim::suite_internal
