// Where a plugin finds the project's data files (frozen worlds, floor plans, trained models).
#pragma once

#include <filesystem>

namespace crowdsim {

/// Root of the project's data (worlds/, results/): $CROWDSIM_DATA_DIR, else PREFIX/share/
/// crowdsim-bench for an installed copy, else the source tree this harness was built from.
std::filesystem::path DataRoot();

}  // namespace crowdsim
