#include "blas_kernel.h"

#include <cstdlib>

namespace crowdsim {

namespace {
constexpr const char* kCoreTypeVariable = "OPENBLAS_CORETYPE";
}  // namespace

void PinBlasKernel() {
#if defined(__x86_64__)
  if (std::getenv(kCoreTypeVariable) != nullptr) return;
  __builtin_cpu_init();
  if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma")) {
    setenv(kCoreTypeVariable, "Haswell", /*overwrite=*/0);
  }
#endif
}

std::string BlasCoreType() {
  const char* value = std::getenv(kCoreTypeVariable);
  return value != nullptr ? value : "";
}

}  // namespace crowdsim
