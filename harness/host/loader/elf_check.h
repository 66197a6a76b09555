// A plugin file checked before dlopen maps it: a file cut short (an interrupted copy) maps
// pages past its end, and touching them kills the process with SIGBUS.
#pragma once

#include <filesystem>
#include <string>

namespace crowdsim {

/// "" when `file` is a whole 64-bit ELF shared object of this machine's kind as far as its
/// headers tell (program and section headers and every loaded segment within the file); else
/// what is wrong, as a predicate: "is cut short: ...", "is not an ELF file ...".
std::string ElfFileProblem(const std::filesystem::path& file);

}  // namespace crowdsim
