// One BLAS kernel for every x86-64 machine, so that learned policies' tables are identical
// across processors.
#pragma once

#include <string>

namespace crowdsim {

/// OpenBLAS picks its kernels by processor when it is loaded (Haswell's AVX2 kernels on Intel
/// Haswell to Comet Lake and AMD Zen 1-3, SkylakeX's AVX-512 kernels on Intel Skylake-SP and
/// later and on AMD Zen 4), and the kernels round sums differently: the value networks'
/// outputs differ in the last bits, which now and then flips a decision between two nearly
/// equal actions (on Zen 4, 5 of the 17,000 committed episodes of table1 and table1_3obs).
/// Before the first plugin (and with it libtorch and OpenBLAS) is loaded, this sets
/// OPENBLAS_CORETYPE=Haswell on any x86-64 processor with AVX2 and FMA, unless
/// OPENBLAS_CORETYPE is already set (the user's or the environment's choice wins). Without
/// effect where OpenBLAS was loaded before (a Python session that imported torch first) and on
/// other architectures.
void PinBlasKernel();

/// OPENBLAS_CORETYPE as the run sees it ("" where unset), for manifest.json.
std::string BlasCoreType();

}  // namespace crowdsim
