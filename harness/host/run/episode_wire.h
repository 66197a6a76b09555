// An episodes.csv line as exact per-column bytes for the worker pipe, so tables match whether
// episodes ran in threads or workers.
#pragma once

#include <string>
#include <string_view>

#include "crowdsim/bench/results.h"

namespace crowdsim {

std::string EncodeEpisodeLine(const EpisodeLine& line);
/// Throws std::runtime_error when `bytes` is not what EncodeEpisodeLine wrote.
EpisodeLine DecodeEpisodeLine(std::string_view bytes);

}  // namespace crowdsim
