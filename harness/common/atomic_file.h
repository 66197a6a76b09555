// Writing a file whole or not at all, never through a link a third party planted.
#pragma once

#include <filesystem>
#include <string>

namespace crowdsim::common {

/// Writes `text` to a new file of its own (mkstemp: created exclusively, in path's folder) and
/// renames it over `path`: a reader sees the old file or the new one, and a symbolic link at
/// `path` is replaced, its target untouched. Throws std::runtime_error naming path and reason.
void WriteFileAtomically(const std::filesystem::path& path, const std::string& text);

}  // namespace crowdsim::common
