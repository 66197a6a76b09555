// Which vector units hot loops may use. AVX2 paths repeat the scalar IEEE operations (no FMA): same
// bits on any processor.
#pragma once

#include "crowdsim/export.h"

namespace crowdsim {

/// True when this processor and its operating system run AVX2 code.
CROWDSIM_SDK_API bool HaveAvx2();

/// True when CROWDSIM_SIMD is "off" (read at first call): every kernel runs scalar, showing the
/// vector paths change nothing.
CROWDSIM_SDK_API bool SimdDisabled();

/// HaveAvx2() && !SimdDisabled(): what a kernel's dispatcher asks once.
CROWDSIM_SDK_API bool UseAvx2();

}  // namespace crowdsim
