// Where a plugin finds the project's data files (frozen worlds, floor plans, trained models).
#pragma once

#include <filesystem>

#include "crowdsim/export.h"

namespace crowdsim {

/// Root of the project's data (worlds/, results/): $CROWDSIM_DATA_DIR, else PREFIX/share/
/// crowdsim-bench when installed, else the source tree of this build.
CROWDSIM_SDK_API std::filesystem::path DataRoot();

}  // namespace crowdsim
