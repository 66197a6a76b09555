// An episodes.csv line as bytes, column by column (kEpisodeColumns), for the pipe from an
// isolated worker process to the run (worker_process.h): every value exact (the CSV rounds),
// so a run's tables come out the same whether its episodes ran in threads or in worker
// processes.
#pragma once

#include <string>
#include <string_view>

#include "crowdsim/bench/results.h"

namespace crowdsim {

std::string EncodeEpisodeLine(const EpisodeLine& line);
/// Throws std::runtime_error when `bytes` is not what EncodeEpisodeLine wrote.
EpisodeLine DecodeEpisodeLine(std::string_view bytes);

}  // namespace crowdsim
