// Writing a file whole or not at all, never through a link a third party planted.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace crowdsim::common {

/// Writes `text` to a fresh mkstemp file in path's folder, then renames it over `path`: readers see
/// old or new, a link at `path` is replaced, not followed. Throws std::runtime_error naming path
/// and reason.
void WriteFileAtomically(const std::filesystem::path& path, const std::string& text);

/// Copies `from` to `to` as WriteFileAtomically writes: a full disk is said as such
/// (std::filesystem's copy says "Input/output error"). Throws std::runtime_error naming the file
/// and the reason.
void CopyFileAtomically(const std::filesystem::path& from, const std::filesystem::path& to);

/// A new file of its own beside `path` (mkstemp in its folder, named ".NAME.XXXXXX", mode 0666
/// less the umask), open for writing: its descriptor, its name in `temp`. Rename it over `path`
/// when whole. Throws std::runtime_error naming the folder and the reason.
int CreateBeside(const std::filesystem::path& path, std::string* temp);

/// write(2) of all `size` bytes, retrying on EINTR: 0, or the failure's errno (ENOSPC when no
/// byte goes). Async-signal-safe.
int WriteAll(int fd, const char* data, size_t size);

}  // namespace crowdsim::common
