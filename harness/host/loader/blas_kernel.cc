#include "loader/blas_kernel.h"

#include <cstdlib>

namespace crowdsim {

namespace {
constexpr const char* kCoreTypeVariable = "OPENBLAS_CORETYPE";
}  // namespace

void PinBlasKernel() {
#if defined(__x86_64__)
  // Once per process (thread-safe static), so setenv never runs beside another thread's getenv.
  [[maybe_unused]] static const bool pinned = [] {
    if (std::getenv(kCoreTypeVariable) != nullptr) return false;
    __builtin_cpu_init();
    if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma")) return false;
    return setenv(kCoreTypeVariable, "Haswell", /*overwrite=*/0) == 0;
  }();
#endif
}

std::string BlasCoreType() {
  const char* value = std::getenv(kCoreTypeVariable);
  return value != nullptr ? value : "";
}

}  // namespace crowdsim
