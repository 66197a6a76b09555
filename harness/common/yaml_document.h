// Loading a YAML document with every problem located: a missing file, a folder, a pipe, a
// binary file, a syntax error (with a hint at the likely line), a key given twice, and aliases
// no reader could walk. A static library that the SDK's world files and the host's readers share.
#pragma once

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <string>
#include <vector>

namespace crowdsim::yaml {

/// One problem of a document: file, 1-based line and column (0 = the whole file), message.
struct Problem {
  std::string file;
  int line = 0;
  int column = 0;
  std::string message;
  /// "file:line:column: message", or "file: message" for the whole file.
  std::string Format() const;
};

/// The document of `file`, or a null node with `problems` saying why (`what` names the kind of
/// file in messages, e.g. "suite file"). Duplicate keys count; any problem returns null.
YAML::Node LoadDocument(const std::filesystem::path& file, const std::string& what,
                        std::vector<Problem>* problems);

}  // namespace crowdsim::yaml
