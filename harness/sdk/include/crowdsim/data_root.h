// Where a plugin finds the project's data files (frozen worlds, floor plans, trained models).
#pragma once

#include <filesystem>

#include "crowdsim/export.h"

namespace crowdsim {

/// Root of the project's data (worlds/, results/): $CROWDSIM_DATA_DIR, else PREFIX/share/
/// crowdsim-bench for an installed copy, else the source tree this harness was built from.
CROWDSIM_SDK_API std::filesystem::path DataRoot();

}  // namespace crowdsim
