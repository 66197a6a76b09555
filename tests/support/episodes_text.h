// episodes.csv compared across runs: every column but decision_time_us, the one wall-time
// measurement that no rerun reproduces.
#pragma once

#include <string>

namespace crowdsim::testing {

/// The text of an episodes.csv without its decision_time_us column (the 12th).
std::string WithoutWallTime(const std::string& csv);

}  // namespace crowdsim::testing
