// What a user-named file is, without opening it: opening a named pipe blocks until a writer comes,
// so every reader asks this first.
#pragma once

#include <filesystem>
#include <string>

#include "crowdsim/export.h"

namespace crowdsim {

/// "" when `path` is a regular file (links followed); else a predicate for "PATH " + reason: "does
/// not exist", "is a folder", "is a named pipe (FIFO)", "is a device", "is a socket". Never opens
/// the file.
CROWDSIM_SDK_API std::string NotARegularFile(const std::filesystem::path& path);

}  // namespace crowdsim
