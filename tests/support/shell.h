// Running a command line from a test (the CLI, sha256sum, ffprobe), with its output.
#pragma once

#include <string>
#include <utility>

namespace crowdsim::testing {

/// Runs `cmd` through the shell, stderr joined to stdout; returns its exit status and output.
std::pair<int, std::string> Shell(const std::string& cmd);

}  // namespace crowdsim::testing
