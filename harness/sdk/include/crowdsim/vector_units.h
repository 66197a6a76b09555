// Which vector units the hot loops may use. A kernel with an AVX2 path computes every lane
// with the scalar path's IEEE operations in the same order (no fused multiply-add), so both
// paths give the same bits and a table made on a processor without AVX2 equals one made with it.
#pragma once

#include "crowdsim/export.h"

namespace crowdsim {

/// True when this processor and its operating system run AVX2 code.
CROWDSIM_SDK_API bool HaveAvx2();

/// True when the environment variable CROWDSIM_SIMD is "off": every dispatching kernel then
/// takes its scalar path on any processor (each reads it at its first call), to show on whole
/// suites that the vector paths change nothing.
CROWDSIM_SDK_API bool SimdDisabled();

/// HaveAvx2() && !SimdDisabled(): what a kernel's dispatcher asks once.
CROWDSIM_SDK_API bool UseAvx2();

}  // namespace crowdsim
