// Internal to the core: loading a YAML document for the suite, training-file and world-file
// readers, with every problem located: a missing file, a folder given as a file, a syntax
// error, a key given twice in one map (yaml-cpp would silently keep one of the values), and
// aliases no reader could walk (a map or list holding an alias of itself, which overflowed the
// stack, or aliases of aliases expanding past a million values).
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <vector>

#include "crowdsim/bench/suite.h"

namespace crowdsim::suite_internal {

/// The document of `file`, or a null node with `errors` saying why (`what` names the kind of
/// file in messages, e.g. "suite file"). Duplicate keys are reported too; the document is
/// returned null when any problem was found.
YAML::Node LoadYamlFile(const std::filesystem::path& file, const std::string& what,
                        std::vector<SuiteError>* errors);

}  // namespace crowdsim::suite_internal
