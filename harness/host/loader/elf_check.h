// Checks a plugin before dlopen: a truncated file maps pages past its end, and touching them raises
// SIGBUS.
#pragma once

#include <filesystem>
#include <string>

namespace crowdsim {

/// "" when `file`'s headers show a whole 64-bit ELF shared object of this machine, headers and
/// loaded segments inside the file; else a predicate: "is cut short: ...", "is not an ELF file
/// ...".
std::string ElfFileProblem(const std::filesystem::path& file);

}  // namespace crowdsim
