// One BLAS kernel for every x86-64 machine, so that learned policies' tables are identical
// across processors.
#pragma once

#include <string>

namespace crowdsim {

/// OpenBLAS kernels round sums differently per processor, which can flip near-tied decisions.
/// Before the first plugin loads, sets OPENBLAS_CORETYPE=Haswell on x86-64 with AVX2 and FMA unless
/// set; no effect once OpenBLAS is loaded or elsewhere.
void PinBlasKernel();

/// OPENBLAS_CORETYPE as the run sees it ("" where unset), for manifest.json.
std::string BlasCoreType();

}  // namespace crowdsim
