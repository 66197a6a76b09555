// Loads a YAML document, locating every problem (missing, folder, pipe, binary, syntax, duplicate
// key, bad alias). Shared by SDK and host.
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

/// The document of `file`, or a null node with `problems` saying why (duplicate keys included);
/// `what`: the file's kind.
YAML::Node LoadDocument(const std::filesystem::path& file, const std::string& what,
                        std::vector<Problem>* problems);

}  // namespace crowdsim::yaml
